// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/project/project.h"

namespace tolturn {

bool isSizeTolerance(ToleranceType type)
{
    return type == ToleranceType::Length || type == ToleranceType::Diameter;
}

bool needsDatum(ToleranceType type)
{
    switch (type) {
    case ToleranceType::Parallelism:
    case ToleranceType::Perpendicularity:
    case ToleranceType::Coaxiality:
    case ToleranceType::CircularRadialRunout:
    case ToleranceType::CircularAxialRunout:
    case ToleranceType::TotalRadialRunout:
    case ToleranceType::TotalAxialRunout:
        return true;
    case ToleranceType::Length:
    case ToleranceType::Diameter:
    case ToleranceType::Flatness:
    case ToleranceType::Cylindricity:
    case ToleranceType::Profile:
        return false;
    }
    return false;
}

} // namespace tolturn
