#pragma once
// The vocabulary in which modsynth's programs are written: points whose
// coordinates are affine in the variables, and the bilinear constraints
// between them (a link of a given length, the side of an elbow, a line that
// keeps a link away from a disc). Both the refinement and the discretized
// baseline build their QuadraticPrograms from these.
#include <string>
#include <utility>
#include <vector>

#include <modsynth/geometry/vec.h>
#include <modsynth/nlp/quadratic_program.h>

namespace modsynth::nlp::bilinear {

using geometry::Vec2;

/// c + sum a_i x_i: a coordinate that is a variable, a constant, or a
/// difference of those.
struct Affine {
    double c = 0.0;
    std::vector<std::pair<int, double>> terms;
};

Affine operator-(Affine a, const Affine& b);
Affine operator+(Affine a, const Affine& b);

/// Adds k * a * b to q.
void add_product(Quadratic& q, const Affine& a, const Affine& b, double k = 1.0);
/// Adds k * a to q.
void add_affine(Quadratic& q, const Affine& a, double k = 1.0);

/// A point of the model with its value in the initial guess.
struct Point {
    Affine x, y;
    Vec2 value;
};

Point constant(const Vec2& v);
Point variable(int ix, int iy, const Vec2& v);
/// Two new unbounded variables, started at v; keyed as `key` with index 0
/// (x) and 1 (y).
Point new_point(QuadraticProgram& qp, const std::string& name, const Vec2& v, Key key = {});

Quadratic squared_distance(const Point& a, const Point& b);
/// cross(e - o, p - o).
Quadratic cross(const Point& o, const Point& e, const Point& p);
/// Adds k * q to into.
void add_scaled(Quadratic& into, const Quadratic& q, double k);
/// k * q.
Quadratic scaled(const Quadratic& q, double k);

/// The unit direction from c to the nearest point of segment ab.
Vec2 away_from(const Vec2& c, const Vec2& a, const Vec2& b);

/// |a - b| = x[r] (paper eq. 11). `tag` and the role, place, link and
/// obstacle of `key` say what for (a key without a role: unkeyed).
void add_link(QuadraticProgram& qp, const Point& a, const Point& b, int r, const std::string& tag,
              Key key = {});

/// Keeps segment ab at least `need` from c: some unit n (two new variables)
/// with n . (a - c) >= need and n . (b - c) >= need, so that the line
/// through c along n's normal separates them. Tagged as add_link.
void add_keep_apart(QuadraticProgram& qp, const Point& a, const Point& b, const Point& c,
                    double need, const std::string& tag, Key key = {});

}  // namespace modsynth::nlp::bilinear
