// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/tolerance/iso286.h"

#include "core/tolerance/iso286_tables.h"

#include <QCoreApplication>
#include <QRegularExpression>
#include <QStringList>

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

namespace tolturn::iso286 {

namespace {

using tables::Letter;

struct Iso286 {
    Q_DECLARE_TR_FUNCTIONS(Iso286)
};

QString num(double v)
{
    return formatNumber(v);
}

// Shaft letters in the order of tables::Letter; hole letters are the same in upper case.
constexpr std::array<const char *, tables::kLetterCount> kLetterNames = {
    "a", "b", "c", "cd", "d", "e", "ef", "f", "fg", "g", "h", "js", "j",  "k",
    "m", "n", "p", "r",  "s", "t", "u",  "v", "x",  "y", "z", "za", "zb", "zc"};

std::optional<Letter> letterFromName(const QString &lowerCaseName)
{
    for (std::size_t i = 0; i < kLetterNames.size(); ++i) {
        if (lowerCaseName == QLatin1String(kLetterNames.at(i)))
            return static_cast<Letter>(i);
    }
    return std::nullopt;
}

QString letterList(Kind kind)
{
    QStringList names;
    for (const char *name : kLetterNames)
        names << (kind == Kind::Hole ? QString::fromLatin1(name).toUpper() : QString::fromLatin1(name));
    return names.join(QStringLiteral(", "));
}

QString kindWord(Kind kind)
{
    return kind == Kind::Hole ? Iso286::tr("hole") : Iso286::tr("shaft");
}

QString gradeSuffix(int itGrade)
{
    if (itGrade == -1)
        return QStringLiteral("01");
    return QString::number(itGrade);
}

// ---- checks shared by the entry points ----

bool checkNominal(double nominal_mm, const QString &field, Diagnostics &out)
{
    if (!std::isfinite(nominal_mm)) {
        out.push_back(makeError(field, Iso286::tr("the nominal size is not a finite number")));
        return false;
    }
    if (nominal_mm == 0.0) {
        out.push_back(
            makeError(field, Iso286::tr("0 mm is not a nominal size: the first range of ISO 286 is above 0 up to and "
                                        "including 3 mm")));
        return false;
    }
    if (nominal_mm < 0.0) {
        out.push_back(
            makeError(field, Iso286::tr("the nominal size must be above 0 mm, but is %1 mm").arg(num(nominal_mm))));
        return false;
    }
    if (nominal_mm > kMaxNominal_mm) {
        out.push_back(makeError(
            field, Iso286::tr("%1 mm is above 3150 mm, the largest nominal size of ISO 286").arg(num(nominal_mm))));
        return false;
    }
    return true;
}

// The standard tolerance with the notes of ISO 286-1 Table 1. Errors go to gradeField.
std::optional<double> toleranceFor(double nominal_mm, int itGrade, const QString &gradeField, Diagnostics &out)
{
    const auto range = tables::toleranceRange(nominal_mm);
    if (!range)
        return std::nullopt;
    const auto it = tables::standardTolerance_um(*range, itGrade);
    if (!it) {
        out.push_back(
            makeError(gradeField, Iso286::tr("%1 is given by ISO 286-1 only for nominal sizes up to and including "
                                             "500 mm, not for %2 mm")
                                      .arg(itGradeName(itGrade), num(nominal_mm))));
        return std::nullopt;
    }
    // ISO 286-1:2010 Table 1, note: IT14 to IT18 shall not be used for nominal sizes up to and including 1 mm.
    if (itGrade >= 14 && nominal_mm <= 1.0) {
        out.push_back(
            makeError(gradeField, Iso286::tr("%1 shall not be used for nominal sizes up to and including 1 mm "
                                             "(ISO 286-1 Table 1), but the size is %2 mm")
                                      .arg(itGradeName(itGrade), num(nominal_mm))));
        return std::nullopt;
    }
    // ISO 286-1:2010 Table 1, note: IT1 to IT5 above 500 mm are included for experimental use.
    if (itGrade >= 1 && itGrade <= 5 && nominal_mm > 500.0)
        out.push_back(
            makeWarning(gradeField, Iso286::tr("%1 above 500 mm is given by ISO 286-1 for experimental use only "
                                               "(size %2 mm)")
                                        .arg(itGradeName(itGrade), num(nominal_mm))));
    return it;
}

// ---- fundamental deviations ----

struct Deviation {
    double value_um = 0.0;
    bool isUpper = false;
};

class DeviationFinder {
public:
    DeviationFinder(const ToleranceClass &cls, double nominal_mm, QString field, Diagnostics &out)
        : m_cls(cls)
        , m_nominal_mm(nominal_mm)
        , m_field(std::move(field))
        , m_out(out)
    {
    }

    // The fundamental deviation, or no value (and an error) where the standard defines none. js and JS
    // are handled by the caller.
    std::optional<Deviation> find(Letter letter)
    {
        const auto devRange = tables::deviationRange(m_nominal_mm);
        const auto tolRange = tables::toleranceRange(m_nominal_mm);
        if (!devRange || !tolRange)
            return std::nullopt;
        m_devRange = *devRange;
        m_tolRange = *tolRange;
        return m_cls.kind == Kind::Shaft ? shaft(letter) : hole(letter);
    }

private:
    std::optional<Deviation> shaft(Letter letter)
    {
        const int grade = m_cls.itGrade;
        if (letter == Letter::J) {
            const int ei = tables::shaftJ_um(grade, m_devRange);
            if (ei == tables::kNotDefined)
                return notDefinedJ(QStringLiteral("j"), 5, 8);
            return Deviation{static_cast<double>(ei), false};
        }
        if (letter == Letter::K) {
            // ISO 286-1:2010 Table 3, column k: "IT4 to IT7" gives the tabulated value, "up to IT3 and above
            // IT7" gives 0; above 500 mm k is 0 for all grades.
            const bool tabulated = grade >= 4 && grade <= 7;
            const int ei = tabulated ? tables::shaftDeviation_um(Letter::K, m_devRange) : 0;
            return Deviation{static_cast<double>(ei), false};
        }
        if (!checkAB(letter))
            return std::nullopt;
        const int value = tables::shaftDeviation_um(letter, m_devRange);
        if (value == tables::kNotDefined)
            return notDefinedForSize(letter);
        // a to h: upper deviation es; m to zc: lower deviation ei.
        const bool upper = static_cast<int>(letter) <= static_cast<int>(Letter::H);
        return Deviation{static_cast<double>(value), upper};
    }

    std::optional<Deviation> hole(Letter letter)
    {
        const int grade = m_cls.itGrade;
        const bool above500 = m_nominal_mm > 500.0;
        if (letter == Letter::J) {
            const int es = tables::holeJ_um(grade, m_devRange);
            if (es == tables::kNotDefined)
                return notDefinedJ(QStringLiteral("J"), 6, 8);
            return Deviation{static_cast<double>(es), true};
        }
        if (!checkAB(letter))
            return std::nullopt;
        // A to H: EI = -es of the shaft of the same letter (ISO 286-1:2010 Table 4).
        if (static_cast<int>(letter) <= static_cast<int>(Letter::H)) {
            const int es = tables::shaftDeviation_um(letter, m_devRange);
            if (es == tables::kNotDefined)
                return notDefinedForSize(letter);
            return Deviation{0.0 - static_cast<double>(es), false};
        }
        // K to ZC: ES from -ei of the shaft of the same letter (k: its "IT4 to IT7" column), plus Δ for
        // K, M, N up to IT8 and P to ZC up to IT7, sizes up to 500 mm (ISO 286-1:2010 Tables 4 and 5).
        const int ei = tables::shaftDeviation_um(letter, m_devRange);
        if (ei == tables::kNotDefined)
            return notDefinedForSize(letter);
        const double minusEi = 0.0 - static_cast<double>(ei);
        if (above500) // no Δ and no grade distinction above 500 mm (ISO 286-1 Tables 4 and 5, 500 to 3150 mm)
            return Deviation{minusEi, true};
        const bool kmn = letter == Letter::K || letter == Letter::M || letter == Letter::N;
        const int deltaUpTo = kmn ? 8 : 7;
        if (grade > deltaUpTo)
            return aboveDeltaGrades(letter, minusEi);
        // Up to 3 mm the table cells carry no Δ (K 0, M -2, N -4; Δ = 0 for P to ZC), so every grade is
        // defined there; above 3 mm Δ is tabulated for IT3 to IT8 only.
        const auto delta = m_tolRange == 0 ? std::optional<double>(0.0) : tables::delta_um(m_tolRange, grade);
        if (!delta) {
            m_out.push_back(
                makeError(m_field, Iso286::tr("hole %1 is not defined: ISO 286-1 forms %2 up to IT%3 as ES = -ei + "
                                              "Δ, and tabulates Δ only for IT3 to IT8")
                                       .arg(m_cls.name, letterName(letter))
                                       .arg(deltaUpTo)));
            return std::nullopt;
        }
        // Special case (ISO 286-1:2010 Table 4, note): M6 from above 250 up to 315 mm has ES = -9 µm (instead
        // of -11 µm).
        constexpr std::size_t kRange250To315 = 10; // index in tables::kToleranceRangeUpper_mm
        if (letter == Letter::M && grade == 6 && m_tolRange == kRange250To315)
            return Deviation{-9.0, true};
        return Deviation{minusEi + *delta, true};
    }

    // K, M, N above IT8 and P to ZC above IT7, up to 500 mm.
    std::optional<Deviation> aboveDeltaGrades(Letter letter, double minusEi)
    {
        if (letter == Letter::K) {
            // K above IT8 is tabulated (0) only up to 3 mm; the cells above 3 mm are empty.
            if (m_devRange != 0) {
                m_out.push_back(
                    makeError(m_field, Iso286::tr("hole %1 is not defined for a nominal size of %2 mm: ISO 286-1 "
                                                  "gives K above IT8 only for nominal sizes up to and including "
                                                  "3 mm")
                                           .arg(m_cls.name, num(m_nominal_mm))));
                return std::nullopt;
            }
            return Deviation{0.0, true};
        }
        if (letter == Letter::N) {
            // Note to ISO 286-1:2010 Table 5: N above IT8 shall not be used for nominal sizes up to 1 mm.
            if (m_nominal_mm <= 1.0) {
                m_out.push_back(
                    makeError(m_field, Iso286::tr("hole %1 is not defined for a nominal size of %2 mm: ISO 286-1 "
                                                  "says N above IT8 shall not be used for nominal sizes up to "
                                                  "and including 1 mm")
                                           .arg(m_cls.name, num(m_nominal_mm))));
                return std::nullopt;
            }
            // N above IT8: -4 µm up to 3 mm, 0 above.
            return Deviation{m_devRange == 0 ? minusEi : 0.0, true};
        }
        return Deviation{minusEi, true};
    }

    // Notes to ISO 286-1 Tables 2 and 4: a, b, A and B shall not be used for sizes up to 1 mm.
    bool checkAB(Letter letter)
    {
        if ((letter == Letter::A || letter == Letter::B) && m_nominal_mm <= 1.0) {
            m_out.push_back(makeError(
                m_field, Iso286::tr("%1 %2 is not defined for a nominal size of %3 mm: ISO 286-1 says "
                                    "the fundamental deviations %4 shall not be used for nominal sizes "
                                    "up to and including 1 mm")
                             .arg(kindWord(m_cls.kind), m_cls.name, num(m_nominal_mm),
                                  m_cls.kind == Kind::Hole ? QStringLiteral("A and B") : QStringLiteral("a and b"))));
            return false;
        }
        return true;
    }

    std::optional<Deviation> notDefinedForSize(Letter letter)
    {
        // The defined cells of every letter are one run of ranges; name it.
        std::optional<std::size_t> first;
        std::size_t last = 0;
        for (std::size_t r = 0; r < tables::kDeviationRangeCount; ++r) {
            if (tables::shaftDeviation_um(letter, r) != tables::kNotDefined) {
                if (!first)
                    first = r;
                last = r;
            }
        }
        const double from = first ? tables::deviationRangeLower_mm(*first) : 0.0;
        const double to = tables::kDeviationRangeUpper_mm.at(last);
        m_out.push_back(
            makeError(m_field, Iso286::tr("%1 %2 is not defined for a nominal size of %3 mm: ISO 286-1 gives the "
                                          "fundamental deviation %4 only above %5 mm up to and including %6 mm")
                                   .arg(kindWord(m_cls.kind), m_cls.name, num(m_nominal_mm), letterName(letter),
                                        num(from), num(to))));
        return std::nullopt;
    }

    std::optional<Deviation> notDefinedJ(const QString &letter, int firstGrade, int lastGrade)
    {
        const int grade = m_cls.itGrade;
        QString message;
        if (grade < firstGrade || grade > lastGrade)
            message = Iso286::tr("%1 %2 is not defined: ISO 286-1 tabulates %3 only for the grades IT%4 to IT%5 (the "
                                 "symmetric %6 covers every grade)")
                          .arg(kindWord(m_cls.kind), m_cls.name, letter)
                          .arg(firstGrade)
                          .arg(lastGrade)
                          .arg(letter == QLatin1String("j") ? QStringLiteral("js") : QStringLiteral("JS"));
        else if (m_nominal_mm > 500.0)
            message = Iso286::tr("%1 %2 is not defined for a nominal size of %3 mm: ISO 286-1 gives %4 only up to and "
                                 "including 500 mm")
                          .arg(kindWord(m_cls.kind), m_cls.name, num(m_nominal_mm), letter);
        else
            message = Iso286::tr("%1 %2 is not defined for a nominal size of %3 mm: ISO 286-1 gives j8 only up to and "
                                 "including 3 mm")
                          .arg(kindWord(m_cls.kind), m_cls.name, num(m_nominal_mm));
        m_out.push_back(makeError(m_field, message));
        return std::nullopt;
    }

    QString letterName(Letter letter) const
    {
        const QString name = QString::fromLatin1(kLetterNames.at(static_cast<std::size_t>(letter)));
        return m_cls.kind == Kind::Hole ? name.toUpper() : name;
    }

    const ToleranceClass &m_cls;
    double m_nominal_mm;
    QString m_field;
    Diagnostics &m_out;
    std::size_t m_devRange = 0;
    std::size_t m_tolRange = 0;
};

// The limits of a parsed class at a size already checked to lie in (0, 3150] mm.
std::optional<ClassLimits> classLimits(double nominal_mm, const ToleranceClass &cls, const QString &field,
                                       const Options &options, Diagnostics &out)
{
    const auto it = toleranceFor(nominal_mm, cls.itGrade, field, out);
    if (!it)
        return std::nullopt;
    const auto letter = letterFromName(cls.letter.toLower());
    if (!letter)
        return std::nullopt;

    ClassLimits l;
    l.nominal_mm = nominal_mm;
    l.toleranceClass = cls.name;
    l.kind = cls.kind;
    l.itGrade = cls.itGrade;
    l.itName = itGradeName(cls.itGrade);
    l.it_um = *it;

    if (*letter == Letter::JS) {
        // js, JS: limit deviations ±IT/2 (ISO 286-1:2010 Tables 2 and 4). Optional rounding of odd IT values
        // for grades 7 to 11: ISO 286-1:1988 note to Tables 2 and 3 (see JsRounding).
        double half = *it / 2.0;
        const bool oddMicrometres = std::fmod(*it, 2.0) == 1.0;
        if (options.jsRounding == JsRounding::EvenBelowForGrades7To11 && cls.itGrade >= 7 && cls.itGrade <= 11 &&
            oddMicrometres)
            half = (*it - 1.0) / 2.0;
        l.upper_um = half;
        l.lower_um = -half;
        l.fundamental_um = half;
        l.fundamentalIsUpper = true;
        return l;
    }

    DeviationFinder finder(cls, nominal_mm, field, out);
    const auto fd = finder.find(*letter);
    if (!fd)
        return std::nullopt;
    l.fundamental_um = fd->value_um;
    l.fundamentalIsUpper = fd->isUpper;
    if (fd->isUpper) {
        l.upper_um = fd->value_um;
        l.lower_um = fd->value_um - *it;
    } else {
        l.lower_um = fd->value_um;
        l.upper_um = fd->value_um + *it;
    }
    return l;
}

std::optional<ToleranceClass> parseInto(const QString &text, const QString &field, Diagnostics &out)
{
    ClassResult r = parseToleranceClass(text, field);
    out.insert(out.end(), r.diagnostics.begin(), r.diagnostics.end());
    return r.toleranceClass;
}

bool isDiameterSign(QChar c)
{
    // Ø (U+00D8), ø (U+00F8), ⌀ (U+2300, diameter sign), ∅ (U+2205, empty set, often typed for it)
    return c == QChar(0x00D8) || c == QChar(0x00F8) || c == QChar(0x2300) || c == QChar(0x2205);
}

} // namespace

QString itGradeName(int itGrade)
{
    return QStringLiteral("IT") + gradeSuffix(itGrade);
}

ClassResult parseToleranceClass(const QString &text, const QString &field)
{
    ClassResult r;
    const QString t = text.trimmed();
    static const QRegularExpression pattern(QStringLiteral("^([A-Za-z]+)([0-9]+)$"));
    const auto match = pattern.match(t);
    if (!match.hasMatch()) {
        if (t.isEmpty())
            r.diagnostics.push_back(
                makeError(field, Iso286::tr("the tolerance class is empty; write a fundamental deviation "
                                            "letter and a tolerance grade, such as H7 or g6")));
        else
            r.diagnostics.push_back(
                makeError(field, Iso286::tr("\"%1\" is not a tolerance class: write a fundamental "
                                            "deviation letter and a tolerance grade, such as H7, g6 or "
                                            "js6")
                                     .arg(t)));
        return r;
    }
    const QString letters = match.captured(1);
    const QString digits = match.captured(2);

    Kind kind = Kind::Hole;
    if (letters == letters.toUpper() || letters == QLatin1String("Js")) // "Js" is the older way to write JS
        kind = Kind::Hole;
    else if (letters == letters.toLower())
        kind = Kind::Shaft;
    else {
        r.diagnostics.push_back(
            makeError(field, Iso286::tr("\"%1\" mixes upper and lower case in \"%2\": hole letters are "
                                        "upper case (H7), shaft letters lower case (g6)")
                                 .arg(t, letters)));
        return r;
    }

    const auto letter = letterFromName(letters.toLower());
    if (!letter)
        r.diagnostics.push_back(
            makeError(field, Iso286::tr("\"%1\": \"%2\" is not a fundamental deviation of ISO 286-1; the "
                                        "%3 letters are %4")
                                 .arg(t, letters, kindWord(kind), letterList(kind))));

    std::optional<int> grade;
    if (digits == QLatin1String("01"))
        grade = -1;
    else if (digits == QLatin1String("0"))
        grade = 0;
    else if (!digits.startsWith(QLatin1Char('0')) && digits.size() <= 2 && digits.toInt() <= 18)
        grade = digits.toInt();
    if (!grade)
        r.diagnostics.push_back(
            makeError(field, Iso286::tr("\"%1\": IT%2 is not a standard tolerance grade; the grades are "
                                        "IT01, IT0 and IT1 to IT18")
                                 .arg(t, digits)));
    if (!letter || !grade)
        return r;

    ToleranceClass cls;
    cls.kind = kind;
    const QString name = QString::fromLatin1(kLetterNames.at(static_cast<std::size_t>(*letter)));
    cls.letter = kind == Kind::Hole ? name.toUpper() : name;
    cls.itGrade = *grade;
    cls.name = cls.letter + gradeSuffix(*grade);
    r.toleranceClass = cls;
    return r;
}

ToleranceResult standardTolerance(double nominal_mm, int itGrade)
{
    ToleranceResult r;
    const QString gradeField = QStringLiteral("itGrade");
    if (itGrade < -1 || itGrade > 18) {
        r.diagnostics.push_back(
            makeError(gradeField, Iso286::tr("IT%1 is not a standard tolerance grade; the grades are "
                                             "IT01, IT0 and IT1 to IT18")
                                      .arg(itGrade)));
        return r;
    }
    if (!checkNominal(nominal_mm, QStringLiteral("nominal_mm"), r.diagnostics))
        return r;
    r.it_um = toleranceFor(nominal_mm, itGrade, gradeField, r.diagnostics);
    return r;
}

LimitsResult limits(double nominal_mm, const QString &toleranceClass, const Options &options)
{
    LimitsResult r;
    const QString field = QStringLiteral("toleranceClass");
    const auto cls = parseInto(toleranceClass, field, r.diagnostics);
    const bool sizeOk = checkNominal(nominal_mm, QStringLiteral("nominal_mm"), r.diagnostics);
    if (!cls || !sizeOk)
        return r;
    r.limits = classLimits(nominal_mm, *cls, field, options, r.diagnostics);
    return r;
}

FitResult fit(double nominal_mm, const QString &holeClass, const QString &shaftClass, const Options &options)
{
    FitResult r;
    const QString holeField = QStringLiteral("holeClass");
    const QString shaftField = QStringLiteral("shaftClass");
    auto hole = parseInto(holeClass, holeField, r.diagnostics);
    auto shaft = parseInto(shaftClass, shaftField, r.diagnostics);
    if (hole && hole->kind != Kind::Hole) {
        r.diagnostics.push_back(
            makeError(holeField, Iso286::tr("%1 is a shaft class; the first class of a fit is the hole, "
                                            "written in upper case (H7)")
                                     .arg(hole->name)));
        hole.reset();
    }
    if (shaft && shaft->kind != Kind::Shaft) {
        r.diagnostics.push_back(makeError(shaftField, Iso286::tr("%1 is a hole class; the second class of a fit is the "
                                                                 "shaft, written in lower case (g6)")
                                                          .arg(shaft->name)));
        shaft.reset();
    }
    const bool sizeOk = checkNominal(nominal_mm, QStringLiteral("nominal_mm"), r.diagnostics);
    if (!hole || !shaft || !sizeOk)
        return r;
    const auto h = classLimits(nominal_mm, *hole, holeField, options, r.diagnostics);
    const auto s = classLimits(nominal_mm, *shaft, shaftField, options, r.diagnostics);
    if (!h || !s)
        return r;

    Fit f;
    f.hole = *h;
    f.shaft = *s;
    f.maxClearance_um = h->upper_um - s->lower_um;
    f.minClearance_um = h->lower_um - s->upper_um;
    if (f.minClearance_um >= 0.0)
        f.type = FitType::Clearance;
    else if (f.maxClearance_um <= 0.0)
        f.type = FitType::Interference;
    else
        f.type = FitType::Transition;
    r.fit = f;
    return r;
}

namespace {
// The three kinds of fit of ISO 286-1:2010 §3.3.4 (clearance, transition, interference fit).
const char *fitTypeText(FitType type)
{
    switch (type) {
    case FitType::Clearance:
        return QT_TRANSLATE_NOOP("Iso286", "clearance");
    case FitType::Transition:
        return QT_TRANSLATE_NOOP("Iso286", "transition");
    case FitType::Interference:
        return QT_TRANSLATE_NOOP("Iso286", "interference");
    }
    return "";
}
} // namespace

QString fitTypeName(FitType type)
{
    return Iso286::tr(fitTypeText(type));
}

QString fitTypeKeyword(FitType type)
{
    return QString::fromLatin1(fitTypeText(type));
}

DesignationResult parseDesignation(const QString &text)
{
    DesignationResult r;
    const QString field = QStringLiteral("designation");
    QString t = text.trimmed();
    if (t.isEmpty()) {
        r.diagnostics.push_back(
            makeError(field, Iso286::tr("the designation is empty; write one such as 50 H7, Ø50 g6 or "
                                        "50 H7/g6")));
        return r;
    }
    const bool diameterSign = isDiameterSign(t.front());
    if (diameterSign)
        t = t.mid(1).trimmed();

    Designation d;
    static const QRegularExpression number(QStringLiteral("^([0-9]+(?:[.,][0-9]+)?)\\s*(.*)$"));
    const auto match = number.match(t);
    QString rest = t;
    if (match.hasMatch()) {
        QString value = match.captured(1);
        value.replace(QLatin1Char(','), QLatin1Char('.'));
        d.nominal_mm = value.toDouble();
        rest = match.captured(2).trimmed();
    } else if (diameterSign) {
        r.diagnostics.push_back(
            makeError(field, Iso286::tr("\"%1\": the diameter sign must be followed by the nominal size, "
                                        "as in Ø50 H7")
                                 .arg(text.trimmed())));
        return r;
    }
    if (rest.isEmpty()) {
        r.diagnostics.push_back(
            makeError(field, Iso286::tr("\"%1\" has no tolerance class; write one after the nominal size, "
                                        "such as 50 H7 or 50 H7/g6")
                                 .arg(text.trimmed())));
        return r;
    }

    const QStringList parts = rest.split(QLatin1Char('/'));
    if (parts.size() > 2 ||
        std::any_of(parts.begin(), parts.end(), [](const QString &p) { return p.trimmed().isEmpty(); })) {
        r.diagnostics.push_back(
            makeError(field, Iso286::tr("\"%1\" is not a designation: a fit is a hole class, a slash and "
                                        "a shaft class, as in 50 H7/g6")
                                 .arg(text.trimmed())));
        return r;
    }
    std::vector<ToleranceClass> classes;
    for (const QString &part : parts) {
        const auto cls = parseInto(part, field, r.diagnostics);
        if (cls)
            classes.push_back(*cls);
    }
    if (classes.size() != static_cast<std::size_t>(parts.size()))
        return r;

    if (classes.size() == 2) {
        if (classes[0].kind != Kind::Hole || classes[1].kind != Kind::Shaft) {
            r.diagnostics.push_back(
                makeError(field, Iso286::tr("\"%1\": a fit is written hole class first (upper case), then "
                                            "the shaft class (lower case), as in 50 H7/g6")
                                     .arg(text.trimmed())));
            return r;
        }
        d.holeClass = classes[0].name;
        d.shaftClass = classes[1].name;
    } else if (classes[0].kind == Kind::Hole) {
        d.holeClass = classes[0].name;
    } else {
        d.shaftClass = classes[0].name;
    }
    r.designation = d;
    return r;
}

DesignationLimits evaluate(const QString &designation, std::optional<double> nominal_mm, const Options &options)
{
    DesignationLimits r;
    DesignationResult parsed = parseDesignation(designation);
    r.diagnostics = parsed.diagnostics;
    if (!parsed.designation)
        return r;
    const Designation &d = *parsed.designation;
    const QString nominalField = QStringLiteral("nominal_mm");
    std::optional<double> size = d.nominal_mm ? d.nominal_mm : nominal_mm;
    if (d.nominal_mm && nominal_mm && *d.nominal_mm != *nominal_mm) {
        r.diagnostics.push_back(
            makeError(nominalField, Iso286::tr("the designation \"%1\" names %2 mm, but %3 mm was given "
                                               "separately")
                                        .arg(designation.trimmed(), num(*d.nominal_mm), num(*nominal_mm))));
        return r;
    }
    if (!size) {
        r.diagnostics.push_back(
            makeError(nominalField, Iso286::tr("\"%1\" has no nominal size; write it in the designation "
                                               "(50 H7) or give it separately")
                                        .arg(designation.trimmed())));
        return r;
    }
    if (d.isFit()) {
        FitResult f = fit(*size, d.holeClass, d.shaftClass, options);
        r.diagnostics.insert(r.diagnostics.end(), f.diagnostics.begin(), f.diagnostics.end());
        r.fit = f.fit;
    } else {
        LimitsResult l = limits(*size, d.holeClass.isEmpty() ? d.shaftClass : d.holeClass, options);
        r.diagnostics.insert(r.diagnostics.end(), l.diagnostics.begin(), l.diagnostics.end());
        r.limits = l.limits;
    }
    return r;
}

} // namespace tolturn::iso286
