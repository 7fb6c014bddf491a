// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

class QThreadPool;

namespace tolturn {

// The threads of the desktop program's long work (optimisation, store listings, learning): not
// Qt's global pool, which the raster paint engine draws with, so that long work never holds up the
// window's painting (docs/benchmarks.md, "Measurement history"). Two threads, as the machine the
// program is sized for has two cores. Needs a QCoreApplication; lives as long as it does.
[[nodiscard]] QThreadPool *workerThreads();

} // namespace tolturn
