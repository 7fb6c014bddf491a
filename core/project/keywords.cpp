// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/project/keywords.h"

#include <QCoreApplication>

#include <array>
#include <utility>

namespace tolturn {

namespace {

template <typename Enum>
struct KeywordTable;

template <>
struct KeywordTable<SegmentKind> {
    static constexpr std::array<std::pair<SegmentKind, const char *>, 5> entries{{
        {SegmentKind::Cylinder, "cylinder"},
        {SegmentKind::Face, "face"},
        {SegmentKind::Cone, "cone"},
        {SegmentKind::Chamfer, "chamfer"},
        {SegmentKind::Radius, "radius"},
    }};
};

template <>
struct KeywordTable<ArcDirection> {
    static constexpr std::array<std::pair<ArcDirection, const char *>, 2> entries{{
        {ArcDirection::Clockwise, "cw"},
        {ArcDirection::CounterClockwise, "ccw"},
    }};
};

template <>
struct KeywordTable<ClampingMethod> {
    static constexpr std::array<std::pair<ClampingMethod, const char *>, 4> entries{{
        {ClampingMethod::Chuck, "chuck"},
        {ClampingMethod::BetweenCentres, "centres"},
        {ClampingMethod::ChuckTailstock, "chuck_tailstock"},
        {ClampingMethod::Collet, "collet"},
    }};
};

template <>
struct KeywordTable<PartEnd> {
    static constexpr std::array<std::pair<PartEnd, const char *>, 2> entries{{
        {PartEnd::Left, "left"},
        {PartEnd::Right, "right"},
    }};
};

template <>
struct KeywordTable<PassKind> {
    static constexpr std::array<std::pair<PassKind, const char *>, 2> entries{{
        {PassKind::Roughing, "roughing"},
        {PassKind::Finishing, "finishing"},
    }};
};

template <>
struct KeywordTable<ToleranceType> {
    static constexpr std::array<std::pair<ToleranceType, const char *>, 12> entries{{
        {ToleranceType::Length, "length"},
        {ToleranceType::Diameter, "diameter"},
        {ToleranceType::Flatness, "flatness"},
        {ToleranceType::Cylindricity, "cylindricity"},
        {ToleranceType::Profile, "profile"},
        {ToleranceType::Parallelism, "parallelism"},
        {ToleranceType::Perpendicularity, "perpendicularity"},
        {ToleranceType::Coaxiality, "coaxiality"},
        {ToleranceType::CircularRadialRunout, "circular_radial_runout"},
        {ToleranceType::CircularAxialRunout, "circular_axial_runout"},
        {ToleranceType::TotalRadialRunout, "total_radial_runout"},
        {ToleranceType::TotalAxialRunout, "total_axial_runout"},
    }};
};

template <>
struct KeywordTable<PlanningObjective> {
    static constexpr std::array<std::pair<PlanningObjective, const char *>, 2> entries{{
        {PlanningObjective::Time, "time"},
        {PlanningObjective::Cost, "cost"},
    }};
};

template <>
struct KeywordTable<ForceModel> {
    static constexpr std::array<std::pair<ForceModel, const char *>, 2> entries{{
        {ForceModel::Kienzle, "kienzle"},
        {ForceModel::LiDu, "li_du"},
    }};
};

template <>
struct KeywordTable<MilledFeatureKind> {
    static constexpr std::array<std::pair<MilledFeatureKind, const char *>, 3> entries{{
        {MilledFeatureKind::Flat, "flat"},
        {MilledFeatureKind::Keyway, "keyway"},
        {MilledFeatureKind::Patch, "patch"},
    }};
};

template <>
struct KeywordTable<MilledToleranceType> {
    static constexpr std::array<std::pair<MilledToleranceType, const char *>, 2> entries{{
        {MilledToleranceType::Flatness, "flatness"},
        {MilledToleranceType::Profile, "profile"},
    }};
};

template <>
struct KeywordTable<BallEndCutKind> {
    static constexpr std::array<std::pair<BallEndCutKind, const char *>, 3> entries{{
        {BallEndCutKind::Slot, "slot"},
        {BallEndCutKind::SideCut, "side_cut"},
        {BallEndCutKind::StepOver, "step_over"},
    }};
};

template <>
struct KeywordTable<MillingDirection> {
    static constexpr std::array<std::pair<MillingDirection, const char *>, 2> entries{{
        {MillingDirection::Down, "down"},
        {MillingDirection::Up, "up"},
    }};
};

template <typename Enum>
QString keywordOf(Enum value)
{
    for (const auto &[v, word] : KeywordTable<Enum>::entries) {
        if (v == value)
            return QString::fromLatin1(word);
    }
    return {};
}

} // namespace

QString keyword(SegmentKind value)
{
    return keywordOf(value);
}

QString keyword(ArcDirection value)
{
    return keywordOf(value);
}

QString keyword(ClampingMethod value)
{
    return keywordOf(value);
}

QString keyword(PartEnd value)
{
    return keywordOf(value);
}

QString keyword(PassKind value)
{
    return keywordOf(value);
}

QString keyword(ToleranceType value)
{
    return keywordOf(value);
}

QString keyword(ForceModel value)
{
    return keywordOf(value);
}

const QStringList &planningConstraintKeywords()
{
    static const QStringList words{
        QStringLiteral("tolerances"), QStringLiteral("roughness"),      QStringLiteral("power"),
        QStringLiteral("torque"),     QStringLiteral("force"),          QStringLiteral("spindle_speed"),
        QStringLiteral("tool_life"),  QStringLiteral("roughing_depth"), QStringLiteral("bar_overhang")};
    return words;
}

QString keyword(PlanningObjective value)
{
    return keywordOf(value);
}

QString keyword(MilledFeatureKind value)
{
    return keywordOf(value);
}

QString keyword(MilledToleranceType value)
{
    return keywordOf(value);
}

QString keyword(BallEndCutKind value)
{
    return keywordOf(value);
}

QString keyword(MillingDirection value)
{
    return keywordOf(value);
}

namespace {
struct Names {
    Q_DECLARE_TR_FUNCTIONS(Names)
};
} // namespace

QString displayName(PartEnd value)
{
    return value == PartEnd::Left ? Names::tr("left") : Names::tr("right");
}

QString displayName(ClampingMethod value)
{
    switch (value) {
    case ClampingMethod::Chuck:
        return Names::tr("chuck");
    case ClampingMethod::BetweenCentres:
        return Names::tr("between centres");
    case ClampingMethod::ChuckTailstock:
        return Names::tr("chuck + tailstock");
    case ClampingMethod::Collet:
        return Names::tr("collet");
    }
    return keyword(value);
}

QString displayName(SegmentKind value)
{
    switch (value) {
    case SegmentKind::Cylinder:
        return Names::tr("cylinder");
    case SegmentKind::Face:
        return Names::tr("face");
    case SegmentKind::Cone:
        return Names::tr("cone");
    case SegmentKind::Chamfer:
        return Names::tr("chamfer");
    case SegmentKind::Radius:
        return Names::tr("radius");
    }
    return keyword(value);
}

QString displayName(ToleranceType value)
{
    switch (value) {
    case ToleranceType::Length:
        return Names::tr("length");
    case ToleranceType::Diameter:
        return Names::tr("diameter");
    case ToleranceType::Flatness:
        return Names::tr("flatness");
    case ToleranceType::Cylindricity:
        return Names::tr("cylindricity");
    case ToleranceType::Profile:
        return Names::tr("profile of a surface");
    case ToleranceType::Parallelism:
        return Names::tr("parallelism");
    case ToleranceType::Perpendicularity:
        return Names::tr("perpendicularity");
    case ToleranceType::Coaxiality:
        return Names::tr("coaxiality");
    case ToleranceType::CircularRadialRunout:
        return Names::tr("circular radial run-out");
    case ToleranceType::CircularAxialRunout:
        return Names::tr("circular axial run-out");
    case ToleranceType::TotalRadialRunout:
        return Names::tr("total radial run-out");
    case ToleranceType::TotalAxialRunout:
        return Names::tr("total axial run-out");
    }
    return keyword(value);
}

QString displayName(MilledFeatureKind value)
{
    switch (value) {
    case MilledFeatureKind::Flat:
        return Names::tr("flat");
    case MilledFeatureKind::Keyway:
        return Names::tr("keyway");
    case MilledFeatureKind::Patch:
        return Names::tr("surface patch");
    }
    return keyword(value);
}

QString displayName(BallEndCutKind value)
{
    switch (value) {
    case BallEndCutKind::Slot:
        return Names::tr("slot");
    case BallEndCutKind::SideCut:
        return Names::tr("side cut");
    case BallEndCutKind::StepOver:
        return Names::tr("step-over");
    }
    return keyword(value);
}

template <typename Enum>
std::optional<Enum> fromKeyword(const QString &word)
{
    for (const auto &[v, text] : KeywordTable<Enum>::entries) {
        if (word == QLatin1String(text))
            return v;
    }
    return std::nullopt;
}

template <typename Enum>
QStringList allKeywords()
{
    QStringList words;
    for (const auto &entry : KeywordTable<Enum>::entries)
        words << QString::fromLatin1(entry.second);
    return words;
}

template std::optional<SegmentKind> fromKeyword<SegmentKind>(const QString &);
template std::optional<ArcDirection> fromKeyword<ArcDirection>(const QString &);
template std::optional<ClampingMethod> fromKeyword<ClampingMethod>(const QString &);
template std::optional<PassKind> fromKeyword<PassKind>(const QString &);
template std::optional<PartEnd> fromKeyword<PartEnd>(const QString &);
template std::optional<ToleranceType> fromKeyword<ToleranceType>(const QString &);
template std::optional<ForceModel> fromKeyword<ForceModel>(const QString &);
template std::optional<PlanningObjective> fromKeyword<PlanningObjective>(const QString &);
template std::optional<MilledFeatureKind> fromKeyword<MilledFeatureKind>(const QString &);
template std::optional<MilledToleranceType> fromKeyword<MilledToleranceType>(const QString &);
template std::optional<BallEndCutKind> fromKeyword<BallEndCutKind>(const QString &);
template std::optional<MillingDirection> fromKeyword<MillingDirection>(const QString &);
template QStringList allKeywords<MilledFeatureKind>();
template QStringList allKeywords<MilledToleranceType>();
template QStringList allKeywords<BallEndCutKind>();
template QStringList allKeywords<MillingDirection>();
template QStringList allKeywords<SegmentKind>();
template QStringList allKeywords<ArcDirection>();
template QStringList allKeywords<ClampingMethod>();
template QStringList allKeywords<PassKind>();
template QStringList allKeywords<PartEnd>();
template QStringList allKeywords<ToleranceType>();
template QStringList allKeywords<ForceModel>();
template QStringList allKeywords<PlanningObjective>();

} // namespace tolturn
