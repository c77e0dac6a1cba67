#pragma once
// formats.md's rules on one pose of a chain, in any scalar type (pose
// points as doubles or as automatic-differentiation scalars): segments
// apart from each other and from the EE (rule 4), clear of the obstacles
// (rule 3) but for the mount and the tool. Distances are exact in value;
// their derivatives are those of the distance between the nearest points,
// held at their parameters (by the envelope theorem, the derivative of a
// minimum). The refinement and the initial guesses of every arm family
// measure a pose with these.
#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include <modsynth/geometry/distance3.h>
#include <modsynth/geometry/obstacle3.h>
#include <modsynth/kinematics/arm_model.h>

namespace modsynth::kinematics {

namespace pose_detail {

inline double constant(double v, double) { return v; }
inline AD constant(double v, const AD&) { return AD(v); }

template <class T>
Point3<T> constant_point(const geometry::Vec3& v, const T& like) {
    return Point3<T>(constant(v.x(), like), constant(v.y(), like), constant(v.z(), like));
}

template <class T>
geometry::Vec3 value(const Point3<T>& p) {
    return {value_of(p.x()), value_of(p.y()), value_of(p.z())};
}

template <class T>
T safe_norm(const Point3<T>& v) {
    using std::sqrt;
    const T sq = v.x() * v.x() + v.y() * v.y() + v.z() * v.z();
    return value_of(sq) > 1e-24 ? T(sqrt(sq)) : T(sqrt(sq + T(1e-24)));
}

template <class T>
Point3<T> lerp(const Point3<T>& a, const Point3<T>& b, const T& t) {
    return a + (b - a) * t;
}

/// Parameters (s, t) of a nearest pair of points of segments ab and cd.
inline std::pair<double, double> nearest_parameters(const geometry::Vec3& a,
                                                    const geometry::Vec3& b,
                                                    const geometry::Vec3& c,
                                                    const geometry::Vec3& d) {
    std::pair<double, double> best{0.0, geometry::segment_parameter(a, c, d)};
    double best_d = (a - (c + best.second * (d - c))).norm();
    auto consider = [&](double s, double t) {
        const double v = (a + s * (b - a) - (c + t * (d - c))).norm();
        if (v < best_d) best_d = v, best = {s, t};
    };
    consider(1.0, geometry::segment_parameter(b, c, d));
    consider(geometry::segment_parameter(c, a, b), 0.0);
    consider(geometry::segment_parameter(d, a, b), 1.0);
    const geometry::Vec3 d1 = b - a, d2 = d - c, r = a - c;
    const double aa = d1.squaredNorm(), ee = d2.squaredNorm(), ab = d1.dot(d2);
    const double denom = aa * ee - ab * ab;
    if (aa > 0.0 && ee > 0.0 && denom > 1e-14 * aa * ee) {
        const double cc = d1.dot(r), ff = d2.dot(r);
        const double s = (ab * ff - cc * ee) / denom;
        const double t = (aa * ff - ab * cc) / denom;
        if (s > 0.0 && s < 1.0 && t > 0.0 && t < 1.0) consider(s, t);
    }
    return best;
}

}  // namespace pose_detail

/// Distance between segments pq and rs.
template <class T>
T segment_distance(const Point3<T>& p, const Point3<T>& q, const Point3<T>& r, const Point3<T>& s) {
    using namespace pose_detail;
    const auto [u, v] = nearest_parameters(value(p), value(q), value(r), value(s));
    return safe_norm<T>(lerp<T>(p, q, constant(u, p.x())) - lerp<T>(r, s, constant(v, p.x())));
}

/// Distance from x to segment pq.
template <class T>
T point_segment_distance(const Point3<T>& x, const Point3<T>& p, const Point3<T>& q) {
    using namespace pose_detail;
    const double t = geometry::segment_parameter(value(x), value(p), value(q));
    return safe_norm<T>(x - lerp<T>(p, q, constant(t, p.x())));
}

/// formats.md's clearance of segment pq to an obstacle: the distance beyond
/// its surface (geometry::segment_gap).
template <class T>
T obstacle_gap(const Point3<T>& p, const Point3<T>& q, const geometry::Obstacle3& o) {
    using namespace pose_detail;
    const T& like = p.x();
    if (const auto* s = std::get_if<geometry::Sphere>(&o))
        return point_segment_distance<T>(constant_point(s->center, like), p, q) -
               constant(s->radius, like);
    if (const auto* c = std::get_if<geometry::Capsule>(&o))
        return segment_distance<T>(p, q, constant_point(c->a, like), constant_point(c->b, like)) -
               constant(c->radius, like);
    const auto& box = std::get<geometry::Box3>(o);
    double t = 0.0;
    geometry::segment_box(value(p), value(q), box, &t);
    const Point3<T> x = lerp<T>(p, q, constant(t, like));
    Point3<T> off = x;
    for (int i = 0; i < 3; ++i) {
        const double v = value_of(x[i]);
        off[i] = v < box.min[i]   ? T(x[i] - constant(box.min[i], like))
                 : v > box.max[i] ? T(x[i] - constant(box.max[i], like))
                                  : constant(0.0, like);
    }
    return safe_norm<T>(off);
}

/// A stretch of segment `segment` of a pose, from fraction `from` to `to`.
template <class T>
struct PosePart {
    int segment = 0;
    T from, to;
};

/// What must keep clear of obstacles (formats.md rule 3, as
/// kinematics::clearance_parts cuts it): every segment but the chain's first
/// `mount` m from the base and its last `tool` m. Which segments the cuts
/// fall in is decided on the values; the fractions carry the derivatives.
template <class T>
std::vector<PosePart<T>> pose_clearance_parts(const ArmPose<T>& pose, double mount, double tool) {
    using pose_detail::safe_norm;
    const std::size_t n = pose.points.empty() ? 0 : pose.points.size() - 1;
    const T zero = pose_detail::constant(0.0, pose.points.front().x());
    const T one = pose_detail::constant(1.0, pose.points.front().x());
    std::vector<T> lengths;
    for (std::size_t k = 0; k < n; ++k)
        lengths.push_back(safe_norm<T>(Point3<T>(pose.points[k + 1] - pose.points[k])));
    std::vector<T> from(n, zero), to(n, one);
    std::vector<bool> gone(n, false);
    T left = pose_detail::constant(mount, zero);
    for (std::size_t k = 0; k < n && left > zero; ++k) {
        if (!(left < lengths[k])) {
            gone[k] = true;
            left = left - lengths[k];
        } else {
            from[k] = left / lengths[k];
            left = zero;
        }
    }
    left = pose_detail::constant(tool, zero);
    for (std::size_t k = n; k-- > 0 && left > zero;) {
        if (!(left < lengths[k])) {
            gone[k] = true;
            left = left - lengths[k];
        } else {
            to[k] = one - left / lengths[k];
            left = zero;
        }
    }
    std::vector<PosePart<T>> out;
    for (std::size_t k = 0; k < n; ++k)
        if (!gone[k] && from[k] < to[k]) out.push_back({static_cast<int>(k), from[k], to[k]});
    return out;
}

/// One of formats.md's rules on a pose, as a distance that must stay at
/// least its bound.
struct PoseRule {
    enum class Kind {
        SegmentsApart,  ///< segments a and b (not consecutive) at least D apart
        EeApart,        ///< the EE at least D from segment a (not the last)
        Clearance,      ///< segment a's clearance part D/2 beyond obstacle b
    };
    Kind kind = Kind::SegmentsApart;
    int a = -1;
    int b = -1;
};

/// The self-collision rules of a chain of `segments` segments.
inline std::vector<PoseRule> self_rules(int segments) {
    std::vector<PoseRule> out;
    for (int k = 0; k < segments; ++k) {
        for (int l = k + 2; l < segments; ++l) out.push_back({PoseRule::Kind::SegmentsApart, k, l});
        if (k + 1 < segments) out.push_back({PoseRule::Kind::EeApart, k});
    }
    return out;
}

/// A rule's distance in a pose (the bound not subtracted); infinite for a
/// clearance part that vanished (a mount or a tool longer than its segment:
/// nothing is left to keep clear).
template <class T>
T rule_value(const PoseRule& rule, const ArmPose<T>& pose, const std::vector<PosePart<T>>& parts,
             const std::vector<geometry::Obstacle3>& obstacles) {
    const auto& pts = pose.points;
    const auto at = [&](int k) { return static_cast<std::size_t>(k); };
    switch (rule.kind) {
        case PoseRule::Kind::SegmentsApart:
            return segment_distance<T>(pts[at(rule.a)], pts[at(rule.a + 1)], pts[at(rule.b)],
                                       pts[at(rule.b + 1)]);
        case PoseRule::Kind::EeApart:
            return point_segment_distance<T>(pts.back(), pts[at(rule.a)], pts[at(rule.a + 1)]);
        case PoseRule::Kind::Clearance: {
            const auto part = std::find_if(parts.begin(), parts.end(), [&](const PosePart<T>& x) {
                return x.segment == rule.a;
            });
            if (part == parts.end())
                return pose_detail::constant(std::numeric_limits<double>::infinity(), pts[0].x());
            const Point3<T>& p = pts[at(part->segment)];
            const Point3<T>& q = pts[at(part->segment + 1)];
            return obstacle_gap<T>(pose_detail::lerp<T>(p, q, part->from),
                                   pose_detail::lerp<T>(p, q, part->to), obstacles[at(rule.b)]);
        }
    }
    return pose_detail::constant(0.0, pts[0].x());
}

}  // namespace modsynth::kinematics
