// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/fe/calculix_job.h"

#include <QCoreApplication>
#include <QList>

namespace tolturn {

namespace {

struct CalculixText {
    Q_DECLARE_TR_FUNCTIONS(CalculixText)
};

QByteArray number(double value)
{
    return QByteArray::number(value, 'g', 12);
}

void writeNodes(QByteArray &deck, const TetMesh &mesh)
{
    deck += "*NODE, NSET=NALL\n";
    for (std::size_t i = 0; i < mesh.nodes.size(); ++i) {
        const Point3 &p = mesh.nodes[i];
        deck += QByteArray::number(i + 1) + ", " + number(p.x()) + ", " + number(p.y()) + ", " + number(p.z()) + '\n';
    }
}

void writeElements(QByteArray &deck, const TetMesh &mesh)
{
    deck += "*ELEMENT, TYPE=C3D10, ELSET=EALL\n";
    for (std::size_t i = 0; i < mesh.elements.size(); ++i) {
        deck += QByteArray::number(i + 1);
        for (const int n : mesh.elements[i])
            deck += ", " + QByteArray::number(n + 1);
        deck += '\n';
    }
}

// *BOUNDARY lines: node, first DOF, last DOF, for each run of held components.
void writeSupports(QByteArray &deck, const std::vector<NodeSupport> &supports)
{
    deck += "*BOUNDARY\n";
    for (const NodeSupport &s : supports) {
        const std::array<bool, 3> held{s.x, s.y, s.z};
        for (int first = 0; first < 3;) {
            if (!held[static_cast<std::size_t>(first)]) {
                ++first;
                continue;
            }
            int last = first;
            while (last < 2 && held[static_cast<std::size_t>(last) + 1])
                ++last;
            deck += QByteArray::number(s.node + 1) + ", " + QByteArray::number(first + 1) + ", " +
                    QByteArray::number(last + 1) + '\n';
            first = last + 1;
        }
    }
}

// sum u_z = 0 over the nodes: *EQUATION, the number of terms, then four terms (node, DOF,
// coefficient) to a line (CalculiX User's Manual 2.20 §7.41).
void writeAxialMean(QByteArray &deck, const std::vector<int> &nodes)
{
    if (nodes.empty())
        return;
    deck += "*EQUATION\n" + QByteArray::number(nodes.size()) + '\n';
    for (std::size_t i = 0; i < nodes.size(); ++i) {
        deck += QByteArray::number(nodes[i] + 1) + ", 3, 1.";
        deck += (i + 1) % 4 == 0 || i + 1 == nodes.size() ? "\n" : ", ";
    }
}

void writeStep(QByteArray &deck, const LoadCase &loads)
{
    deck += "*STEP\n*STATIC\n*CLOAD, OP=NEW\n";
    for (const NodalForce &f : loads) {
        for (int d = 0; d < 3; ++d) {
            if (f.force_N[d] != 0.0)
                deck += QByteArray::number(f.node + 1) + ", " + QByteArray::number(d + 1) + ", " +
                        number(f.force_N[d]) + '\n';
        }
    }
    deck += "*NODE PRINT, NSET=NALL\nU\n*END STEP\n";
}

} // namespace

QByteArray calculixDeck(const CalculixJob &job)
{
    QByteArray deck = "** TolTurn solid check (docs/solid-fe.md): N, mm, MPa\n";
    writeNodes(deck, *job.mesh);
    writeElements(deck, *job.mesh);
    deck += "*MATERIAL, NAME=WORK\n*ELASTIC\n" + number(job.youngsModulus_MPa) + ", " + number(job.poissonRatio) + '\n';
    deck += "*SOLID SECTION, ELSET=EALL, MATERIAL=WORK\n";
    writeSupports(deck, job.supports);
    writeAxialMean(deck, job.axialMeanHeld);
    for (const LoadCase &loads : job.loadCases)
        writeStep(deck, loads);
    return deck;
}

CalculixDisplacements parseCalculixDisplacements(const QByteArray &dat, std::size_t nodeCount, std::size_t caseCount)
{
    CalculixDisplacements out;
    std::vector<Point3> *current = nullptr;
    for (const QByteArray &raw : dat.split('\n')) {
        const QByteArray line = raw.simplified();
        if (line.startsWith("displacements")) {
            out.perCase.emplace_back(nodeCount, Point3::Zero());
            current = &out.perCase.back();
            continue;
        }
        if (current == nullptr || line.isEmpty())
            continue;
        const QList<QByteArray> fields = line.split(' ');
        bool ok = fields.size() == 4;
        const long long node = ok ? fields[0].toLongLong(&ok) : 0;
        if (!ok || node < 1 || static_cast<std::size_t>(node) > nodeCount) {
            current = nullptr; // another block
            continue;
        }
        Point3 u;
        for (int d = 0; d < 3 && ok; ++d)
            u[d] = fields[d + 1].toDouble(&ok);
        if (ok)
            (*current)[static_cast<std::size_t>(node - 1)] = u;
    }
    if (out.perCase.size() != caseCount)
        out.error = CalculixText::tr("CalculiX wrote displacements for %1 of the %2 load cases")
                        .arg(out.perCase.size())
                        .arg(caseCount);
    return out;
}

QString calculixErrorLine(const QByteArray &output)
{
    QString last;
    for (const QByteArray &raw : output.split('\n')) {
        QString line = QString::fromUtf8(raw).trimmed();
        if (line.contains(QLatin1String("*ERROR"), Qt::CaseInsensitive))
            return line;
        if (!line.isEmpty())
            last = line;
    }
    return last;
}

} // namespace tolturn
