// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/common/diagnostic.h"
#include "core/cutting/cutting_forces.h"
#include "core/project/project.h"

#include <QJsonObject>
#include <QJsonValue>
#include <QString>
#include <QStringList>

#include <memory>
#include <optional>

class QCommandLineOption;
class QCommandLineParser;
class QTextStream;

namespace tolturn {

class MeasurementStore;

// What every tolturn-cli command shares.
[[nodiscard]] QString programName();

// Parses the options of the command `name` and handles --help (usage `synopsis`, then the
// options). Returns -1 to go on, or the exit code when the command must stop here.
[[nodiscard]] int parseCommand(QCommandLineParser &parser, const QString &name, const QString &synopsis,
                               const QString &summary, const QStringList &args, QTextStream &out, QTextStream &err);

// parseCommand for a command of tolturn-cli's table, with its synopsis and summary.
[[nodiscard]] int parseNamedCommand(QCommandLineParser &parser, const QString &name, const QStringList &args,
                                    QTextStream &out, QTextStream &err);

// The project file of a command that takes exactly one; empty after printing the usage error.
[[nodiscard]] QString oneProjectFile(const QCommandLineParser &parser, const QString &command, QTextStream &err);

// The largest force --load takes, per component: twice the 500 kN that a cut of the largest depth
// and feed TolTurn takes (50 mm x 5 mm/rev = 250 mm²) needs at a specific cutting force of
// 2 000 N/mm², about kc1.1 of a hard steel.
inline constexpr double kMaxLoad_N = 1e6;

// The forces of --load: "Fr,Ft,Fa" in newtons (radial, tangential, axial); nullopt if malformed.
[[nodiscard]] std::optional<CuttingForces> parseLoad(const QString &text);

// The value of a number option in [lo, hi]; nullopt, with the option, the value and the range named
// on `err`, when it is not one.
[[nodiscard]] std::optional<double> numberInRange(const QCommandLineParser &parser, const QCommandLineOption &option,
                                                  double lo, double hi, const QString &command, QTextStream &err);

// numberInRange for a whole number.
[[nodiscard]] std::optional<long long> wholeNumberInRange(const QCommandLineParser &parser,
                                                          const QCommandLineOption &option, long long lo, long long hi,
                                                          const QString &command, QTextStream &err);

// Reads a project for a command, printing its problems as "FILE: severity: field: message"; none
// when the file, or `check` (checkPlausibility), finds an error in it.
enum class MissingPasses { Refused, Planned }; // the optimiser plans a project without passes
[[nodiscard]] std::optional<Project> readProject(const QString &file, QTextStream &err,
                                                 MissingPasses missingPasses = MissingPasses::Refused);

// --operation NAME, for the commands that work on one set-up of a project (docs/operations.md).
[[nodiscard]] QCommandLineOption operationOption();
// The project of the operation --operation names (by default the first) when the project has
// several, saying on `err` which one it is; the project itself when it has one. nullopt, with a
// message listing the operations, for a name it does not have.
[[nodiscard]] std::optional<Project> selectOperation(const Project &project, const QCommandLineParser &parser,
                                                     const QString &command, QTextStream &err);

// True for the output path "-" (`-o -`): the command writes its file to standard output, and its
// own messages then go to standard error.
[[nodiscard]] inline bool isStandardOutput(const QString &path)
{
    return path == QLatin1String("-");
}

// An error message when `output` is the file `input` (after symbolic links), which writing the
// output would destroy; empty otherwise (also for "-" and for an output that does not exist yet).
[[nodiscard]] QString overwritesInput(const QString &output, const QString &input);
// The same for the measurement store --store names (its default when empty), when it is a file.
[[nodiscard]] QString overwritesStore(const QString &output, const QString &store);

// Writes a command's output (text, or a PDF or STEP file) to a file atomically, or to standard
// output for "-". Returns an error message, empty on success.
[[nodiscard]] QString writeOutput(const QString &path, const QByteArray &data, QTextStream &out);

// Prints a command's JSON result, unless some number in it is not finite (an overflow the input
// checks did not stop): then nothing is printed, the path of the first such number is named on
// `err`, and the exit code for problems is returned; kExitOk otherwise. No `null` leaves with
// exit code 0.
[[nodiscard]] int printJson(const QJsonValue &result, QTextStream &out, QTextStream &err, const QString &command);

// --store STORE of the commands that use the measurement history (docs/cli.md, measurements).
[[nodiscard]] QCommandLineOption measurementStoreOption();

// The measurement store named by `store` (an SQLite file or a postgresql:// address; empty: the
// per-user file), opened; null after printing why on `err` after `prefix`. Only a command that
// stores parts makes an SQLite store that is not there; one that reads it is told there is none.
enum class StoreAccess { Read, Store };
[[nodiscard]] std::unique_ptr<MeasurementStore> openMeasurementStore(const QString &store, const QString &prefix,
                                                                     QTextStream &err,
                                                                     StoreAccess access = StoreAccess::Read);

} // namespace tolturn
