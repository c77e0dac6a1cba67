#include <modsynth/nlp/bilinear.h>

#include <modsynth/geometry/distance.h>

namespace modsynth::nlp::bilinear {

Affine operator-(Affine a, const Affine& b) {
    a.c -= b.c;
    for (const auto& [i, w] : b.terms) a.terms.push_back({i, -w});
    return a;
}

Affine operator+(Affine a, const Affine& b) {
    a.c += b.c;
    a.terms.insert(a.terms.end(), b.terms.begin(), b.terms.end());
    return a;
}

void add_product(Quadratic& q, const Affine& a, const Affine& b, double k) {
    q.add(k * a.c * b.c);
    for (const auto& [i, w] : b.terms) q.add(i, k * a.c * w);
    for (const auto& [i, w] : a.terms) q.add(i, k * b.c * w);
    for (const auto& [i, wi] : a.terms)
        for (const auto& [j, wj] : b.terms) q.add(i, j, k * wi * wj);
}

void add_affine(Quadratic& q, const Affine& a, double k) {
    q.add(k * a.c);
    for (const auto& [i, w] : a.terms) q.add(i, k * w);
}

Point constant(const Vec2& v) { return {{v.x(), {}}, {v.y(), {}}, v}; }

Point variable(int ix, int iy, const Vec2& v) {
    return {{0.0, {{ix, 1.0}}}, {0.0, {{iy, 1.0}}}, v};
}

namespace {

// The key of one part of a tagged construction: `family`, `index`, and the
// tag's role and place; unkeyed when the tag has no role.
Key part_of(Key tag, Key::Family family, int index = 0) {
    if (tag.role == Key::Role::None) return {};
    tag.family = family;
    tag.index = index;
    return tag;
}

Key coordinate(Key key, int xy) {
    key.coordinate = xy;
    return key;
}

}  // namespace

Point new_point(QuadraticProgram& qp, const std::string& name, const Vec2& v, Key key) {
    const int ix = qp.add_variable(-kInfinity, kInfinity, v.x(), name + ".x", coordinate(key, 0));
    const int iy = qp.add_variable(-kInfinity, kInfinity, v.y(), name + ".y", coordinate(key, 1));
    return variable(ix, iy, v);
}

Quadratic squared_distance(const Point& a, const Point& b) {
    Quadratic q;
    const Affine dx = a.x - b.x, dy = a.y - b.y;
    add_product(q, dx, dx);
    add_product(q, dy, dy);
    return q;
}

Quadratic cross(const Point& o, const Point& e, const Point& p) {
    Quadratic q;
    add_product(q, e.x - o.x, p.y - o.y);
    add_product(q, e.y - o.y, p.x - o.x, -1.0);
    return q;
}

void add_scaled(Quadratic& into, const Quadratic& q, double k) {
    into.add(k * q.constant);
    for (const auto& [i, w] : q.linear) into.add(i, k * w);
    for (const auto& t : q.quadratic) into.add(t.i, t.j, k * t.w);
}

Quadratic scaled(const Quadratic& q, double k) {
    Quadratic out;
    add_scaled(out, q, k);
    return out;
}

Vec2 away_from(const Vec2& c, const Vec2& a, const Vec2& b) {
    const double t = geometry::segment_parameter(c, a, b);
    const Vec2 d = a + t * (b - a) - c;
    const double n = d.norm();
    return n > 1e-12 ? Vec2(d / n) : Vec2(1.0, 0.0);
}

void add_link(QuadraticProgram& qp, const Point& a, const Point& b, int r, const std::string& tag,
              Key key) {
    Quadratic q = squared_distance(a, b);
    q.add(r, r, -1.0);
    qp.add_constraint(q, 0.0, 0.0, "link length " + tag,
                      part_of(key, Key::Family::LinkLength, key.index));
}

void add_keep_apart(QuadraticProgram& qp, const Point& a, const Point& b, const Point& c,
                    double need, const std::string& tag, Key key) {
    const Vec2 n0 = away_from(c.value, a.value, b.value);
    const Key normal = part_of(key, Key::Family::Normal);
    const int nx = qp.add_variable(-1.0, 1.0, n0.x(), "normal.x " + tag, coordinate(normal, 0));
    const int ny = qp.add_variable(-1.0, 1.0, n0.y(), "normal.y " + tag, coordinate(normal, 1));
    const Point n = variable(nx, ny, n0);
    for (const Point* end : {&a, &b}) {
        Quadratic q;
        add_product(q, n.x, end->x - c.x);
        add_product(q, n.y, end->y - c.y);
        qp.add_constraint(q, need, kInfinity, "clearance of " + tag,
                          part_of(key, Key::Family::Clearance));
    }
    qp.add_constraint(Quadratic{}.add(nx, nx, 1.0).add(ny, ny, 1.0), -kInfinity, 1.0,
                      "unit normal for " + tag, part_of(key, Key::Family::UnitNormal));
}

}  // namespace modsynth::nlp::bilinear
