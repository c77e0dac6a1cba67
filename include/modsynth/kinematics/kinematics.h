#pragma once
// Planar serial-chain kinematics with the conventions of formats.md:
// s_1 = base, s_{k+1} = s_k + r_k u(q_1 + ... + q_k); the EE is s_{n+1}.
#include <optional>
#include <span>
#include <vector>

#include <modsynth/geometry/vec.h>

namespace modsynth::kinematics {

using geometry::Vec2;

/// Joint positions s_1 .. s_{n+1} (the last one is the end-effector).
std::vector<Vec2> forward(const Vec2& base, std::span<const double> lengths,
                          std::span<const double> q);

/// Absolute link angles phi_k = q_1 + ... + q_k.
std::vector<double> absolute_angles(std::span<const double> q);

/// Elbow sign of a 2-link arm: the sign of c = cross(s_2 - s_1, s_3 - s_1)
/// (paper eq. 5, errata), which equals sign(sin q_2). +1 puts the EE to the
/// left of the first link, -1 to the right. 0 when the arm is straight or folded.
int elbow_sign(double q2);

/// Two-link inverse kinematics: the absolute angle of the first link and the
/// relative elbow angle q2 that put the end of link 2 at target, with
/// sign(sin q2) == elbow (elbow is +1 or -1). std::nullopt when the target is
/// outside the closed annulus |r1 - r2| <= |target - origin| <= r1 + r2
/// (targets within 1e-12 of the boundary are clamped onto it).
struct TwoLinkAngles {
    double phi1 = 0.0;  ///< absolute angle of the first link
    double q2 = 0.0;    ///< elbow angle relative to the first link, in [-pi, pi]
};
std::optional<TwoLinkAngles> inverse_two_link(const Vec2& origin, double r1, double r2,
                                              const Vec2& target, int elbow);

/// Where the elbow of a two-link arm hinged at origin goes to put its end at
/// target on the given branch; when target is out of reach, a pose bent to
/// that side and pointing towards it (a starting point for an optimiser).
Vec2 elbow_towards(const Vec2& origin, double r1, double r2, const Vec2& target, int elbow);

/// angle + 2*pi*k nearest to reference: keeps sampled joint angles continuous.
double unwrap_near(double angle, double reference);

}  // namespace modsynth::kinematics
