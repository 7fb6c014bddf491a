// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/cli/milling_input.h"

#include "app/cli/cli_common.h"
#include "core/milling/seed_ball_end_cases.h"

#include <QCommandLineParser>
#include <QTextStream>

#include <numbers>

namespace tolturn {

namespace {

constexpr double kDegree = std::numbers::pi / 180.0;

// Sets `target` from an option given in range; false after naming it when it is not.
bool readNumber(const QCommandLineParser &parser, const QCommandLineOption &option, double lo, double hi, double scale,
                double &target, const QString &command, QTextStream &err)
{
    if (!parser.isSet(option))
        return true;
    const std::optional<double> v = numberInRange(parser, option, lo, hi, command, err);
    if (v)
        target = *v * scale;
    return v.has_value();
}

bool readCut(const QCommandLineParser &parser, const MillingOptions &o, MillingInput &in, const QString &command,
             QTextStream &err)
{
    bool ok = readNumber(parser, o.diameter, 0.1, 100.0, 1.0, in.mill.diameter_mm, command, err);
    if (parser.isSet(o.flutes)) {
        const std::optional<long long> flutes = wholeNumberInRange(parser, o.flutes, 1, 12, command, err);
        ok = flutes.has_value() && ok;
        if (flutes)
            in.mill.flutes = static_cast<int>(*flutes);
    }
    ok = readNumber(parser, o.helix, 0.0, 59.0, kDegree, in.mill.helix_rad, command, err) && ok;
    ok = readNumber(parser, o.lead, -60.0, 60.0, kDegree, in.cut.lead_rad, command, err) && ok;
    ok = readNumber(parser, o.tilt, -60.0, 60.0, kDegree, in.cut.tilt_rad, command, err) && ok;
    ok = readNumber(parser, o.axialDepth, 0.001, 50.0, 1.0, in.cut.axialDepth_mm, command, err) && ok;
    ok = readNumber(parser, o.feedPerTooth, 0.0001, 2.0, 1.0, in.cut.feedPerTooth_mm, command, err) && ok;
    ok = readNumber(parser, o.spindle, 1.0, 100000.0, 1.0, in.spindle_rpm, command, err) && ok;
    if (parser.isSet(o.radialDepth) && parser.isSet(o.stepOver)) {
        complain(err, command, MillingCommand::tr("give --radial-depth or --step-over, not both"));
        return false;
    }
    if (parser.isSet(o.radialDepth) || parser.isSet(o.stepOver)) {
        const bool side = parser.isSet(o.radialDepth);
        in.cut.kind = side ? BallEndCutKind::SideCut : BallEndCutKind::StepOver;
        ok = readNumber(parser, side ? o.radialDepth : o.stepOver, 0.001, 100.0, 1.0, in.cut.radialDepth_mm, command,
                        err) &&
             ok;
    }
    if (parser.isSet(o.up))
        in.cut.direction = MillingDirection::Up;
    return ok;
}

bool readResolution(const QCommandLineParser &parser, const MillingOptions &o, MillingInput &in, const QString &command,
                    QTextStream &err)
{
    const std::optional<long long> slices = wholeNumberInRange(parser, o.slices, 1, 20000, command, err);
    const std::optional<long long> angles = wholeNumberInRange(parser, o.angles, 1, 36000, command, err);
    if (!slices || !angles)
        return false;
    in.resolution = {static_cast<int>(*slices), static_cast<int>(*angles)};
    return true;
}

// The tool, cut and coefficients of a mill-* command; nullopt after saying what is wrong.
std::optional<MillingInput> readOptionsInput(const QCommandLineParser &parser, const MillingOptions &o,
                                             const QString &command, QTextStream &err, bool feedPlanned)
{
    MillingInput in;
    in.mill.helix_rad = 30.0 * kDegree;
    if (parser.isSet(o.caseNumber)) {
        const std::optional<long long> number = wholeNumberInRange(parser, o.caseNumber, 1, 4, command, err);
        if (!number)
            return std::nullopt;
        const SeedBallEndCase seed = seedBallEndCases().at(static_cast<std::size_t>(*number - 1));
        in.mill = seed.mill;
        in.cut = seed.cut;
        in.spindle_rpm = seed.spindle_rpm;
        in.caseNumber = seed.number;
    } else {
        QStringList missing;
        for (const QCommandLineOption *required : {&o.diameter, &o.flutes, &o.axialDepth, &o.feedPerTooth, &o.spindle})
            if (!parser.isSet(*required) && !(feedPlanned && required == &o.feedPerTooth))
                missing << QStringLiteral("--") + required->names().constFirst();
        in.cut.feedPerTooth_mm = 0.1; // mill-optimize plans it; the force model needs one to start from
        if (!missing.isEmpty()) {
            complain(err, command,
                     MillingCommand::tr("give --case N, or the tool and cut: %1 missing").arg(missing.join(u", ")));
            return std::nullopt;
        }
    }
    if (!readCut(parser, o, in, command, err) || !readResolution(parser, o, in, command, err))
        return std::nullopt;
    if (!parser.isSet(o.coefficients)) {
        complain(err, command,
                 MillingCommand::tr("--coefficients Ktc,Krc,Kac,Kte,Kre,Kae is required: Öztürk & Budak print no "
                                    "coefficients (theirs come from an orthogonal-cutting database of Ti6Al4V through "
                                    "the oblique transformation), and TolTurn's data library has none for ball-end "
                                    "milling; give your tool and material's (docs/milling.md)"));
        return std::nullopt;
    }
    const std::optional<MillingForceCoefficients> k = parseMillingCoefficients(parser.value(o.coefficients));
    if (!k) {
        complain(err, command,
                 MillingCommand::tr("--coefficients: \"%1\" is not six numbers Ktc,Krc,Kac,Kte,Kre,Kae of at most %2")
                     .arg(parser.value(o.coefficients))
                     .arg(kMaxMillingCoefficient));
        return std::nullopt;
    }
    in.coefficients = *k;
    const std::vector<std::string> problems = validateBallEndCut(in.mill, in.cut, in.resolution);
    for (const std::string &p : problems)
        complain(err, command, QString::fromStdString(p));
    if (!problems.empty())
        return std::nullopt;
    return in;
}

// The feature's tool and cut from PROJECT --feature ID; options that would change them are refused
// (change the project instead), so that what is computed is what the project says.
std::optional<MillingInput> readFeatureInput(const QCommandLineParser &parser, const MillingOptions &o,
                                             const QString &command, QTextStream &err)
{
    QStringList clashing;
    for (const QCommandLineOption *option :
         {&o.caseNumber, &o.diameter, &o.flutes, &o.helix, &o.lead, &o.tilt, &o.axialDepth, &o.radialDepth, &o.stepOver,
          &o.up, &o.feedPerTooth, &o.spindle, &o.coefficients})
        if (parser.isSet(*option))
            clashing << QStringLiteral("--") + option->names().constFirst();
    if (!clashing.isEmpty()) {
        complain(err, command,
                 MillingCommand::tr("%1: the tool and cut come from the project's feature; change them there")
                     .arg(clashing.join(u", ")));
        return std::nullopt;
    }
    MillingInput in;
    in.projectFile = parser.positionalArguments().constFirst();
    const std::optional<Project> project = readProject(in.projectFile, err);
    if (!project)
        return std::nullopt;
    const QString id = parser.value(o.feature);
    const auto found = std::find_if(project->milledFeatures.begin(), project->milledFeatures.end(),
                                    [&](const MilledFeature &f) { return f.id == id; });
    if (found == project->milledFeatures.end()) {
        complain(err, command,
                 MillingCommand::tr("--feature: there is no milled feature \"%1\" in %2").arg(id, in.projectFile));
        return std::nullopt;
    }
    QStringList missing;
    const std::optional<MilledFeatureInputs> inputs = milledFeatureInputs(*found, missing);
    if (!inputs) {
        complain(err, command,
                 MillingCommand::tr("milled feature %1 lacks %2").arg(id, missing.join(QStringLiteral(", "))));
        return std::nullopt;
    }
    in.feature = *found;
    in.mill = inputs->mill;
    in.cut = inputs->cut;
    in.spindle_rpm = inputs->spindle_rpm;
    in.coefficients = inputs->coefficients;
    in.structure = inputs->structure;
    in.carbideAssumed = inputs->carbideAssumed;
    in.tolerance = inputs->tolerance;
    return in;
}

// A patch's lead and tilt at its CL point --point; false after saying why.
bool atPathPoint(const QCommandLineParser &parser, const MillingOptions &o, MillingInput &in, const QString &command,
                 QTextStream &err)
{
    if (in.feature->kind != MilledFeatureKind::Patch)
        return true;
    const std::optional<long long> point =
        wholeNumberInRange(parser, o.point, 1, static_cast<long long>(in.feature->path.size()), command, err);
    if (!point)
        return false;
    try {
        const PathStation station =
            pathStations(in.feature->path, 0.5 * in.mill.diameter_mm).at(static_cast<std::size_t>(*point - 1));
        in.cut.lead_rad = station.angles.lead_rad;
        in.cut.tilt_rad = station.angles.tilt_rad;
    } catch (const std::invalid_argument &refused) {
        complain(err, command, QString::fromStdString(refused.what()));
        return false;
    }
    return true;
}

} // namespace

void complain(QTextStream &err, const QString &command, const QString &message)
{
    err << programName() << ' ' << command << ": " << message << '\n';
}

std::optional<MillingInput> readMillingInput(const QCommandLineParser &parser, const MillingOptions &o,
                                             const QString &command, QTextStream &err, bool feedPlanned)
{
    if (parser.positionalArguments().isEmpty())
        return readOptionsInput(parser, o, command, err, feedPlanned);
    std::optional<MillingInput> in = readFeatureInput(parser, o, command, err);
    if (!in || !readResolution(parser, o, *in, command, err) || !atPathPoint(parser, o, *in, command, err))
        return std::nullopt;
    const std::vector<std::string> problems = validateBallEndCut(in->mill, in->cut, in->resolution);
    for (const std::string &p : problems)
        complain(err, command, QString::fromStdString(p));
    return problems.empty() ? in : std::nullopt;
}

std::optional<BallEndToolStructure> readStructure(const QCommandLineParser &parser, const DeflectOptions &d,
                                                  const MillingInput &in, const QString &command, QTextStream &err)
{
    if (in.structure) {
        for (const QCommandLineOption *option : {&d.overhang, &d.equivalentDiameter, &d.modulus, &d.holder})
            if (parser.isSet(*option)) {
                complain(err, command,
                         MillingCommand::tr("--%1: the tool's structure comes from the project's feature; change it "
                                            "there")
                             .arg(option->names().constFirst()));
                return std::nullopt;
            }
        return in.structure;
    }
    BallEndToolStructure tool;
    QStringList missing;
    for (const QCommandLineOption *required : {&d.overhang, &d.equivalentDiameter})
        if (!parser.isSet(*required))
            missing << QStringLiteral("--") + required->names().constFirst();
    if (!parser.isSet(d.holder) && in.caseNumber == 0)
        missing << QStringLiteral("--holder");
    if (!missing.isEmpty()) {
        complain(err, command,
                 MillingCommand::tr("the tool's structure is needed: %1 missing").arg(missing.join(u", ")));
        return std::nullopt;
    }
    bool ok = readNumber(parser, d.overhang, 1.0, 1000.0, 1.0, tool.overhang_mm, command, err);
    ok = readNumber(parser, d.equivalentDiameter, 0.1, 100.0, 1.0, tool.equivalentDiameter_mm, command, err) && ok;
    tool.youngsModulus_N_mm2 = kCarbideModulus_N_mm2;
    ok = readNumber(parser, d.modulus, 1000.0, 1.2e6, 1.0, tool.youngsModulus_N_mm2, command, err) && ok;
    tool.holderStiffness_N_mm = kSeedHolderStiffness_N_mm;
    tool.holderRotational_N_mm_rad = kSeedHolderRotational_N_mm_rad;
    if (parser.isSet(d.holder)) {
        const QStringList parts = parser.value(d.holder).split(QLatin1Char(','));
        bool okK = parts.size() == 2;
        bool okTheta = okK;
        if (okK) {
            tool.holderStiffness_N_mm = parts.at(0).trimmed().toDouble(&okK);
            tool.holderRotational_N_mm_rad = parts.at(1).trimmed().toDouble(&okTheta);
        }
        if (!okK || !okTheta) {
            complain(err, command,
                     MillingCommand::tr("--holder: \"%1\" is not two numbers K,KTHETA").arg(parser.value(d.holder)));
            ok = false;
        }
    }
    if (!ok)
        return std::nullopt;
    const std::vector<std::string> problems = validateToolStructure(tool, in.mill);
    for (const std::string &p : problems)
        complain(err, command, QString::fromStdString(p));
    return problems.empty() ? std::optional(tool) : std::nullopt;
}

} // namespace tolturn
