// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/common/library_info.h"

#include "core/common/version.h"

#include <Eigen/Core>
#include <QtGlobal>
#include <Standard_Version.hxx>
#include <nlopt.h>

#include <pagmo/config.hpp>

namespace tolturn {

QString tolturnVersion()
{
    return QStringLiteral(TOLTURN_VERSION_STRING);
}

std::vector<LibraryInfo> coreLibraries()
{
    int nloptMajor = 0;
    int nloptMinor = 0;
    int nloptBugfix = 0;
    nlopt_version(&nloptMajor, &nloptMinor, &nloptBugfix);

    return {
        {QStringLiteral("Qt"), QString::fromLatin1(qVersion()), QStringLiteral("LGPL-3.0-only / GPL-2.0-or-later")},
        {QStringLiteral("Open CASCADE Technology"), QStringLiteral(OCC_VERSION_COMPLETE),
         QStringLiteral("LGPL-2.1-only with the Open CASCADE exception")},
        {QStringLiteral("NLopt"), QStringLiteral("%1.%2.%3").arg(nloptMajor).arg(nloptMinor).arg(nloptBugfix),
         QStringLiteral("LGPL-2.1-or-later (parts MIT)")},
        {QStringLiteral("pagmo2"), QStringLiteral(PAGMO_VERSION),
         QStringLiteral("GPL-3.0-or-later or LGPL-3.0-or-later (Debian's copyright file)")},
        {QStringLiteral("Eigen"),
         QStringLiteral("%1.%2.%3").arg(EIGEN_WORLD_VERSION).arg(EIGEN_MAJOR_VERSION).arg(EIGEN_MINOR_VERSION),
         QStringLiteral("MPL-2.0")},
    };
}

} // namespace tolturn
