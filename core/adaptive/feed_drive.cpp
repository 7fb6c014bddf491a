// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/adaptive/feed_drive.h"

#include <cmath>
#include <unsupported/Eigen/MatrixFunctions>

namespace tolturn {

double FeedDriveModel::naturalFrequency_rad_s() const
{
    return 1.0 / std::sqrt(a_s2);
}

double FeedDriveModel::dampingRatio() const
{
    // a s² + b s + 1 = (s² + 2 ζ ω s + ω²) / ω²  =>  ζ = b ω / 2
    return 0.5 * b_s * naturalFrequency_rad_s();
}

FeedDrive::FeedDrive(const FeedDriveModel &model, double period_s, double initialFeed)
    : m_period_s(period_s)
    , m_state(initialFeed, 0.0)
{
    // a y'' + b y' + y = u  =>  x' = A x + B u with x = (y, y')
    Eigen::Matrix2d a;
    a << 0.0, 1.0, -1.0 / model.a_s2, -model.b_s / model.a_s2;
    const Eigen::Vector2d b(0.0, 1.0 / model.a_s2);
    // Van Loan: exp([[A, B], [0, 0]] dt) = [[Φ, Γ], [0, 1]] gives Γ = ∫ e^(A s) ds B without A⁻¹.
    Eigen::Matrix3d m = Eigen::Matrix3d::Zero();
    m.topLeftCorner<2, 2>() = a * period_s;
    m.topRightCorner<2, 1>() = b * period_s;
    const Eigen::Matrix3d e = m.exp();
    m_phi = e.topLeftCorner<2, 2>();
    m_gamma = e.topRightCorner<2, 1>();
}

double FeedDrive::step(double command)
{
    m_state = m_phi * m_state + m_gamma * command;
    return m_state(0);
}

double criticallyDampedStepResponse(double omega_rad_s, double t_s)
{
    const double wt = omega_rad_s * t_s;
    return 1.0 - (1.0 + wt) * std::exp(-wt);
}

} // namespace tolturn
