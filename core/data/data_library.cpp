// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/data/data_library.h"

#include <QCoreApplication>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

namespace tolturn {

namespace {

struct DataFiles {
    Q_DECLARE_TR_FUNCTIONS(DataFiles)
};

// Reads one data file: a JSON object with "format", "version" 1 and "sources".
class DataFileReader {
public:
    DataFileReader(const QString &path, const char *format, Diagnostics &out, QHash<QString, QString> &sources)
        : m_path(path)
        , m_out(out)
        , m_sources(sources)
    {
        QFile file(path);
        if (!file.open(QIODevice::ReadOnly)) {
            error(QString(), DataFiles::tr("cannot open the data file: %1").arg(file.errorString()));
            return;
        }
        QJsonParseError parseError;
        const QJsonDocument doc = QJsonDocument::fromJson(file.readAll(), &parseError);
        if (parseError.error != QJsonParseError::NoError || !doc.isObject()) {
            error(QString(), DataFiles::tr("not a valid JSON object: %1").arg(parseError.errorString()));
            return;
        }
        m_root = doc.object();
        if (m_root.value(QStringLiteral("format")).toString() != QLatin1String(format) ||
            m_root.value(QStringLiteral("version")).toInt() != 1) {
            error(QStringLiteral("format"),
                  DataFiles::tr("expected format \"%1\" version 1").arg(QLatin1String(format)));
            m_root = {};
            return;
        }
        const QJsonObject table = m_root.value(QStringLiteral("sources")).toObject();
        for (auto it = table.begin(); it != table.end(); ++it)
            m_sources.insert(it.key(), it.value().toString());
    }

    [[nodiscard]] const QJsonObject &root() const { return m_root; }

    void error(const QString &field, const QString &message)
    {
        m_out.push_back(makeError(m_path + (field.isEmpty() ? QString() : QStringLiteral(": ") + field), message));
    }

    // {"value": number, "source": key}; the key must be in "sources".
    std::optional<SourcedValue> value(const QJsonObject &object, const QString &key, const QString &path, bool required)
    {
        const QJsonValue v = object.value(key);
        if (v.isUndefined()) {
            if (required)
                error(path + QLatin1Char('.') + key, DataFiles::tr("required value is missing"));
            return std::nullopt;
        }
        const QJsonObject o = v.toObject();
        const QString source = o.value(QStringLiteral("source")).toString();
        if (!o.value(QStringLiteral("value")).isDouble() || !m_sources.contains(source)) {
            error(path + QLatin1Char('.') + key,
                  DataFiles::tr("expected {\"value\": number, \"source\": key of \"sources\"}"));
            return std::nullopt;
        }
        return SourcedValue{o.value(QStringLiteral("value")).toDouble(), source};
    }

private:
    QString m_path;
    Diagnostics &m_out;
    QHash<QString, QString> &m_sources;
    QJsonObject m_root;
};

} // namespace

const DataLibrary &DataLibrary::builtIn()
{
    static const DataLibrary library =
        load(QStringLiteral(":/data/materials.json"), QStringLiteral(":/data/machines.json"),
             QStringLiteral(":/data/holders.json"));
    return library;
}

DataLibrary DataLibrary::load(const QString &materialsPath, const QString &machinesPath, const QString &holdersPath)
{
    DataLibrary library;
    library.readMaterials(materialsPath);
    library.readMachines(machinesPath);
    library.readHolders(holdersPath);
    return library;
}

void DataLibrary::readMaterials(const QString &path)
{
    DataFileReader r(path, "tolturn-materials", m_diagnostics, m_sources);
    const QJsonObject defaults = r.root().value(QStringLiteral("defaults")).toObject();
    m_defaultFeedRatio = r.value(defaults, QStringLiteral("feed_to_cutting_ratio"), QStringLiteral("defaults"), true);
    m_defaultPassiveRatio =
        r.value(defaults, QStringLiteral("passive_to_cutting_ratio"), QStringLiteral("defaults"), true);
    m_defaultTaylorN = r.value(defaults, QStringLiteral("taylor_n_carbide_turning"), QStringLiteral("defaults"), false);
    const QJsonArray list = r.root().value(QStringLiteral("materials")).toArray();
    for (qsizetype i = 0; i < list.size(); ++i) {
        const QJsonObject o = list.at(i).toObject();
        const QString p = QStringLiteral("materials[%1]").arg(i);
        const QJsonObject k = o.value(QStringLiteral("kienzle")).toObject();
        const QString kp = p + QStringLiteral(".kienzle");
        MaterialData m;
        m.id = o.value(QStringLiteral("id")).toString();
        m.name = o.value(QStringLiteral("name")).toString();
        m.standard = o.value(QStringLiteral("standard")).toString();
        m.isoGroup = o.value(QStringLiteral("iso_group")).toString();
        const auto e = r.value(o, QStringLiteral("youngs_modulus_MPa"), p, true);
        const auto rho = r.value(o, QStringLiteral("density_kg_m3"), p, true);
        const auto kc = r.value(k, QStringLiteral("kc11_MPa"), kp, true);
        const auto mc = r.value(k, QStringLiteral("mc"), kp, true);
        if (m.id.isEmpty() || !e || !rho || !kc || !mc) {
            r.error(p, DataFiles::tr("material \"%1\" lacks its id, modulus, density or Kienzle constants").arg(m.id));
            continue;
        }
        m.youngsModulus_MPa = *e;
        m.density_kg_m3 = *rho;
        m.kc11_MPa = *kc;
        m.mc = *mc;
        m.poissonRatio = r.value(o, QStringLiteral("poisson_ratio"), p, false);
        m.tensileStrength_MPa = r.value(o, QStringLiteral("tensile_strength_MPa"), p, false);
        m.kf11_MPa = r.value(k, QStringLiteral("kf11_MPa"), kp, false);
        m.mf = r.value(k, QStringLiteral("mf"), kp, false);
        m.kp11_MPa = r.value(k, QStringLiteral("kp11_MPa"), kp, false);
        m.mp = r.value(k, QStringLiteral("mp"), kp, false);
        m.feedToCuttingRatio = r.value(k, QStringLiteral("feed_to_cutting_ratio"), kp, false);
        m.passiveToCuttingRatio = r.value(k, QStringLiteral("passive_to_cutting_ratio"), kp, false);
        const QJsonObject t = o.value(QStringLiteral("taylor")).toObject();
        m.taylorC_m_min = r.value(t, QStringLiteral("C_m_min"), p + QStringLiteral(".taylor"), false);
        m.taylorN = r.value(t, QStringLiteral("n"), p + QStringLiteral(".taylor"), false);
        m_materials.push_back(m);
    }
}

namespace {

std::optional<StiffnessRange> stiffnessRange(DataFileReader &r, const QJsonObject &parent, const QString &key)
{
    if (!parent.contains(key))
        return std::nullopt;
    const QJsonObject o = parent.value(key).toObject();
    const QString path = QStringLiteral("uncharacterised_supports.") + key;
    const auto compliant = r.value(o, QStringLiteral("compliant"), path, true);
    const auto stiff = r.value(o, QStringLiteral("stiff"), path, true);
    if (!compliant || !stiff)
        return std::nullopt;
    if (!(compliant->value > 0.0) || !(stiff->value >= compliant->value)) {
        r.error(path, DataFiles::tr("a stiffness range needs 0 < compliant <= stiff, not %1 and %2")
                          .arg(compliant->value)
                          .arg(stiff->value));
        return std::nullopt;
    }
    return StiffnessRange{*compliant, *stiff, o.value(QStringLiteral("valid_for")).toString()};
}

} // namespace

void DataLibrary::readMachines(const QString &path)
{
    DataFileReader r(path, "tolturn-machines", m_diagnostics, m_sources);
    const QJsonObject supports = r.root().value(QStringLiteral("uncharacterised_supports")).toObject();
    m_supports.chuckRadial = stiffnessRange(r, supports, QStringLiteral("chuck_radial_N_per_mm"));
    m_supports.tailstockRadial = stiffnessRange(r, supports, QStringLiteral("tailstock_radial_N_per_mm"));
    m_supports.centreRadial = stiffnessRange(r, supports, QStringLiteral("centre_radial_N_per_mm"));
    m_supports.notes = supports.value(QStringLiteral("notes")).toString();
    const QJsonObject reclamping = r.root().value(QStringLiteral("reclamping")).toObject();
    m_reclamping.concentricity_mm =
        r.value(reclamping, QStringLiteral("concentricity_mm"), QStringLiteral("reclamping"), false);
    m_reclamping.axialRunout_mm =
        r.value(reclamping, QStringLiteral("axial_runout_mm"), QStringLiteral("reclamping"), false);
    const QJsonArray list = r.root().value(QStringLiteral("machines")).toArray();
    for (qsizetype i = 0; i < list.size(); ++i) {
        const QJsonObject o = list.at(i).toObject();
        const QString p = QStringLiteral("machines[%1]").arg(i);
        MachineData m;
        m.id = o.value(QStringLiteral("id")).toString();
        m.name = o.value(QStringLiteral("name")).toString();
        m.notes = o.value(QStringLiteral("notes")).toString();
        m.control = o.value(QStringLiteral("control")).toString();
        const QJsonObject limits = o.value(QStringLiteral("limits")).toObject();
        for (auto it = limits.begin(); it != limits.end(); ++it) {
            if (const auto v = r.value(limits, it.key(), p + QStringLiteral(".limits"), true))
                m.limits.emplace(it.key(), *v);
        }
        m_machines.push_back(m);
    }
}

namespace {

// Boring-bar materials (holders.json "boring_bar_materials"): every entry but "notes".
std::vector<BoringBarMaterialData> readBoringBarMaterials(DataFileReader &r)
{
    std::vector<BoringBarMaterialData> materials;
    const QJsonObject table = r.root().value(QStringLiteral("boring_bar_materials")).toObject();
    for (auto it = table.begin(); it != table.end(); ++it) {
        if (!it.value().isObject())
            continue;
        const QJsonObject o = it.value().toObject();
        const QString p = QStringLiteral("boring_bar_materials.") + it.key();
        const auto e = r.value(o, QStringLiteral("E_N_per_mm2"), p, true);
        const auto nu = r.value(o, QStringLiteral("poisson_ratio"), p, true);
        const auto ratio = r.value(o, QStringLiteral("max_overhang_ratio"), p, true);
        QStringList letters;
        for (const QJsonValue v : o.value(QStringLiteral("type_letters")).toArray())
            letters << v.toString();
        if (!e || !nu || !ratio || letters.isEmpty()) {
            r.error(p, DataFiles::tr("a boring-bar material needs its type letters, modulus, Poisson's ratio and "
                                     "largest overhang ratio"));
            continue;
        }
        materials.push_back({it.key(), letters, *e, *nu, *ratio});
    }
    return materials;
}

} // namespace

void DataLibrary::readHolders(const QString &path)
{
    DataFileReader r(path, "tolturn-holders", m_diagnostics, m_sources);
    const QJsonObject styles = r.root().value(QStringLiteral("style_entering_angle_deg")).toObject();
    for (auto it = styles.begin(); it != styles.end(); ++it) {
        if (const auto v = r.value(styles, it.key(), QStringLiteral("style_entering_angle_deg"), true);
            v && it.key().size() == 1)
            m_styleAngles.emplace(it.key().at(0), *v);
    }
    const QJsonObject seat = r.root()
                                 .value(QStringLiteral("seat_angles"))
                                 .toObject()
                                 .value(QStringLiteral("negative_insert_D_system_dormer_pramet"))
                                 .toObject();
    m_negativeSeatRake =
        r.value(seat, QStringLiteral("rake_angle_orthogonal_deg"), QStringLiteral("seat_angles"), true);
    m_negativeSeatInclination =
        r.value(seat, QStringLiteral("inclination_angle_deg"), QStringLiteral("seat_angles"), true);
    const QJsonObject steel = r.root()
                                  .value(QStringLiteral("shank_materials"))
                                  .toObject()
                                  .value(QStringLiteral("steel_C45_class"))
                                  .toObject();
    m_shankModulus = r.value(steel, QStringLiteral("E_N_per_mm2"), QStringLiteral("shank_materials"), true);
    m_barMaterials = readBoringBarMaterials(r);

    const QJsonArray list = r.root().value(QStringLiteral("holders")).toArray();
    for (qsizetype i = 0; i < list.size(); ++i) {
        const QJsonObject o = list.at(i).toObject();
        const QString p = QStringLiteral("holders[%1]").arg(i);
        HolderData h;
        h.code = o.value(QStringLiteral("code")).toString();
        h.kind = o.value(QStringLiteral("kind")).toString();
        const auto angle = r.value(o, QStringLiteral("entering_angle_deg"), p, true);
        if (h.code.isEmpty() || !angle)
            continue;
        h.enteringAngle_deg = *angle;
        h.shankHeight_mm = r.value(o, QStringLiteral("shank_height_mm"), p, false);
        h.shankWidth_mm = r.value(o, QStringLiteral("shank_width_mm"), p, false);
        h.length_mm = r.value(o, QStringLiteral("tool_length_mm"), p, false);
        h.barDiameter_mm = r.value(o, QStringLiteral("bar_diameter_mm"), p, false);
        h.rake_deg = r.value(o, QStringLiteral("rake_angle_orthogonal_deg"), p, false);
        h.inclination_deg = r.value(o, QStringLiteral("inclination_angle_deg"), p, false);
        m_holders.push_back(h);
    }
}

const BoringBarMaterialData *DataLibrary::boringBarMaterial(const HolderData &bar) const
{
    if (!bar.isBoringBar() || bar.code.isEmpty())
        return nullptr;
    const QString letter = bar.code.left(1).toUpper();
    for (const BoringBarMaterialData &m : m_barMaterials) {
        if (m.typeLetters.contains(letter))
            return &m;
    }
    return nullptr;
}

const MaterialData *DataLibrary::material(const QString &id) const
{
    for (const MaterialData &m : m_materials) {
        if (m.id == id)
            return &m;
    }
    return nullptr;
}

const MachineData *DataLibrary::machine(const QString &id) const
{
    for (const MachineData &m : m_machines) {
        if (m.id == id)
            return &m;
    }
    return nullptr;
}

const HolderData *DataLibrary::holder(const QString &code) const
{
    const QString wanted = QString(code).remove(QLatin1Char(' ')).toUpper();
    for (const HolderData &h : m_holders) {
        if (QString(h.code).remove(QLatin1Char(' ')).toUpper() == wanted)
            return &h;
    }
    return nullptr;
}

std::optional<SourcedValue> DataLibrary::styleEnteringAngle(QChar style) const
{
    const auto it = m_styleAngles.find(style.toUpper());
    if (it == m_styleAngles.end())
        return std::nullopt;
    return it->second;
}

} // namespace tolturn
