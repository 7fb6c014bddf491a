// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/cad/model_references.h"

#include <IGESDraw_LabelDisplay.hxx>
#include <Interface_EntityIterator.hxx>
#include <Interface_InterfaceModel.hxx>
#include <TCollection_HAsciiString.hxx>
#include <algorithm>
#include <limits>
#include <vector>

namespace tolturn::cad {

namespace {

QString labelOf(const Interface_Graph &graph, int number)
{
    const Handle(Interface_InterfaceModel) &model = graph.Model();
    const Handle(TCollection_HAsciiString) label = model->StringLabel(graph.Entity(number));
    return label.IsNull() ? QStringLiteral("entity %1").arg(number) : QString::fromLatin1(label->ToCString());
}

std::vector<int> referencedBy(const Interface_Graph &graph, int number)
{
    std::vector<int> out;
    Interface_EntityIterator shared = graph.Shareds(graph.Entity(number));
    for (shared.Start(); shared.More(); shared.Next()) {
        // An IGES entity's label display (402 form 5) points back at the entity it labels, a cycle
        // by design that the translators never follow (they read no annotation): not a reference.
        if (shared.Value()->IsKind(STANDARD_TYPE(IGESDraw_LabelDisplay)))
            continue;
        const int n = graph.EntityNumber(shared.Value());
        if (n > 0) // 0: not an entity of the model
            out.push_back(n);
    }
    return out;
}

enum class Visit : unsigned char { Unseen, OnPath, Done };

struct Frame {
    int entity;
    std::vector<int> referenced;
    std::size_t next = 0;
};

// Depth-first over the references with an explicit stack; `height[n]` is the longest chain from
// entity n (1 for an entity that refers to none). Stops at the first cycle or chain over maxDepth.
std::optional<ReferenceProblem> walk(const Interface_Graph &graph, int maxDepth, std::vector<int> &height)
{
    const int count = graph.Size();
    std::vector<Visit> visit(static_cast<std::size_t>(count) + 1, Visit::Unseen);
    height.assign(static_cast<std::size_t>(count) + 1, 0);
    std::vector<Frame> path;
    for (int root = 1; root <= count; ++root) {
        if (visit[static_cast<std::size_t>(root)] != Visit::Unseen)
            continue;
        visit[static_cast<std::size_t>(root)] = Visit::OnPath;
        path.push_back({root, referencedBy(graph, root)});
        while (!path.empty()) {
            Frame &top = path.back();
            const auto topIndex = static_cast<std::size_t>(top.entity);
            if (top.next < top.referenced.size()) {
                const int next = top.referenced[top.next++];
                const auto nextIndex = static_cast<std::size_t>(next);
                if (visit[nextIndex] == Visit::OnPath)
                    return ReferenceProblem{ReferenceProblem::Kind::Cycle, labelOf(graph, top.entity),
                                            labelOf(graph, next), 0};
                if (visit[nextIndex] == Visit::Done) {
                    // A chain already walked from elsewhere: its length counts from here too.
                    if (static_cast<long long>(path.size()) + height[nextIndex] > maxDepth)
                        return ReferenceProblem{ReferenceProblem::Kind::TooDeep,
                                                labelOf(graph, next),
                                                {},
                                                static_cast<int>(path.size()) + height[nextIndex]};
                    height[topIndex] = std::max(height[topIndex], height[nextIndex]);
                    continue;
                }
                if (static_cast<int>(path.size()) >= maxDepth)
                    return ReferenceProblem{
                        ReferenceProblem::Kind::TooDeep, labelOf(graph, next), {}, static_cast<int>(path.size()) + 1};
                visit[nextIndex] = Visit::OnPath;
                path.push_back({next, referencedBy(graph, next)});
                continue;
            }
            ++height[topIndex]; // the entity itself, above the longest chain below it
            visit[topIndex] = Visit::Done;
            const int done = top.entity;
            path.pop_back();
            if (!path.empty()) {
                const auto parent = static_cast<std::size_t>(path.back().entity);
                height[parent] = std::max(height[parent], height[static_cast<std::size_t>(done)]);
            }
        }
    }
    return std::nullopt;
}

} // namespace

std::optional<ReferenceProblem> firstReferenceProblem(const Interface_Graph &graph, int maxDepth)
{
    std::vector<int> height;
    return walk(graph, maxDepth, height);
}

int referenceDepth(const Interface_Graph &graph)
{
    std::vector<int> height;
    if (walk(graph, std::numeric_limits<int>::max(), height))
        return -1;
    return height.empty() ? 0 : *std::max_element(height.begin(), height.end());
}

} // namespace tolturn::cad
