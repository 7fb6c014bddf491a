// SPDX-License-Identifier: GPL-3.0-or-later
// Timing helper shared by the benchmarks.
#pragma once

#include <algorithm>
#include <chrono>
#include <vector>

namespace tolturn::bench {

// The median wall-clock time of `repetitions` runs of `run`, in milliseconds.
template <typename F>
double medianMilliseconds(int repetitions, F &&run)
{
    using Clock = std::chrono::steady_clock;
    std::vector<double> times;
    for (int i = 0; i < repetitions; ++i) {
        const auto t0 = Clock::now();
        run();
        times.push_back(std::chrono::duration<double, std::milli>(Clock::now() - t0).count());
    }
    std::sort(times.begin(), times.end());
    return times[times.size() / 2];
}

} // namespace tolturn::bench
