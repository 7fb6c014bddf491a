// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/tooling/iso1832.h"

#include <QCoreApplication>
#include <QRegularExpression>

#include <array>
#include <cmath>
#include <numbers>
#include <utility>

namespace tolturn {

namespace {

struct InsertCodes {
    Q_DECLARE_TR_FUNCTIONS(InsertCodes)
};

// ISO 1832:2017 clause 4.1, Table 1: insert shape and its included (corner) angle.
constexpr std::array<std::pair<char, double>, 16> kShapes{{{'A', 85.0},
                                                           {'B', 82.0},
                                                           {'C', 80.0},
                                                           {'D', 55.0},
                                                           {'E', 75.0},
                                                           {'H', 120.0},
                                                           {'K', 55.0},
                                                           {'L', 90.0},
                                                           {'M', 86.0},
                                                           {'O', 135.0},
                                                           {'P', 108.0},
                                                           {'R', 0.0},
                                                           {'S', 90.0},
                                                           {'T', 60.0},
                                                           {'V', 35.0},
                                                           {'W', 80.0}}};

// Clause 4.2, Table 2: normal clearance angle. O (other) carries no angle.
constexpr std::array<std::pair<char, double>, 10> kClearances{{{'A', 3.0},
                                                               {'B', 5.0},
                                                               {'C', 7.0},
                                                               {'D', 15.0},
                                                               {'E', 20.0},
                                                               {'F', 25.0},
                                                               {'G', 30.0},
                                                               {'N', 0.0},
                                                               {'P', 11.0},
                                                               {'O', 0.0}}};

// Clause 4.3: tolerance classes; clause 4.4: types (fixing and chip-breaker forms).
constexpr char kToleranceClasses[] = "AFCHEGJKLMNU";
constexpr char kTypes[] = "ABCFGHJMNQRTUWX";

// Clause 4.6, Table 5: thickness symbols.
constexpr std::array<std::pair<const char *, double>, 12> kThicknesses{{{"01", 1.59},
                                                                        {"T1", 1.98},
                                                                        {"02", 2.38},
                                                                        {"03", 3.18},
                                                                        {"T3", 3.97},
                                                                        {"04", 4.76},
                                                                        {"05", 5.56},
                                                                        {"06", 6.35},
                                                                        {"07", 7.94},
                                                                        {"09", 9.52},
                                                                        {"11", 11.11},
                                                                        {"12", 12.70}}};

// Inscribed circles of inserts with corners (inch series, ISO 883) and of round inserts (metric
// series), ISO 1832 clause 4.5.
constexpr std::array<double, 10> kInscribedCircles{3.97, 4.76, 5.56, 6.35, 7.94, 9.525, 12.7, 15.875, 19.05, 25.4};
constexpr std::array<double, 8> kRoundDiameters{6.0, 8.0, 10.0, 12.0, 16.0, 20.0, 25.0, 32.0};

// Cutting-edge length of a shape with inscribed circle d: rhombic and square inserts
// l = d / sin(epsilon); triangles l = d sqrt(3); trigons (W, 80°) l = d / (2 sin 80° ... ) is
// not a simple function, so their size code maps by the ISO 883 sizes (06 -> 9.525, 08 -> 12.7).
std::optional<double> edgeLengthFor(char shape, double ic)
{
    switch (shape) {
    case 'T':
        return ic * std::sqrt(3.0);
    case 'R':
        return ic;
    case 'W':
        return std::nullopt;
    default:
        break;
    }
    for (const auto &[s, angle] : kShapes) {
        if (s == shape && angle > 0.0 && angle <= 90.0)
            return ic / std::sin(angle * std::numbers::pi / 180.0);
    }
    return std::nullopt;
}

template <std::size_t N>
std::optional<double> lookup(const std::array<std::pair<char, double>, N> &table, char c)
{
    for (const auto &[key, value] : table) {
        if (key == c)
            return value;
    }
    return std::nullopt;
}

QString letters(const char *set)
{
    QString s;
    for (const char *p = set; *p != '\0'; ++p)
        s += QLatin1Char(*p) + QLatin1Char(' ');
    return s.trimmed();
}

template <std::size_t N>
QString tableLetters(const std::array<std::pair<char, double>, N> &table)
{
    QString s;
    for (const auto &entry : table)
        s += QLatin1Char(entry.first) + QLatin1Char(' ');
    return s.trimmed();
}

} // namespace

InsertParseResult parseInsertCode(const QString &code, const QString &field)
{
    InsertParseResult result;
    auto fail = [&](const QString &message) {
        result.diagnostics.push_back(makeError(field, InsertCodes::tr("insert code \"%1\": %2").arg(code, message)));
        return result;
    };
    static const QRegularExpression pattern(
        QStringLiteral("^([A-Z])([A-Z])([A-Z])([A-Z])\\s*(\\d\\d)(T?\\d{1,2})(\\d\\d|M0)\\s*-?\\s*([A-Z0-9-]*)$"));
    const QString text = code.trimmed().toUpper();
    const auto m = pattern.match(text);
    if (!m.hasMatch())
        return fail(
            InsertCodes::tr("not an ISO 1832 designation (four letters, then size, thickness and corner digits, as in "
                            "CNMG 120408)"));
    const char shape = m.captured(1).at(0).toLatin1();
    const char clearance = m.captured(2).at(0).toLatin1();
    const char tolerance = m.captured(3).at(0).toLatin1();
    const char type = m.captured(4).at(0).toLatin1();
    const auto angle = lookup(kShapes, shape);
    if (!angle)
        return fail(InsertCodes::tr("position 1 (shape) '%1' is not one of %2")
                        .arg(QString(QLatin1Char(shape)), tableLetters(kShapes)));
    const auto clearanceAngle = lookup(kClearances, clearance);
    if (!clearanceAngle)
        return fail(InsertCodes::tr("position 2 (clearance angle) '%1' is not one of %2")
                        .arg(QString(QLatin1Char(clearance)), tableLetters(kClearances)));
    if (QByteArray(kToleranceClasses).indexOf(tolerance) < 0)
        return fail(InsertCodes::tr("position 3 (tolerance class) '%1' is not one of %2")
                        .arg(QString(QLatin1Char(tolerance)), letters(kToleranceClasses)));
    if (QByteArray(kTypes).indexOf(type) < 0)
        return fail(InsertCodes::tr("position 4 (type) '%1' is not one of %2")
                        .arg(QString(QLatin1Char(type)), letters(kTypes)));

    const int sizeCode = m.captured(5).toInt();
    std::optional<double> ic;
    double edge = 0.0;
    if (shape == 'W') {
        ic = sizeCode == 6 ? std::optional<double>(9.525) : sizeCode == 8 ? std::optional<double>(12.7) : std::nullopt;
        edge = sizeCode;
    } else if (shape == 'R') {
        for (const double d : kRoundDiameters) {
            if (static_cast<int>(d) == sizeCode) {
                ic = d;
                edge = d;
            }
        }
    } else {
        // The size code is the edge length with its decimals dropped; 0.01 mm absorbs the rounding
        // of the nominal lengths (a 12.7 mm triangle has l = 21.997, code 22).
        for (const double d : kInscribedCircles) {
            const auto l = edgeLengthFor(shape, d);
            if (l && static_cast<int>(std::floor(*l + 0.01)) == sizeCode) {
                ic = d;
                edge = *l;
                break;
            }
        }
    }
    if (!ic)
        return fail(InsertCodes::tr("position 5 (size) '%1' is not a standard cutting-edge length for shape %2")
                        .arg(m.captured(5), QString(QLatin1Char(shape))));

    QString thicknessCode = m.captured(6);
    if (thicknessCode.size() == 1)
        thicknessCode.prepend(QLatin1Char('0'));
    std::optional<double> thickness;
    for (const auto &[symbol, value] : kThicknesses) {
        if (thicknessCode == QLatin1String(symbol))
            thickness = value;
    }
    if (!thickness)
        return fail(
            InsertCodes::tr("position 6 (thickness) '%1' is not an ISO 1832 thickness symbol").arg(m.captured(6)));

    const QString corner = m.captured(7);
    const double nose = corner == QLatin1String("M0") ? 0.0 : corner.toInt() / 10.0;
    if (shape == 'R' && corner != QLatin1String("M0") && corner != QLatin1String("00"))
        return fail(InsertCodes::tr("position 7 of a round insert is M0 or 00, not '%1'").arg(corner));
    if (shape != 'R' && nose <= 0.0)
        return fail(InsertCodes::tr(
                        "position 7 (corner radius) '%1' gives a sharp corner, which turning inserts of shape %2 do "
                        "not have in TolTurn's models")
                        .arg(corner, QString(QLatin1Char(shape))));

    InsertGeometry g;
    g.code = m.captured(1) + m.captured(2) + m.captured(3) + m.captured(4) + QLatin1Char(' ') + m.captured(5) +
             m.captured(6) + corner + (m.captured(8).isEmpty() ? QString() : QLatin1Char('-') + m.captured(8));
    g.shape = QLatin1Char(shape);
    g.includedAngle_deg = *angle;
    g.clearanceLetter = QLatin1Char(clearance);
    g.clearanceAngle_deg = *clearanceAngle;
    g.toleranceClass = QLatin1Char(tolerance);
    g.type = QLatin1Char(type);
    g.edgeLength_mm = edge;
    g.inscribedCircle_mm = *ic;
    g.thickness_mm = *thickness;
    g.noseRadius_mm = nose;
    g.suffix = m.captured(8);
    result.insert = g;
    return result;
}

} // namespace tolturn
