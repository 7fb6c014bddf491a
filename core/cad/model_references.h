// SPDX-License-Identifier: GPL-3.0-or-later
// Private to core/cad: a check of the entity references of a read STEP or IGES model before its
// translators walk it. They follow references by recursion, so a reference cycle (an
// ORIENTED_EDGE whose edge is itself, say) or a chain of references deeper than any CAD system
// writes would exhaust the stack and end the process, which no signal guard survives.
#pragma once

#include <QString>

#include <Interface_Graph.hxx>
#include <optional>

namespace tolturn::cad {

// The longest chain of references accepted. STEP AP203/AP214 solids nest about 15 entities deep
// (product → shape representation → brep → shell → face → loop → oriented edge → edge → curve →
// placement → point), assemblies a few levels more each; IGES less. See model_references.cpp.
inline constexpr int kMaxReferenceDepth = 400;

struct ReferenceProblem {
    enum class Kind { Cycle, TooDeep };
    Kind kind = Kind::Cycle;
    QString entity;  // the entity that closes the cycle (refers to one it is reached from), or the deepest one
    QString through; // for a cycle: the entity it refers back to
    int depth = 0;   // for TooDeep: the length of the chain found (more than kMaxReferenceDepth)
};

// The first cycle of references, or the first chain longer than `maxDepth`, in the model of
// `graph`; empty when the references form a graph without cycles of bounded depth. Iterative:
// it needs no stack of its own however the file is made.
[[nodiscard]] std::optional<ReferenceProblem> firstReferenceProblem(const Interface_Graph &graph,
                                                                    int maxDepth = kMaxReferenceDepth);

// The longest chain of references in the model (1: an entity that refers to none); for the tests
// and the documentation of kMaxReferenceDepth.
[[nodiscard]] int referenceDepth(const Interface_Graph &graph);

} // namespace tolturn::cad
