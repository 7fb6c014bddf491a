// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// The feed drive of a CNC axis as a second-order lag between the commanded and the actual feed
// rate (Čuš & Župerl, "Control strategy for assuring constant surface finish by controlling
// cutting forces", seed 004, eq. 1):
//   F(s) = f_a(s) / f_c(s) = 1 / (a s² + b s + 1),  a = 0.001024 s², b = 0.064 s (Heller bea 01).
// The printed polynomial is critically damped: a = T², b = 2 T with T = 0.032 s, so the natural
// frequency is 1/T = 31.25 rad/s and the step response 1 − (1 + ω t) e^(−ω t).

#include <Eigen/Core>

namespace tolturn {

struct FeedDriveModel {
    double a_s2 = 0.001024; // s² coefficient [s²] (004 eq. 1)
    double b_s = 0.064;     // s coefficient [s] (004 eq. 1)

    [[nodiscard]] double naturalFrequency_rad_s() const;
    [[nodiscard]] double dampingRatio() const;
};

// The drive sampled by a controller that holds its command over each period (zero-order hold):
// the exact discretisation x[k+1] = Φ x[k] + Γ u[k] of the state (f_a, df_a/dt), Φ = e^(A·dt).
// The feed is whatever unit the command is in (mm/min, or an override ratio: the drive is linear).
class FeedDrive {
public:
    FeedDrive(const FeedDriveModel &model, double period_s, double initialFeed);

    // Holds `command` for one period and returns the actual feed at its end.
    double step(double command);

    [[nodiscard]] double actual() const { return m_state(0); }

    [[nodiscard]] double period_s() const { return m_period_s; }

private:
    double m_period_s;
    Eigen::Matrix2d m_phi;
    Eigen::Vector2d m_gamma;
    Eigen::Vector2d m_state;
};

// The closed form of a critically damped second-order lag's unit step response:
// 1 − (1 + ω t) e^(−ω t).
[[nodiscard]] double criticallyDampedStepResponse(double omega_rad_s, double t_s);

} // namespace tolturn
