#include <modsynth/kinematics/yaw_pitch_ik.h>

#include <cmath>
#include <stdexcept>

#include <modsynth/geometry/vec.h>

namespace modsynth::kinematics {

using geometry::kPi;
using geometry::Vec3;

namespace {

constexpr double kPatternTolerance = 1e-9;

/// The angle in (-pi, pi].
double wrapped(double a) {
    a = std::remainder(a, geometry::kTau);
    return a <= -kPi ? a + geometry::kTau : a;
}

}  // namespace

std::optional<YawPitchArm> as_yaw_pitch(const DhChain& chain) {
    const int n = chain.dof();
    if (n < 3 || n > 6) return std::nullopt;
    const DhRow& first = chain.rows[0];
    if (std::abs(first.a) > kPatternTolerance) return std::nullopt;
    YawPitchArm arm;
    if (std::abs(first.alpha - kPi / 2) <= kPatternTolerance) {
        arm.column_twist = 1;
    } else if (std::abs(first.alpha + kPi / 2) <= kPatternTolerance) {
        arm.column_twist = -1;
    } else {
        return std::nullopt;
    }
    arm.base = chain.base;
    arm.column = first.d;
    for (int k = 1; k < n; ++k) {
        const DhRow& r = chain.rows[static_cast<std::size_t>(k)];
        if (std::abs(r.alpha) > kPatternTolerance || std::abs(r.d) > kPatternTolerance ||
            !(r.a > kPatternTolerance))
            return std::nullopt;
        arm.links.push_back(r.a);
    }
    return arm;
}

DhChain to_chain(const YawPitchArm& arm, double link_diameter) {
    DhChain c;
    c.base = arm.base;
    c.link_diameter = link_diameter;
    c.rows.push_back({0.0, arm.column_twist * kPi / 2, arm.column});
    for (double a : arm.links) c.rows.push_back({a, 0.0, 0.0});
    return c;
}

std::optional<std::vector<double>> yaw_pitch_ik(const YawPitchArm& arm, const Vec3& target,
                                                IkBranch branch,
                                                const std::vector<double>& hand_pitches,
                                                const IkOptions& options) {
    const int n = arm.dof();
    if (static_cast<int>(hand_pitches.size()) != n - 3)
        throw std::invalid_argument("yaw_pitch_ik: " + std::to_string(n) + " joints need " +
                                    std::to_string(n - 3) + " hand pitches, got " +
                                    std::to_string(hand_pitches.size()));
    // Every link lies in the vertical plane through the column at yaw q_1:
    // the EE is shoulder + X x_1 + sigma Y z with x_1 = (cos q1, sin q1, 0),
    // X = sum a_k cos phi_k, Y = sum a_k sin phi_k, phi_k = q_2 + ... + q_k.
    const Vec3 v = target - arm.shoulder();
    const double horizontal = std::hypot(v.x(), v.y());
    if (!(horizontal >= options.min_axis_distance)) return std::nullopt;
    const double azimuth = std::atan2(v.y(), v.x());
    const double q1 = branch.shoulder > 0 ? azimuth : azimuth + kPi;
    double x = branch.shoulder > 0 ? horizontal : -horizontal;
    double y = arm.column_twist * v.z();
    // The hand links hang from the wrist at their given pitches.
    for (std::size_t i = 0; i < hand_pitches.size(); ++i) {
        const double a = arm.links[2 + i];
        x -= a * std::cos(hand_pitches[i]);
        y -= a * std::sin(hand_pitches[i]);
    }
    const double a2 = arm.links[0], a3 = arm.links[1];
    const double c = (x * x + y * y - a2 * a2 - a3 * a3) / (2.0 * a2 * a3);
    if (!(std::abs(c) <= options.max_elbow_cos)) return std::nullopt;
    const double q3 = (branch.elbow >= 0 ? 1.0 : -1.0) * std::acos(c);
    const double q2 = std::atan2(y, x) - std::atan2(a3 * std::sin(q3), a2 + a3 * std::cos(q3));
    std::vector<double> q{wrapped(q1), wrapped(q2), q3};
    double phi = q[1] + q3;
    for (double pitch : hand_pitches) {
        q.push_back(pitch - phi);
        phi = pitch;
    }
    // The closed form is exact; a pose rounding has bent is no answer.
    const Vec3 reached = end_effector(to_chain(arm, 0.0), q);
    const double scale = 1.0 + std::abs(arm.column) + a2 + a3 + (target - arm.base).norm();
    if (!((reached - target).norm() <= 1e-9 * scale)) return std::nullopt;
    return q;
}

}  // namespace modsynth::kinematics
