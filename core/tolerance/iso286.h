// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// ISO 286-1/-2 limits and fits: standard tolerance grades IT01 to IT18, fundamental deviations of shafts
// a to zc and holes A to ZC for nominal sizes above 0 up to 3150 mm, the limits of a tolerance class
// ("50 H7", "Ø50g6") and of a fit ("50 H7/g6"). All deviations are in micrometres. What is implemented,
// the special rules and the sources: docs/iso286.md.

#include "core/common/diagnostic.h"

#include <QString>

#include <optional>

namespace tolturn::iso286 {

enum class Kind { Hole, Shaft };

enum class FitType { Clearance, Transition, Interference };

// How the limits ±IT/2 of js and JS are formed when the IT value in µm is odd.
enum class JsRounding {
    // ±IT/2 exactly, so an odd IT gives half micrometres (js7 at 40 mm: ±12.5 µm), as current tables
    // print it (DME's ISO/DIN tables, JIS B 0401).
    Exact,
    // ISO 286-1:1988, note to Tables 2 and 3: "for js7 to js11 (JS7 to JS11) the two symmetrical
    // deviations ±IT/2 may be rounded, if the IT value in micrometres is an odd value, by replacing it by
    // the even value immediately below" (js7 at 40 mm: ±12 µm). Grades 7 to 11 only.
    EvenBelowForGrades7To11,
};

struct Options {
    JsRounding jsRounding = JsRounding::Exact;
};

// Largest nominal size of ISO 286 (the last range is above 2500 up to and including 3150 mm).
inline constexpr double kMaxNominal_mm = 3150.0;

// A tolerance class as written, parsed: "H7" is {Hole, "H", 7}, "js6" is {Shaft, "js", 6}, "h01" is
// {Shaft, "h", -1}.
struct ToleranceClass {
    Kind kind = Kind::Hole;
    QString letter;  // "H", "js", "ZC", as in the standard (hole letters upper case, shaft letters lower)
    int itGrade = 0; // -1 for IT01, 0 for IT0, 1 ... 18
    QString name;    // letter and grade, normalised: "JS7" for "Js7"
};

struct ClassResult {
    std::optional<ToleranceClass> toleranceClass;
    Diagnostics diagnostics;
};

// Parses "H7", "g6", "js6", "ZC10", "h01". Errors name the field given.
[[nodiscard]] ClassResult parseToleranceClass(const QString &text,
                                              const QString &field = QStringLiteral("toleranceClass"));

// "IT01", "IT0", "IT1" ... "IT18".
[[nodiscard]] QString itGradeName(int itGrade);

struct ToleranceResult {
    std::optional<double> it_um;
    Diagnostics diagnostics;
};

// The standard tolerance of an IT grade (-1 = IT01, 0 = IT0, 1 ... 18) for a nominal size (ISO 286-1
// Table 1).
[[nodiscard]] ToleranceResult standardTolerance(double nominal_mm, int itGrade);

// The limits of one tolerance class at one nominal size.
struct ClassLimits {
    double nominal_mm = 0.0;
    QString toleranceClass; // normalised name, "H7"
    Kind kind = Kind::Hole;
    int itGrade = 0;       // -1 for IT01, 0 for IT0
    QString itName;        // "IT7"
    double it_um = 0.0;    // standard tolerance (for js/JS with EvenBelowForGrades7To11, upper - lower may be 1 less)
    double upper_um = 0.0; // es or ES
    double lower_um = 0.0; // ei or EI
    double fundamental_um = 0.0;
    bool fundamentalIsUpper = false; // es for a to h, EI for A to H; +IT/2 (upper) for js and JS
};

struct LimitsResult {
    std::optional<ClassLimits> limits;
    Diagnostics diagnostics; // errors (then no limits) and warnings (limits given)
};

[[nodiscard]] LimitsResult limits(double nominal_mm, const QString &toleranceClass, const Options &options = {});

struct Fit {
    ClassLimits hole;
    ClassLimits shaft;
    FitType type = FitType::Clearance;
    double maxClearance_um = 0.0; // ES - ei; negative = interference
    double minClearance_um = 0.0; // EI - es; negative = interference
};

struct FitResult {
    std::optional<Fit> fit;
    Diagnostics diagnostics;
};

// The fit of a hole class and a shaft class at one nominal size (definitions of ISO 286-1: clearance fit when
// the smallest hole is not smaller than the largest shaft, interference fit when the largest hole is not
// larger than the smallest shaft, transition fit otherwise).
[[nodiscard]] FitResult fit(double nominal_mm, const QString &holeClass, const QString &shaftClass,
                            const Options &options = {});

[[nodiscard]] QString fitTypeName(FitType type);
// The same as a keyword for files and JSON ("clearance", "transition", "interference"): never translated.
[[nodiscard]] QString fitTypeKeyword(FitType type);

// A designation as people write it: "50 H7", "Ø50g6", "50h7", "50 js6", "50 H7/g6", "Ø50 H7/g6", or a
// class or fit alone ("H7", "H7/g6") whose nominal size is given separately.
struct Designation {
    std::optional<double> nominal_mm;
    QString holeClass;  // empty when the designation has no hole class
    QString shaftClass; // empty when the designation has no shaft class

    [[nodiscard]] bool isFit() const { return !holeClass.isEmpty() && !shaftClass.isEmpty(); }
};

struct DesignationResult {
    std::optional<Designation> designation;
    Diagnostics diagnostics;
};

[[nodiscard]] DesignationResult parseDesignation(const QString &text);

// A designation evaluated: the limits of a single class, or the fit of hole and shaft.
struct DesignationLimits {
    std::optional<ClassLimits> limits; // a single class
    std::optional<Fit> fit;            // a fit
    Diagnostics diagnostics;
};

// Parses and evaluates a designation. nominal_mm is used when the text has no nominal size ("H7"); when
// both give one they must agree.
[[nodiscard]] DesignationLimits evaluate(const QString &designation, std::optional<double> nominal_mm = std::nullopt,
                                         const Options &options = {});

} // namespace tolturn::iso286
