#pragma once
// The pose of a yaw-pitch arm (kinematics/yaw_pitch_ik.h) with its EE at a
// target, as points rather than angles, for any scalar type: the same
// closed form gives the search's scores in doubles and the refinement's
// constraints with their derivatives in automatic-differentiation scalars
// (Eigen's AutoDiffScalar), as functions of the base, the column, the link
// lengths and the hand pitches. The elbow is placed by intersecting two
// circles in the arm's vertical plane, which avoids the angles' branch cuts.
#include <cmath>
#include <vector>

#include <Eigen/Core>

#include <modsynth/kinematics/autodiff.h>
#include <modsynth/kinematics/yaw_pitch_ik.h>

namespace modsynth::kinematics {

template <class T>
struct YawPitchPose {
    /// o_0 .. o_n: the base, the shoulder (the top of the column), the
    /// elbow, the wrist (the end of link 3), the hand links' ends, the EE.
    std::vector<Point3<T>> points;
    /// cos q_3: within (-1, 1) when the wrist point is reachable, +-1 at the
    /// stretch and the fold; the pose is meaningless outside.
    T elbow_cos;
    /// m: how far the target lies from the column's axis (the shoulder
    /// singularity is at 0, where the yaw is undefined).
    T axis_distance;
};

/// The design's variables as the pose needs them, in any scalar type.
template <class T>
struct YawPitchShape {
    Point3<T> base;
    T column;              ///< d_1
    std::vector<T> links;  ///< a_2 .. a_n
    int column_twist = 1;  ///< sign of alpha_1
};

namespace detail {
template <class T>
T safe_sqrt(const T& v, double floor) {
    using std::sqrt;
    return v > T(floor) ? T(sqrt(v)) : T(sqrt(T(floor)));
}
}  // namespace detail

/// The pose on `branch` with the EE at `target` and the hand links (links
/// 4..n) at the absolute pitches `hand_pitches`, as yaw_pitch_ik computes
/// it. Near the singularities (see YawPitchPose) the square roots are
/// floored, so the points stay finite for any design.
template <class T>
YawPitchPose<T> yaw_pitch_pose(const YawPitchShape<T>& shape, const Point3<T>& target,
                               IkBranch branch, const std::vector<T>& hand_pitches) {
    using std::cos;
    using std::sin;
    constexpr double kFloor = 1e-18;
    YawPitchPose<T> pose;
    const Point3<T> shoulder = shape.base + Point3<T>(T(0), T(0), shape.column);
    const Point3<T> v = target - shoulder;
    const T horizontal = detail::safe_sqrt(T(v.x() * v.x() + v.y() * v.y()), kFloor);
    pose.axis_distance = horizontal;
    // The arm's plane: x along the yaw direction (towards the target for the
    // front shoulder, away from it for the back one), y along sigma z.
    const double s = branch.shoulder > 0 ? 1.0 : -1.0;
    const double sigma = shape.column_twist > 0 ? 1.0 : -1.0;
    const Point3<T> x_axis(T(s * v.x() / horizontal), T(s * v.y() / horizontal), T(0));
    const Point3<T> y_axis(T(0), T(0), T(sigma));
    auto world = [&](const T& px, const T& py) -> Point3<T> {
        return shoulder + x_axis * px + y_axis * py;
    };
    T x = s * horizontal;
    T y = sigma * v.z();
    std::vector<T> hand_x, hand_y;  // each hand link's offset in the plane
    for (std::size_t i = 0; i < hand_pitches.size(); ++i) {
        const T& a = shape.links[2 + i];
        hand_x.push_back(a * cos(hand_pitches[i]));
        hand_y.push_back(a * sin(hand_pitches[i]));
        x -= hand_x.back();
        y -= hand_y.back();
    }
    const T& a2 = shape.links[0];
    const T& a3 = shape.links[1];
    const T l2 = x * x + y * y;
    pose.elbow_cos = (l2 - a2 * a2 - a3 * a3) / (T(2) * a2 * a3);
    const T l = detail::safe_sqrt(l2, kFloor);
    const T along = (a2 * a2 - a3 * a3 + l2) / (T(2) * l);
    const T across = detail::safe_sqrt(T(a2 * a2 - along * along), kFloor);
    // q_3 > 0 (elbow +1) puts the elbow to the right of the line from the
    // shoulder to the wrist.
    const double e = branch.elbow >= 0 ? 1.0 : -1.0;
    const T ex = (along * x + e * across * y) / l;
    const T ey = (along * y - e * across * x) / l;
    pose.points.push_back(shape.base);
    pose.points.push_back(shoulder);
    pose.points.push_back(world(ex, ey));
    T wx = x, wy = y;
    pose.points.push_back(world(wx, wy));
    for (std::size_t i = 0; i < hand_x.size(); ++i) {
        wx += hand_x[i];
        wy += hand_y[i];
        pose.points.push_back(world(wx, wy));
    }
    return pose;
}

/// The chain's segments in a pose, as kinematics::segment_layout orders
/// them: the column (when d_1 is not zero), then each pitch link.
template <class T>
std::vector<std::pair<Point3<T>, Point3<T>>> pose_segments(const YawPitchPose<T>& pose,
                                                           bool has_column) {
    std::vector<std::pair<Point3<T>, Point3<T>>> out;
    for (std::size_t k = has_column ? 0 : 1; k + 1 < pose.points.size(); ++k)
        out.push_back({pose.points[k], pose.points[k + 1]});
    return out;
}

/// A stretch of segment `segment` of pose_segments, from fraction `from` to
/// `to` of its length.
template <class T>
struct PosePart {
    int segment = 0;
    T from, to;
};

/// What must keep clear of obstacles (formats.md rule 3, as
/// kinematics::clearance_parts cuts it): every segment but the chain's first
/// `mount` m from the base and its last `tool` m, in a pose. Which segments
/// the cuts fall in is decided on the values; the fractions carry the
/// derivatives.
template <class T>
std::vector<PosePart<T>> pose_clearance_parts(
    const std::vector<std::pair<Point3<T>, Point3<T>>>& segments, double mount, double tool) {
    using std::sqrt;
    const std::size_t n = segments.size();
    std::vector<T> lengths;
    for (const auto& [p, q] : segments)
        lengths.push_back(detail::safe_sqrt(T((q - p).squaredNorm()), 1e-24));
    std::vector<T> from(n, T(0.0)), to(n, T(1.0));
    std::vector<bool> gone(n, false);
    T left = T(mount);
    for (std::size_t k = 0; k < n && left > T(0.0); ++k) {
        if (!(left < lengths[k])) {
            gone[k] = true;
            left = left - lengths[k];
        } else {
            from[k] = left / lengths[k];
            left = T(0.0);
        }
    }
    left = T(tool);
    for (std::size_t k = n; k-- > 0 && left > T(0.0);) {
        if (!(left < lengths[k])) {
            gone[k] = true;
            left = left - lengths[k];
        } else {
            to[k] = T(1.0) - left / lengths[k];
            left = T(0.0);
        }
    }
    std::vector<PosePart<T>> out;
    for (std::size_t k = 0; k < n; ++k)
        if (!gone[k] && from[k] < to[k]) out.push_back({static_cast<int>(k), from[k], to[k]});
    return out;
}

}  // namespace modsynth::kinematics
