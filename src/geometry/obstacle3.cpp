#include <modsynth/geometry/obstacle3.h>

#include <modsynth/geometry/distance3.h>

#include "overload.h"

namespace modsynth::geometry {

const char* type_name(const Obstacle3& o) {
    return std::visit(
        Overload{[](const Sphere&) { return "sphere"; }, [](const Capsule&) { return "capsule"; },
                 [](const Box3&) { return "box"; }},
        o);
}

double point_gap(const Vec3& p, const Obstacle3& o) {
    return std::visit(
        Overload{[&](const Sphere& s) { return (p - s.center).norm() - s.radius; },
                 [&](const Capsule& c) { return point_segment(p, c.a, c.b) - c.radius; },
                 [&](const Box3& b) { return point_box(p, b); }},
        o);
}

double segment_gap(const Vec3& a, const Vec3& b, const Obstacle3& o) {
    return std::visit(
        Overload{[&](const Sphere& s) { return point_segment(s.center, a, b) - s.radius; },
                 [&](const Capsule& c) { return segment_segment(a, b, c.a, c.b) - c.radius; },
                 [&](const Box3& box) { return segment_box(a, b, box); }},
        o);
}

ObstacleCore core_of(const Obstacle3& o) {
    ObstacleCore c;
    std::visit(Overload{[&](const Sphere& s) {
                            c.points[c.count++] = s.center;
                            c.radius = s.radius;
                        },
                        [&](const Capsule& k) {
                            c.points[c.count++] = k.a;
                            c.points[c.count++] = k.b;
                            c.radius = k.radius;
                        },
                        [&](const Box3& b) {
                            for (int i = 0; i < 8; ++i)
                                c.points[c.count++] = Vec3(i & 1 ? b.max.x() : b.min.x(),
                                                           i & 2 ? b.max.y() : b.min.y(),
                                                           i & 4 ? b.max.z() : b.min.z());
                        }},
               o);
    return c;
}

Sphere bounding_sphere(const Obstacle3& o) {
    return std::visit(
        Overload{[](const Sphere& s) { return s; },
                 [](const Capsule& c) {
                     return Sphere{0.5 * (c.a + c.b), 0.5 * (c.b - c.a).norm() + c.radius};
                 },
                 [](const Box3& b) {
                     return Sphere{b.center(), 0.5 * (b.max - b.min).norm()};
                 }},
        o);
}

}  // namespace modsynth::geometry
