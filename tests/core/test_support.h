// SPDX-License-Identifier: GPL-3.0-or-later
// Helpers shared by the core tests: profile segments written as on a drawing, and the elastic
// constants of the steel the tests' bars are made of.
#pragma once

#include "core/adaptive/force_control.h"
#include "core/common/diagnostic.h"
#include "core/cutting/cutting_forces.h"
#include "core/io/project_file.h"
#include "core/part/profile.h"
#include "core/project/project.h"

#include <QByteArray>
#include <QFile>
#include <QRegularExpression>
#include <QString>
#include <QStringList>
#include <QtGlobal>

#include <cmath>
#include <numbers>
#include <sys/stat.h>
#include <vector>

namespace tolturn::test {

// A bundled example (resources/examples/NAME), read as File > Open reads it; the test stops when it
// cannot be read.
inline Project exampleProject(const char *name)
{
    const ProjectParseResult read =
        readProjectFile(QStringLiteral(TOLTURN_SOURCE_DIR "/resources/examples/") + QString::fromLatin1(name));
    if (!read.project)
        qFatal("cannot read %s", name);
    return *read.project;
}

// C45E-N in resources/data/materials.json: E = 210000 MPa, nu = 0.3 (EN 1993-1-1); the shear
// factor of a solid circle after Cowper (1966).
inline constexpr double kSteelE_MPa = 210000.0;
inline constexpr double kSteelNu = 0.3;
inline constexpr double kSteelG_MPa = kSteelE_MPa / (2 * (1 + kSteelNu));
inline constexpr double kKappaSolidCircle = 6 * (1 + kSteelNu) / (7 + 6 * kSteelNu);

// `value` within `relative` of |reference| (plus `absolute`, for a reference at or near zero).
inline bool nearRelative(double value, double reference, double relative, double absolute = 0.0)
{
    return std::abs(value - reference) <= relative * std::abs(reference) + absolute;
}

// `value` within `tolerance` of `expected`, in their own unit.
inline bool nearAbsolute(double value, double expected, double tolerance)
{
    return std::abs(value - expected) <= tolerance;
}

inline Segment seg(const char *id, SegmentKind kind, ProfilePoint a, ProfilePoint b)
{
    Segment s;
    s.id = QString::fromLatin1(id);
    s.kind = kind;
    s.from = a;
    s.to = b;
    return s;
}

// Sets an environment variable for the life of the object.
class ScopedEnv {
public:
    ScopedEnv(const char *name, const QByteArray &value) : m_name(name) { qputenv(name, value); }

    ~ScopedEnv() { qunsetenv(m_name); }

    ScopedEnv(const ScopedEnv &) = delete;
    ScopedEnv &operator=(const ScopedEnv &) = delete;

private:
    const char *m_name;
};

// Every finding, one a line, for a failing test's message.
inline QString dump(const Diagnostics &d)
{
    QStringList lines;
    for (const Diagnostic &x : d)
        lines << x.toString();
    return lines.join(QLatin1Char('\n'));
}

// The permission bits of a file (-1 when it cannot be read), and those a new file gets: 0666
// less the umask (open(2)).
inline int permissionBits(const QString &path)
{
    struct stat st {};

    return ::stat(QFile::encodeName(path).constData(), &st) == 0 ? static_cast<int>(st.st_mode & 0777) : -1;
}

inline int newFileBits()
{
    const mode_t mask = ::umask(0);
    ::umask(mask);
    return static_cast<int>(0666 & ~mask);
}

// A turning process for the constant-force loop: Kienzle without a nose radius at kappa_r = 90°,
// Fc = k11 a f^(1 − m), Ff and Fp 0.3 and 0.4 of it, so the resultant is Fc sqrt(1 + 0.3² + 0.4²)
// and F ∝ f^(1 − m) exactly; at Ø60 mm 1000 rpm.
inline PassProcess kienzlePassProcess(double k11, double m)
{
    KienzleConstants c;
    c.cutting = {k11, m};
    c.feedToCuttingRatio = 0.3;
    c.passiveToCuttingRatio = 0.4;
    PassProcess p;
    p.forces = [c](double f, double a) { return kienzleForces(c, f, a, std::numbers::pi / 2.0).forces; };
    p.cuttingSpeed_m_min = std::numbers::pi * 60.0;
    p.noseRadius_mm = 0.8;
    return p;
}

// G-code moves: (X, Z) end points of G00/G01/G02/G03 lines, in order (a small reader for the tests).
struct Move {
    int g = 0;
    double x = 0.0;
    double z = 0.0;
};

inline std::vector<Move> readMoves(const QString &program)
{
    static const QRegularExpression word(QStringLiteral("([GXZ])(-?\\d+(?:\\.\\d+)?)"));
    std::vector<Move> moves;
    Move state;
    for (QString line : program.split(QLatin1Char('\n'))) {
        line.remove(QRegularExpression(QStringLiteral("\\([^)]*\\)")));
        bool motion = false;
        auto it = word.globalMatch(line);
        while (it.hasNext()) {
            const auto m = it.next();
            const double v = m.captured(2).toDouble();
            if (m.captured(1) == QLatin1String("G") && v <= 3.0) {
                state.g = static_cast<int>(v);
                motion = true;
            } else if (m.captured(1) == QLatin1String("X")) {
                state.x = v;
                motion = true;
            } else if (m.captured(1) == QLatin1String("Z")) {
                state.z = v;
                motion = true;
            }
        }
        if (motion && (line.contains(QLatin1Char('X')) || line.contains(QLatin1Char('Z'))))
            moves.push_back(state);
    }
    return moves;
}

// The moves of a program's finishing passes.
inline std::vector<Move> finishingMoves(const QString &program)
{
    return readMoves(program.mid(program.indexOf(QStringLiteral(", FINISHING:"))));
}

// Whether the tool reaches a station: it keeps 2 mm from the jaws, plus its nose radius 0.8 mm.
inline bool reachedByTheTool(const Project &p, double z_mm)
{
    const double support = p.clamping.method == ClampingMethod::BetweenCentres ? 0.0 : p.clamping.clampedLength_mm;
    return z_mm >= support + 2.0 + 0.8 - 1e-9;
}

} // namespace tolturn::test
