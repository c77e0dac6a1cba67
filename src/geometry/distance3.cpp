#include <modsynth/geometry/distance3.h>

#include <Eigen/Cholesky>
#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <limits>
#include <utility>

namespace modsynth::geometry {

double segment_parameter(const Vec3& p, const Vec3& a, const Vec3& b) {
    const Vec3 d = b - a;
    const double dd = d.squaredNorm();
    if (!(dd > 0.0)) return 0.0;
    return std::clamp((p - a).dot(d) / dd, 0.0, 1.0);
}

double point_segment(const Vec3& p, const Vec3& a, const Vec3& b) {
    const double t = segment_parameter(p, a, b);
    return (a + t * (b - a) - p).norm();
}

double segment_segment(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
    // The least distance is at an end point of one segment unless both
    // nearest points of the two lines lie strictly inside: the four end
    // point distances cover parallel, collinear and point-like segments
    // exactly, and the interior candidate is polished by one projection each
    // way, which can only bring it nearer.
    double best = std::min({point_segment(a, c, d), point_segment(b, c, d), point_segment(c, a, b),
                            point_segment(d, a, b)});
    const Vec3 d1 = b - a, d2 = d - c, r = a - c;
    const double aa = d1.squaredNorm(), ee = d2.squaredNorm(), ab = d1.dot(d2);
    const double denom = aa * ee - ab * ab;
    if (aa > 0.0 && ee > 0.0 && denom > 0.0) {
        const double cc = d1.dot(r), ff = d2.dot(r);
        double s = (ab * ff - cc * ee) / denom;
        double t = (aa * ff - ab * cc) / denom;
        if (s > 0.0 && s < 1.0 && t > 0.0 && t < 1.0) {
            t = std::clamp((ab * s + ff) / ee, 0.0, 1.0);
            s = std::clamp((ab * t - cc) / aa, 0.0, 1.0);
            best = std::min(best, (a + s * d1 - (c + t * d2)).norm());
        }
    }
    return best;
}

Vec3 nearest_in_box(const Vec3& p, const Box3& box) {
    return p.cwiseMax(box.min).cwiseMin(box.max);
}

double point_box(const Vec3& p, const Box3& box) {
    double sum = 0.0;
    for (int i = 0; i < 3; ++i) {
        const double out = std::max({box.min[i] - p[i], 0.0, p[i] - box.max[i]});
        sum += out * out;
    }
    return std::sqrt(sum);
}

double segment_box(const Vec3& a, const Vec3& b, const Box3& box, double* t_out) {
    // Along the segment the squared distance is a convex quadratic between
    // the parameters where a coordinate crosses one of the box's face
    // planes, so the least value of each piece is closed-form.
    const Vec3 d = b - a;
    std::array<double, 8> ts{};
    int n = 0;
    ts[n++] = 0.0;
    ts[n++] = 1.0;
    for (int i = 0; i < 3; ++i) {
        if (d[i] == 0.0) continue;
        for (const double face : {box.min[i], box.max[i]}) {
            const double t = (face - a[i]) / d[i];
            if (t > 0.0 && t < 1.0) ts[n++] = t;
        }
    }
    // At most eight values: an insertion sort.
    for (int i = 1; i < n; ++i)
        for (int k = i; k > 0 && ts[k - 1] > ts[k]; --k) std::swap(ts[k - 1], ts[k]);
    double best = point_box(a, box), best_t = 0.0;
    for (int k = 0; k + 1 < n && best > 0.0; ++k) {
        const double t0 = ts[k], t1 = ts[k + 1];
        const double tm = 0.5 * (t0 + t1);
        double qa = 0.0, qb = 0.0;
        for (int i = 0; i < 3; ++i) {
            const double x = a[i] + tm * d[i];
            const double face = x < box.min[i] ? box.min[i] : x > box.max[i] ? box.max[i] : x;
            if (face == x) continue;
            qa += d[i] * d[i];
            qb += (a[i] - face) * d[i];
        }
        const double t = qa > 0.0 ? std::clamp(-qb / qa, t0, t1) : t0;
        const double v = point_box(a + t * d, box);
        if (v < best) best = v, best_t = t;
    }
    if (const double v = point_box(b, box); v < best) best = v, best_t = 1.0;
    if (t_out) *t_out = best_t;
    return best;
}

namespace {

/// The point of the convex hull of at most 4 points nearest to the origin,
/// and the points of the smallest face that holds it. Every face whose
/// points are affinely independent is projected on exactly; the nearest
/// point lies inside one of them (faces of dependent points are unions of
/// independent ones), and a face whose projection falls outside it is not
/// the one.
// Gram systems of at most 3 unknowns, without allocation.
using Small = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 3, 3>;
using SmallVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 3, 1>;

struct Simplex {
    std::array<Vec3, 4> points;
    int size = 0;
};

Vec3 nearest_to_origin(Simplex& s) {
    Vec3 best_point = s.points[0];
    double best = std::numeric_limits<double>::infinity();
    int best_mask = 1;
    for (int mask = 1; mask < (1 << s.size); ++mask) {
        std::array<int, 4> idx{};
        int k = 0;
        for (int i = 0; i < s.size; ++i)
            if (mask & (1 << i)) idx[k++] = i;
        Vec3 p;
        if (k == 1) {
            p = s.points[idx[0]];
        } else {
            const Vec3& t0 = s.points[idx[0]];
            Eigen::Matrix<double, 3, 3> e;
            for (int j = 1; j < k; ++j) e.col(j - 1) = s.points[idx[j]] - t0;
            const auto ek = e.leftCols(k - 1);
            const Small g = ek.transpose() * ek;
            const SmallVector rhs = -(ek.transpose() * t0);
            const Eigen::LDLT<Small> ldlt(g);
            const SmallVector diag = ldlt.vectorD();
            if (ldlt.info() != Eigen::Success || !(diag.minCoeff() > 1e-12 * diag.maxCoeff()))
                continue;  // affinely dependent: its sub-faces cover it
            const SmallVector mu = ldlt.solve(rhs);
            const double lambda0 = 1.0 - mu.sum();
            if (!(lambda0 > 0.0) || !(mu.minCoeff() > 0.0)) continue;
            p = t0 + ek * mu;
        }
        const double n2 = p.squaredNorm();
        if (n2 < best) best = n2, best_point = p, best_mask = mask;
    }
    Simplex kept;
    for (int i = 0; i < s.size; ++i)
        if (best_mask & (1 << i)) kept.points[kept.size++] = s.points[i];
    s = kept;
    return best_point;
}

}  // namespace

double hull_distance(std::span<const Vec3> a, std::span<const Vec3> b) {
    assert(!a.empty() && !b.empty() && a.size() <= 8 && b.size() <= 8);
    // The distance between the hulls is that of the origin from the hull of
    // the differences a_i - b_j.
    std::array<Vec3, 64> m;
    m.fill(Vec3::Zero());
    std::size_t n = 0;
    for (const Vec3& p : a)
        for (const Vec3& q : b) m[n++] = p - q;
    auto support = [&](const Vec3& dir) {
        std::size_t arg = 0;
        double low = m[0].dot(dir);
        for (std::size_t i = 1; i < n; ++i) {
            const double v = m[i].dot(dir);
            if (v < low) low = v, arg = i;
        }
        return arg;
    };
    Simplex s;
    s.points[s.size++] = m[support(Vec3(1.0, 0.0, 0.0))];
    Vec3 x = s.points[0];
    for (int iteration = 0; iteration < 64; ++iteration) {
        const double xx = x.squaredNorm();
        if (!(xx > 0.0)) return 0.0;
        const Vec3 w = m[support(x)];
        // No point of the set lies further towards the origin: x is nearest.
        if (xx - x.dot(w) <= 1e-13 * xx) break;
        bool known = false;
        for (int i = 0; i < s.size; ++i) known = known || s.points[i] == w;
        if (known || s.size == 4) break;
        s.points[s.size++] = w;
        const Vec3 next = nearest_to_origin(s);
        if (!(next.squaredNorm() < xx)) break;
        x = next;
    }
    const double norm = x.norm();
    if (!(norm > 0.0)) return 0.0;
    const Vec3 dir = x / norm;
    return std::max(0.0, m[support(dir)].dot(dir));
}

}  // namespace modsynth::geometry
