#include <modsynth/kinematics/kinematics.h>

#include <algorithm>
#include <cassert>
#include <cmath>

namespace modsynth::kinematics {

namespace {

// Slack on the annulus: targets computed from the arm itself (FK of a
// straight or folded pose) land a few ulps off the boundary.
constexpr double kReachTol = 1e-12;
// Below this |sin q2| the arm counts as straight or folded.
constexpr double kStraight = 1e-12;

}  // namespace

std::vector<Vec2> forward(const Vec2& base, std::span<const double> lengths,
                          std::span<const double> q) {
    assert(lengths.size() == q.size());
    std::vector<Vec2> joints;
    joints.reserve(lengths.size() + 1);
    joints.push_back(base);
    double phi = 0.0;
    for (std::size_t k = 0; k < lengths.size(); ++k) {
        phi += q[k];
        joints.push_back(joints.back() + lengths[k] * geometry::unit(phi));
    }
    return joints;
}

std::vector<double> absolute_angles(std::span<const double> q) {
    std::vector<double> phi(q.size());
    double sum = 0.0;
    for (std::size_t k = 0; k < q.size(); ++k) phi[k] = sum += q[k];
    return phi;
}

int elbow_sign(double q2) {
    const double s = std::sin(q2);
    if (std::abs(s) < kStraight) return 0;
    return s > 0.0 ? 1 : -1;
}

std::optional<TwoLinkAngles> inverse_two_link(const Vec2& origin, double r1, double r2,
                                              const Vec2& target, int elbow) {
    const Vec2 v = target - origin;
    const double d = v.norm();
    if (d > r1 + r2 + kReachTol || d < std::abs(r1 - r2) - kReachTol) return std::nullopt;
    const double denominator = 2.0 * r1 * r2;
    // Clamping puts near-boundary targets onto the boundary (straight or
    // folded arm); a zero-length link leaves q2 free, take it straight.
    const double cos_q2 =
        denominator > 0.0 ? std::clamp((d * d - r1 * r1 - r2 * r2) / denominator, -1.0, 1.0) : 1.0;
    const double q2 = (elbow < 0 ? -1.0 : 1.0) * std::acos(cos_q2);
    const double phi1 =
        std::atan2(v.y(), v.x()) - std::atan2(r2 * std::sin(q2), r1 + r2 * std::cos(q2));
    return TwoLinkAngles{std::remainder(phi1, geometry::kTau), q2};
}

Vec2 elbow_towards(const Vec2& origin, double r1, double r2, const Vec2& target, int elbow) {
    if (auto ik = inverse_two_link(origin, r1, r2, target, elbow))
        return origin + r1 * geometry::unit(ik->phi1);
    const Vec2 d = target - origin;
    const Vec2 dir = d.norm() > 1e-12 ? Vec2(d.normalized()) : Vec2(1.0, 0.0);
    return origin + r1 * (0.8 * dir - 0.6 * elbow * geometry::perp(dir)).normalized();
}

double unwrap_near(double angle, double reference) {
    // remainder is exact, so only the final addition rounds.
    return reference + std::remainder(angle - reference, geometry::kTau);
}

}  // namespace modsynth::kinematics
