// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// What the mill-* commands read (docs/cli.md "Ball-end milling"): the tool, cut and coefficients
// from options, from 001's table 4 (--case) or from a project's milled feature (PROJECT --feature),
// and the tool's structure for its deflection.

#include "core/milling/milled_features.h"

#include <QCommandLineOption>
#include <QCoreApplication>
#include <QList>

#include <optional>

class QCommandLineParser;
class QTextStream;

namespace tolturn {

struct MillingCommand {
    Q_DECLARE_TR_FUNCTIONS(MillingCommand)
};

struct MillingOptions {
    QCommandLineOption caseNumber{QStringLiteral("case"),
                                  MillingCommand::tr("Öztürk & Budak's cut 1–4 (001 table 4): tool, cut and speed; "
                                                     "the options below change it."),
                                  QStringLiteral("N")};
    QCommandLineOption diameter{QStringLiteral("diameter"), MillingCommand::tr("Ball diameter in mm."),
                                QStringLiteral("MM")};
    QCommandLineOption flutes{QStringLiteral("flutes"), MillingCommand::tr("Number of flutes."), QStringLiteral("N")};
    QCommandLineOption helix{QStringLiteral("helix"), MillingCommand::tr("Helix angle in degrees (default 30)."),
                             QStringLiteral("DEG")};
    QCommandLineOption lead{QStringLiteral("lead"), MillingCommand::tr("Lead angle in degrees (default 0)."),
                            QStringLiteral("DEG")};
    QCommandLineOption tilt{QStringLiteral("tilt"), MillingCommand::tr("Tilt angle in degrees (default 0)."),
                            QStringLiteral("DEG")};
    QCommandLineOption axialDepth{QStringLiteral("axial-depth"),
                                  MillingCommand::tr("Axial depth of cut along the surface normal in mm."),
                                  QStringLiteral("MM")};
    QCommandLineOption radialDepth{QStringLiteral("radial-depth"),
                                   MillingCommand::tr("Side cut into uncut material this wide, in mm (table 1); "
                                                      "without it or --step-over, a slot."),
                                   QStringLiteral("MM")};
    QCommandLineOption stepOver{QStringLiteral("step-over"),
                                MillingCommand::tr("Cut beside a previous pass this far away, in mm (table 2)."),
                                QStringLiteral("MM")};
    QCommandLineOption up{QStringLiteral("up"), MillingCommand::tr("Up milling (default down milling).")};
    QCommandLineOption feedPerTooth{QStringLiteral("feed-per-tooth"), MillingCommand::tr("Feed per tooth in mm."),
                                    QStringLiteral("MM")};
    QCommandLineOption spindle{QStringLiteral("spindle-speed"), MillingCommand::tr("Spindle speed in 1/min."),
                               QStringLiteral("RPM")};
    QCommandLineOption coefficients{
        QStringLiteral("coefficients"),
        MillingCommand::tr("The tool and material's cutting and edge coefficients Ktc,Krc,Kac (N/mm²),Kte,Kre,Kae "
                           "(N/mm) of the linear edge-force model (001 eq. 11). Required: 001 prints none, and "
                           "TolTurn's data library has none for ball-end milling."),
        QStringLiteral("K")};
    QCommandLineOption slices{QStringLiteral("slices"),
                              MillingCommand::tr("Disc elements over the engaged height (default 200)."),
                              QStringLiteral("N"), QStringLiteral("200")};
    QCommandLineOption angles{QStringLiteral("angles"),
                              MillingCommand::tr("Rotation angles per revolution (default 360)."), QStringLiteral("N"),
                              QStringLiteral("360")};
    QCommandLineOption feature{
        QStringLiteral("feature"),
        MillingCommand::tr("The milled feature of the project PROJECT to compute, with its tool, "
                           "cut, coefficients and tolerance."),
        QStringLiteral("ID")};
    QCommandLineOption point{QStringLiteral("point"),
                             MillingCommand::tr("With --feature, a patch's CL point to compute at (default 1; "
                                                "mill-optimize plans the whole path)."),
                             QStringLiteral("N"), QStringLiteral("1")};
    QCommandLineOption json{QStringLiteral("json"), MillingCommand::tr("Print the results as JSON.")};
    QCommandLineOption csv{QStringLiteral("csv"), MillingCommand::tr("Print every rotation angle as CSV.")};

    [[nodiscard]] QList<QCommandLineOption> all() const
    {
        return {caseNumber,   diameter, flutes,       helix,  lead,   tilt,    axialDepth, radialDepth, stepOver, up,
                feedPerTooth, spindle,  coefficients, slices, angles, feature, point,      json,        csv};
    }
};

struct MillingInput {
    BallEndMill mill;
    BallEndCut cut;
    double spindle_rpm = 0.0;
    MillingForceCoefficients coefficients;
    BallEndResolution resolution;
    int caseNumber = 0;
    // From a project's milled feature (PROJECT --feature ID): the feature, the file, its tool's
    // structure and its tolerance.
    std::optional<MilledFeature> feature;
    QString projectFile;
    std::optional<BallEndToolStructure> structure;
    bool carbideAssumed = false;
    std::optional<MilledSurfaceTolerance> tolerance;
};

struct DeflectOptions {
    QCommandLineOption overhang{QStringLiteral("overhang"),
                                MillingCommand::tr("From where the holder grips the tool to its tip, in mm."),
                                QStringLiteral("MM")};
    QCommandLineOption equivalentDiameter{
        QStringLiteral("equivalent-diameter"),
        MillingCommand::tr("Diameter of the cylinder that stands for the fluted tool in bending, in mm."),
        QStringLiteral("MM")};
    QCommandLineOption modulus{QStringLiteral("modulus"),
                               MillingCommand::tr("Young's modulus of the tool in N/mm² (default 630000, tungsten "
                                                  "carbide; cemented carbides span 530000–700000)."),
                               QStringLiteral("E"), QString::number(kCarbideModulus_N_mm2)};
    QCommandLineOption holder{QStringLiteral("holder"),
                              MillingCommand::tr("The holder's springs k (N/mm) and k_θ (N·mm/rad) as K,KTHETA; with "
                                                 "--case, 001's calibration 6306,1.656e7 for its tool."),
                              QStringLiteral("K,KTHETA")};
};

// "programName command: message" on the error stream.
void complain(QTextStream &err, const QString &command, const QString &message);

// The tool, cut and coefficients of a mill-* command; nullopt after saying what is wrong. With
// `feedPlanned` (mill-optimize) the feed per tooth is not required.
[[nodiscard]] std::optional<MillingInput> readMillingInput(const QCommandLineParser &parser, const MillingOptions &o,
                                                           const QString &command, QTextStream &err,
                                                           bool feedPlanned = false);

// The tool's structure: the feature's, or from the options; nullopt after saying what is wrong.
[[nodiscard]] std::optional<BallEndToolStructure> readStructure(const QCommandLineParser &parser,
                                                                const DeflectOptions &d, const MillingInput &in,
                                                                const QString &command, QTextStream &err);

} // namespace tolturn
