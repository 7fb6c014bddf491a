// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/common/diagnostic.h"

#include <QHash>
#include <QString>
#include <QStringList>

#include <map>
#include <optional>
#include <vector>

namespace tolturn {

// A number from a data file with the key of the source it was read from.
struct SourcedValue {
    double value = 0.0;
    QString source;
};

// A work material (resources/data/materials.json).
struct MaterialData {
    QString id;
    QString name;
    QString standard;
    QString isoGroup; // ISO 513 application group: P, M, K, N, S, H
    SourcedValue youngsModulus_MPa;
    std::optional<SourcedValue> poissonRatio;
    SourcedValue density_kg_m3;
    std::optional<SourcedValue> tensileStrength_MPa;
    SourcedValue kc11_MPa;
    SourcedValue mc;
    std::optional<SourcedValue> kf11_MPa, mf, kp11_MPa, mp;
    std::optional<SourcedValue> feedToCuttingRatio, passiveToCuttingRatio;
    std::optional<SourcedValue> taylorC_m_min, taylorN;
};

// A published range of a support's stiffness, for machines that were not measured
// (machines.json "uncharacterised_supports"): its compliant and stiff ends and what it is valid for.
struct StiffnessRange {
    SourcedValue compliant_N_per_mm;
    SourcedValue stiff_N_per_mm;
    QString validFor;
};

// What the data give for the supports of a machine that was not measured: ranges where a source
// gives one, nothing where none was found (docs/model.md §2).
struct UncharacterisedSupports {
    std::optional<StiffnessRange> chuckRadial; // static radial stiffness at the chuck face
    std::optional<StiffnessRange> tailstockRadial;
    std::optional<StiffnessRange> centreRadial;
    QString notes;
};

// What clamping a part again costs features cut in different operations (machines.json
// "reclamping"): a chuck maker's largest concentricity and axial run-out errors.
struct ReclampingErrors {
    std::optional<SourcedValue> concentricity_mm;
    std::optional<SourcedValue> axialRunout_mm;
};

// A lathe (resources/data/machines.json): documented limits, keyed by field name
// ("power_kW", "max_speed_rpm", ...). A measured stiffness is a characterisation of one machine,
// kept in the project (see Project::characterisation); the data give ranges for the rest.
struct MachineData {
    QString id;
    QString name;
    QString notes;
    QString control; // dialect of its CNC control ("fanuc", "sinumerik", "linuxcnc"); empty: none known
    std::map<QString, SourcedValue> limits;
};

// A tool holder (resources/data/holders.json).
struct HolderData {
    QString code;
    QString kind;
    SourcedValue enteringAngle_deg;
    std::optional<SourcedValue> shankHeight_mm, shankWidth_mm, length_mm, barDiameter_mm;
    std::optional<SourcedValue> rake_deg, inclination_deg;

    // A boring bar (an internal tool held along the part's axis), by the kind the data give it.
    [[nodiscard]] bool isBoringBar() const { return kind.startsWith(QLatin1String("boring bar")); }
};

// What a boring bar is made of (holders.json "boring_bar_materials"), found from the
// toolholder-type letter that begins its ISO designation (S, A: steel; E: carbide).
struct BoringBarMaterialData {
    QString id; // "steel", "carbide"
    QStringList typeLetters;
    SourcedValue youngsModulus_MPa; // the compliant end of the published range
    SourcedValue poissonRatio;
    SourcedValue maxOverhangRatio; // the maker's largest overhang / bar diameter
};

// The ids of a data library's entries (materials, machines), for a message naming an unknown one.
template <typename Entries>
[[nodiscard]] QString libraryIds(const Entries &entries)
{
    QStringList ids;
    for (const auto &entry : entries)
        ids << entry.id;
    return ids.join(QStringLiteral(", "));
}

// The data shipped with TolTurn. Every number carries the key of its source; sourceText() gives
// the citation.
class DataLibrary {
public:
    // The built-in library, read once from the program's resources.
    static const DataLibrary &builtIn();
    // Reads a library from the three files; problems are reported with file and field.
    static DataLibrary load(const QString &materialsPath, const QString &machinesPath, const QString &holdersPath);

    [[nodiscard]] const Diagnostics &diagnostics() const { return m_diagnostics; }

    [[nodiscard]] const MaterialData *material(const QString &id) const;
    [[nodiscard]] const MachineData *machine(const QString &id) const;
    [[nodiscard]] const HolderData *holder(const QString &code) const;

    [[nodiscard]] const std::vector<MaterialData> &materials() const { return m_materials; }

    [[nodiscard]] const std::vector<MachineData> &machines() const { return m_machines; }

    [[nodiscard]] const std::vector<HolderData> &holders() const { return m_holders; }

    // Entering angle of a holder style letter (ISO 5608 position 3), e.g. 'L' -> 95°.
    [[nodiscard]] std::optional<SourcedValue> styleEnteringAngle(QChar style) const;

    // Rake and inclination the seat of a holder for negative inserts gives them.
    [[nodiscard]] std::optional<SourcedValue> negativeSeatRake() const { return m_negativeSeatRake; }

    [[nodiscard]] std::optional<SourcedValue> negativeSeatInclination() const { return m_negativeSeatInclination; }

    // Feed and passive force ratios for materials whose entry has neither their own Kienzle
    // constants nor ratios (materials.json "defaults").
    [[nodiscard]] std::optional<SourcedValue> defaultFeedToCuttingRatio() const { return m_defaultFeedRatio; }

    [[nodiscard]] std::optional<SourcedValue> defaultPassiveToCuttingRatio() const { return m_defaultPassiveRatio; }

    // The Taylor exponent n of carbide turning inserts, from tool makers' speed–life factors
    // (materials.json "defaults"): a class value, with C still to come from the insert's catalogue.
    [[nodiscard]] std::optional<SourcedValue> defaultTaylorExponent() const { return m_defaultTaylorN; }

    // Support stiffness ranges for a machine without a measured characterisation.
    [[nodiscard]] const UncharacterisedSupports &uncharacterisedSupports() const { return m_supports; }

    // The material of a boring bar from the first letter of its designation; nullptr when the
    // letter is not one the data know (a damped bar, say).
    [[nodiscard]] const BoringBarMaterialData *boringBarMaterial(const HolderData &bar) const;

    [[nodiscard]] const std::vector<BoringBarMaterialData> &boringBarMaterials() const { return m_barMaterials; }

    [[nodiscard]] const ReclampingErrors &reclamping() const { return m_reclamping; }

    // Young's modulus of a steel tool shank.
    [[nodiscard]] std::optional<SourcedValue> shankModulus() const { return m_shankModulus; }

    [[nodiscard]] QString sourceText(const QString &key) const { return m_sources.value(key); }

    [[nodiscard]] const QHash<QString, QString> &sources() const { return m_sources; }

private:
    void readMaterials(const QString &path);
    void readMachines(const QString &path);
    void readHolders(const QString &path);

    Diagnostics m_diagnostics;
    QHash<QString, QString> m_sources;
    std::vector<MaterialData> m_materials;
    std::vector<MachineData> m_machines;
    std::vector<HolderData> m_holders;
    std::vector<BoringBarMaterialData> m_barMaterials;
    std::map<QChar, SourcedValue> m_styleAngles;
    std::optional<SourcedValue> m_negativeSeatRake;
    std::optional<SourcedValue> m_negativeSeatInclination;
    std::optional<SourcedValue> m_shankModulus;
    UncharacterisedSupports m_supports;
    ReclampingErrors m_reclamping;
    std::optional<SourcedValue> m_defaultFeedRatio;
    std::optional<SourcedValue> m_defaultPassiveRatio;
    std::optional<SourcedValue> m_defaultTaylorN;
};

} // namespace tolturn
