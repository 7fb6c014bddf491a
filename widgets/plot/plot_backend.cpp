// SPDX-License-Identifier: GPL-3.0-or-later
#include "widgets/plot/plot_backend.h"

#include <qcustomplot.h>

namespace tolturn {

LibraryInfo plotBackendInfo()
{
    return {QStringLiteral("QCustomPlot"), QStringLiteral(QCUSTOMPLOT_VERSION_STR), QStringLiteral("GPL-3.0-or-later")};
}

} // namespace tolturn
