// SPDX-License-Identifier: GPL-3.0-or-later
// libFuzzer target: the project reader (parse, bounds, validation) and its round trip. A document
// that reads as a project must write and read back as the same project.
#include "core/io/project_json.h"

#include <QByteArray>

#include <cstddef>
#include <cstdint>
#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    const QByteArray json(reinterpret_cast<const char *>(data), static_cast<qsizetype>(size));
    const tolturn::ProjectParseResult first = tolturn::parseProjectJson(json);
    if (first.project) {
        const tolturn::ProjectParseResult again =
            tolturn::parseProjectJson(tolturn::serializeProjectJson(*first.project));
        if (!again.project || !(*again.project == *first.project))
            std::abort(); // a project that does not survive its own round trip
    }
    return 0;
}
