// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/project/project_defaults.h"

#include <algorithm>

namespace tolturn {

Project projectForPart(PartProfile part)
{
    Project p;
    p.clamping = {ClampingMethod::Chuck, std::min(kDefaultClampedLength_mm, part.length_mm() / 3.0)};
    p.part = std::move(part);
    p.materialId = QLatin1String(kDefaultMaterialId);
    p.machineId = QLatin1String(kDefaultMachineId);
    p.tool.insertCode = QStringLiteral("CNMG 120408");
    p.tool.holderCode = QStringLiteral("PCLNR 2525M12");
    p.passes = {{PassKind::Finishing, 200.0, 0.2, 0.5}};
    return p;
}

} // namespace tolturn
