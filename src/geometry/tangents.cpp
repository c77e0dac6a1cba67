#include <modsynth/geometry/tangents.h>

#include <cmath>

namespace modsynth::geometry {

std::vector<Vec2> tangent_points(const Vec2& p, const Vec2& c, double r) {
    const Vec2 v = p - c;
    const double d = v.norm();
    if (d <= r) return {};
    const double phi = std::atan2(v.y(), v.x());
    const double beta = std::acos(r / d);
    return {c + r * unit(phi + beta), c + r * unit(phi - beta)};
}

std::vector<TangentSegment> bitangents(const Vec2& c1, double r1, const Vec2& c2, double r2,
                                       double slack) {
    std::vector<TangentSegment> out;
    const Vec2 D = c2 - c1;
    const double d = D.norm();
    if (d == 0.0) return out;
    const Vec2 u = D / d;
    // A tangent line {x : n.x = h} touches circle 1 at c1 + r1 n and circle
    // 2 at c2 + s r2 n, s = +1 (outer) or -1 (inner): n.D = r1 - s r2.
    for (const double s : {1.0, -1.0}) {
        double cos_a = (r1 - s * r2) / d;
        if (std::abs(cos_a) > 1.0) {
            if (s < 0.0 && (r1 + r2) - d <= slack) {
                cos_a = 1.0;
            } else {
                continue;
            }
        }
        const double sin_a = std::sqrt(std::max(0.0, 1.0 - cos_a * cos_a));
        for (const double side : {1.0, -1.0}) {
            const Vec2 n = cos_a * u + side * sin_a * perp(u);
            out.push_back({c1 + r1 * n, c2 + s * r2 * n});
            if (sin_a == 0.0) break;
        }
    }
    return out;
}

}  // namespace modsynth::geometry
