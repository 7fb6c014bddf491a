// SPDX-License-Identifier: GPL-3.0-or-later
// libFuzzer target: STEP and IGES import through OpenCascade, as a user's file reaches it. The
// input is written to a temporary file (OpenCascade reads files): an IGES file when it carries
// IGES's Start section letter in column 73 of its first line, STEP otherwise.
#include "core/cad/step_import.h"

#include <QByteArray>
#include <QFile>
#include <QTemporaryDir>

#include <cstddef>
#include <cstdint>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    static const QTemporaryDir dir;
    const QByteArray bytes(reinterpret_cast<const char *>(data), static_cast<qsizetype>(size));
    const qsizetype firstLine = bytes.indexOf('\n');
    const bool iges = firstLine > 72 && bytes.at(72) == 'S';
    const QString path = dir.filePath(iges ? QStringLiteral("input.igs") : QStringLiteral("input.step"));
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly | QIODevice::Truncate) || file.write(bytes) != bytes.size())
        return 0;
    file.close();
    (void)tolturn::importCadFile(path);
    return 0;
}
