#include <modsynth/nlp/formulation.h>

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>

#include <modsynth/geometry/distance.h>
#include <modsynth/kinematics/chain_layout.h>
#include <modsynth/kinematics/clearance_rule.h>
#include <modsynth/kinematics/kinematics.h>
#include <modsynth/nlp/bilinear.h>
#include <modsynth/nlp/key.h>
#include <modsynth/task/part.h>
#include <modsynth/task/strokes.h>
#include <modsynth/text/format.h>

namespace modsynth::nlp {
namespace {

using geometry::Vec2;

using namespace bilinear;

std::string obstacle_name(int o) { return task::to_string(task::TaskPart::obstacle(o)); }

// Where along the task a variable or constraint sits: its words in labels,
// and the same as a key's place (key.h). Arc lengths and angles enter keys
// to the micrometre and microradian, as precisely as labels print them.
struct Where {
    std::string text;
    Key::Place place = Key::Place::None;
    int primitive = -1;
    std::int64_t at = 0;

    static Where trace(const task::Task& t, int j, double s) {
        return {task::part_name(t, j) + text::format(" at %.6f m", s), Key::Place::Trace, j,
                std::llround(s * 1e6)};
    }
    static Where primitive_of(const task::Task& t, int j) {
        return {task::part_name(t, j), Key::Place::Primitive, j, 0};
    }
    static Where transition(const task::Task& t, int j, double angle) {
        return {"transition after " + task::part_name(t, j) +
                    text::format(", link 1 at %.6f rad", angle),
                Key::Place::Transition, j, std::llround(angle * 1e6)};
    }

    Key key(Key::Family family, Key::Role role = Key::Role::None, int index = 0) const {
        Key k;
        k.family = family;
        k.role = role;
        k.index = index;
        k.place = place;
        k.primitive = primitive;
        k.at = at;
        return k;
    }
};

class Builder {
public:
    Builder(const ArmProblem& problem, Formulation& f)
        : p_(problem), t_(*problem.task), f_(f), qp_(f.program), rule_{t_.robot.link_diameter} {}

    void build() {
        const kinematics::Robot& start = p_.start;
        // The start robot is of the skeleton's kind: its links, and with
        // three joints a proximal angle per primitive.
        assert(start.dof() == p_.skeleton.dof);
        assert(!kinematics::has_proximal_link(p_.skeleton.dof) ||
               start.proximal_angles.size() == t_.trajectory.size());
        assert(p_.skeleton.base_region < static_cast<int>(t_.base_regions.size()));
        f_.dof = p_.skeleton.dof;
        f_.elbow = p_.skeleton.elbow;
        f_.link_diameter = t_.robot.link_diameter;

        double bx_lo = -kInfinity, bx_hi = kInfinity, by_lo = -kInfinity, by_hi = kInfinity;
        if (p_.skeleton.base_region >= 0) {
            const task::BaseRegion& r = t_.base_regions[p_.skeleton.base_region];
            bx_lo = r.min.x(), bx_hi = r.max.x(), by_lo = r.min.y(), by_hi = r.max.y();
        }
        const Where nowhere;
        f_.base_x = qp_.add_variable(bx_lo, bx_hi, start.base.x(), "base.x",
                                     nowhere.key(Key::Family::Base).at_coordinate(0));
        f_.base_y = qp_.add_variable(by_lo, by_hi, start.base.y(), "base.y",
                                     nowhere.key(Key::Family::Base).at_coordinate(1));
        base_ = variable(f_.base_x, f_.base_y, start.base);
        Quadratic objective;
        for (int k = 0; k < f_.dof; ++k) {
            f_.r.push_back(
                qp_.add_variable(t_.robot.min_link_length, t_.robot.max_link_length,
                                 start.link_lengths[k], "r" + std::to_string(k + 1),
                                 nowhere.key(Key::Family::LinkLength, Key::Role::None, k + 1)));
            objective.add(f_.r.back(), 1.0);
        }
        qp_.set_objective(objective);

        if (kinematics::has_proximal_link(f_.dof)) add_proximal_poses();
        for (const PathPoint& pt : p_.points) add_trace_point(pt);
        if (kinematics::has_proximal_link(f_.dof)) {
            for (int j = 0; j + 1 < static_cast<int>(t_.trajectory.size()); ++j)
                if (task::has_transition_after(t_, j)) add_transition(j);
        }
        if (p_.swept == SweptVolume::Over) add_swept_over();
        if (p_.swept == SweptVolume::App) add_swept_app();
        qp_.finalize();
    }

private:
    // The point the distal pair turns about while primitive j is traced.
    const Point& origin(int j) const {
        return kinematics::has_proximal_link(f_.dof) ? proximal_[j] : base_;
    }

    double need_for(const task::Obstacle& ob) const {
        return rule_.obstacle_distance(ob) + p_.margins.clearance;
    }

    Point new_point(const std::string& name, const Vec2& v, const Key& key) {
        return bilinear::new_point(qp_, name, v, key);
    }

    void link(const Point& a, const Point& b, int r, const std::string& tag, const Key& key) {
        add_link(qp_, a, b, r, tag, key);
    }

    // Pairs farther apart than the horizon in the initial guess are left to
    // the verification.
    void keep_apart(const Point& a, const Point& b, const Point& c, double need,
                    const std::string& tag, const Key& key) {
        if (geometry::point_segment(c.value, a.value, b.value) - need > p_.horizon) return;
        add_keep_apart(qp_, a, b, c, need, tag, key);
    }

    void keep_links_from_obstacles(const Point& a, const Point& b, int link, const Where& where) {
        for (int o = 0; o < static_cast<int>(t_.obstacles.size()); ++o) {
            Key key = where.key(Key::Family::None, Key::Role::LinkObstacle);
            key.link = link;
            key.obstacle = o;
            keep_apart(
                a, b, constant(t_.obstacles[o].center), need_for(t_.obstacles[o]),
                "link " + std::to_string(link) + " to " + obstacle_name(o) + ", " + where.text,
                key);
        }
    }

    // The distal pair from `o` with its EE at p: elbow variable, both link
    // lengths, the elbow side, and (unless a swept volume stands for them)
    // clearance of both distal links. Returns the elbow.
    Point distal_pair(const Point& o, const Vec2& p, const Where& where, bool clear_links = true) {
        const int r_a = f_.r[f_.dof - 2], r_b = f_.r[f_.dof - 1];
        const double a0 = p_.start.link_lengths[f_.dof - 2], b0 = p_.start.link_lengths[f_.dof - 1];
        const Point e = new_point("elbow " + where.text,
                                  kinematics::elbow_towards(o.value, a0, b0, p, f_.elbow),
                                  where.key(Key::Family::Elbow));
        const Point target = constant(p);
        link(o, e, r_a, "distal 1 " + where.text,
             where.key(Key::Family::None, Key::Role::Distal, 1));
        link(e, target, r_b, "distal 2 " + where.text,
             where.key(Key::Family::None, Key::Role::Distal, 2));
        // eqs. (5) and (8) in one: sigma * cross(e - o, p - o) >= k * r_a.
        // The cross product is r_a times the height of p above the line of
        // the first distal link: this keeps the elbow on its branch, away
        // from the singular straight and folded poses, and the EE at least k
        // from that link (a lower bound on its distance from the segment).
        Quadratic side = scaled(cross(o, e, target), f_.elbow);
        side.add(r_a, -(rule_.self_distance() + p_.margins.self));
        qp_.add_constraint(side, 0.0, kInfinity, "elbow side " + where.text,
                           where.key(Key::Family::ElbowSide));
        if (clear_links) {
            keep_links_from_obstacles(o, e, f_.dof - 1, where);
            keep_links_from_obstacles(e, target, f_.dof, where);
        }
        if (kinematics::has_proximal_link(f_.dof)) {
            // eq. (9): the EE keeps a diameter away from the proximal link.
            keep_apart(base_, o, target, rule_.self_distance() + p_.margins.self,
                       "EE to link 1, " + where.text,
                       where.key(Key::Family::None, Key::Role::EeToProximal));
        }
        return e;
    }

    void add_trace_point(const PathPoint& pt) {
        const Vec2 p = geometry::point_at(t_.trajectory[pt.primitive], pt.s);
        const bool swept = p_.swept != SweptVolume::Sampled && p_.swept_only;
        const Point e =
            distal_pair(origin(pt.primitive), p, Where::trace(t_, pt.primitive, pt.s), !swept);
        if (elbows_.size() < t_.trajectory.size()) elbows_.resize(t_.trajectory.size());
        elbows_[pt.primitive].push_back(e);
    }

    void add_proximal_poses() {
        for (int j = 0; j < static_cast<int>(t_.trajectory.size()); ++j) {
            const double angle = p_.start.proximal_angles.at(j);
            const Where where = Where::primitive_of(t_, j);
            proximal_.push_back(new_point("proximal " + where.text, p_.start.distal_origin(angle),
                                          where.key(Key::Family::Proximal)));
            f_.proximal.push_back(
                {proximal_.back().x.terms[0].first, proximal_.back().y.terms[0].first});
            link(base_, proximal_.back(), f_.r[0], "proximal " + where.text,
                 where.key(Key::Family::None, Key::Role::Proximal));
            keep_links_from_obstacles(base_, proximal_.back(), 1, where);
        }
    }

    // Proximal poses inside the transition after primitive j, by repeated
    // bisection of the swept angle: t - b = lambda (a - b + c - b) with
    // |t - b| = r1 puts t on the bisector of a and c (for sweeps under pi),
    // and keeps every constraint bilinear.
    void add_transition(int j) {
        const Vec2 p = t_.trajectory[j].end;
        const double r1 = p_.start.link_lengths[0];
        const double a0 = p_.start.proximal_angles[j];
        const double c0 = a0 + std::remainder(p_.start.proximal_angles[j + 1] - a0, geometry::kTau);
        bisect(proximal_[j], a0, proximal_[j + 1], c0, p_.transition_depth, p, r1, j);
    }

    void bisect(const Point& a, double angle_a, const Point& c, double angle_c, int depth,
                const Vec2& p, double r1, int j) {
        if (depth <= 0) return;
        const double mid = 0.5 * (angle_a + angle_c);
        const Vec2 t0 = p_.start.distal_origin(mid);
        const Where where = Where::transition(t_, j, mid);
        const Point t = new_point("proximal " + where.text, t0, where.key(Key::Family::Proximal));
        const Affine sum = (a.x - base_.x) + (c.x - base_.x);
        const Affine sum_y = (a.y - base_.y) + (c.y - base_.y);
        const double len0 = ((a.value - p_.start.base) + (c.value - p_.start.base)).norm();
        const int lambda = qp_.add_variable(0.0, 1e3, len0 > 1e-9 ? r1 / len0 : 1.0,
                                            "lambda " + where.text, where.key(Key::Family::Lambda));
        const Affine lam{0.0, {{lambda, 1.0}}};
        for (const auto& [coord, s] : {std::pair{&t.x, &sum}, std::pair{&t.y, &sum_y}}) {
            Quadratic q;
            add_affine(q, *coord - (coord == &t.x ? base_.x : base_.y));
            add_product(q, lam, *s, -1.0);
            qp_.add_constraint(q, 0.0, 0.0, "bisector " + where.text,
                               where.key(Key::Family::Bisector));
        }
        link(base_, t, f_.r[0], "proximal " + where.text,
             where.key(Key::Family::None, Key::Role::Proximal));
        keep_links_from_obstacles(base_, t, 1, where);
        distal_pair(t, p, where);
        bisect(a, angle_a, t, mid, depth - 1, p, r1, j);
        bisect(t, mid, c, angle_c, depth - 1, p, r1, j);
    }

    // SV^over: conv(disc(o_j, r_a) and primitive j) holds the distal pair
    // during j (with three joints the proximal link is static during j, and
    // its pose keeps its own separating lines).
    void add_swept_over() {
        const int r_a = f_.r[f_.dof - 2];
        for (int j = 0; j < static_cast<int>(t_.trajectory.size()); ++j) {
            const geometry::Primitive& prim = t_.trajectory[j];
            const Point& origin_j = origin(j);
            for (int o = 0; o < static_cast<int>(t_.obstacles.size()); ++o) {
                const task::Obstacle& ob = t_.obstacles[o];
                const SvTag tag{obstacle_name(o) + " on " + task::part_name(t_, j), 0, o, j};
                const Vec2 mid = geometry::point_at(prim, geometry::length(prim) / 2);
                const Vec2 n0 = away_from(ob.center, origin_j.value, mid);
                separate({}, Disc{origin_j, r_a}, &prim, ob, tag, n0);
            }
        }
    }

    // eqs. (3) and (4) for one convex polygon: a unit n with
    // n . (v - c) >= need at every vertex v, and for an arc or circle of the
    // path its whole disc beyond the line (no obstacle lies inside it, II-A).
    // SV^over's polygon is a disc of variable radius about a point, which
    // stands in for the vertices.
    struct Disc {
        Point center;
        int radius;  ///< the variable
    };

    // What one separating line keeps apart: the label's words, and the link
    // (0: SV^over's whole bound), obstacle and primitive for its keys.
    struct SvTag {
        std::string text;
        int link = 0;
        int obstacle = -1;
        int primitive = -1;

        Key key(Key::Family family, int index = 0) const {
            Key k;
            k.family = family;
            k.index = index;
            k.link = link;
            k.obstacle = obstacle;
            k.place = Key::Place::Primitive;
            k.primitive = primitive;
            return k;
        }
    };

    void separate(const std::vector<Point>& vertices, std::optional<Disc> disc,
                  const geometry::Primitive* prim, const task::Obstacle& ob, const SvTag& tag,
                  std::optional<Vec2> start = std::nullopt) {
        const double need = need_for(ob);
        Vec2 n0 = Vec2(1.0, 0.0);
        if (start) {
            n0 = *start;
        } else {
            Vec2 centroid = Vec2::Zero();
            for (const Point& v : vertices) centroid += v.value;
            centroid /= static_cast<double>(vertices.size());
            const Vec2 away = centroid - ob.center;
            if (away.norm() > 1e-9) n0 = away / away.norm();
        }
        const int nx = qp_.add_variable(-1.0, 1.0, n0.x(), "sv normal.x " + tag.text,
                                        tag.key(Key::Family::SvNormal).at_coordinate(0));
        const int ny = qp_.add_variable(-1.0, 1.0, n0.y(), "sv normal.y " + tag.text,
                                        tag.key(Key::Family::SvNormal).at_coordinate(1));
        const Point n = variable(nx, ny, n0);
        const Point c = constant(ob.center);
        auto support = [&](const Point& v) {
            Quadratic q;
            add_product(q, n.x, v.x - c.x);
            add_product(q, n.y, v.y - c.y);
            return q;
        };
        if (disc)
            qp_.add_constraint(support(disc->center).add(disc->radius, -1.0), need, kInfinity,
                               "SV disc " + tag.text, tag.key(Key::Family::SvDisc));
        for (const Point& v : vertices)
            qp_.add_constraint(support(v), need, kInfinity, "SV vertex " + tag.text,
                               tag.key(Key::Family::SvVertex));
        if (prim != nullptr) {
            switch (prim->kind) {
                case geometry::PrimitiveKind::Line:
                    for (const Vec2& v : {prim->start, prim->end})
                        qp_.add_constraint(support(constant(v)), need, kInfinity,
                                           "SV primitive " + tag.text,
                                           tag.key(Key::Family::SvPrimitive));
                    break;
                case geometry::PrimitiveKind::Arc:
                case geometry::PrimitiveKind::Circle:
                    // The arc lies in its circle's disc: a sound, simpler bound.
                    qp_.add_constraint(support(constant(prim->center)).add(-prim->radius), need,
                                       kInfinity, "SV primitive " + tag.text,
                                       tag.key(Key::Family::SvPrimitive));
                    break;
            }
        }
        qp_.add_constraint(Quadratic{}.add(nx, nx, 1.0).add(ny, ny, 1.0), -kInfinity, 1.0,
                           "SV unit " + tag.text, tag.key(Key::Family::SvUnit));
    }

    // (a - b) . (c - d)
    static Quadratic dot(const Point& a, const Point& b, const Point& c, const Point& d) {
        Quadratic q;
        add_product(q, a.x - b.x, c.x - d.x);
        add_product(q, a.y - b.y, c.y - d.y);
        return q;
    }

    // SV^app (III-D). The elbow's arc e_j runs counter-clockwise about o_j
    // from p1 to p2, the elbows at the chosen points of j that bound the
    // largest angular gap between them in the initial guess. M is the arc's
    // midpoint (on the circle, equidistant from p1 and p2, on the arc's
    // side), A and B the corners where the tangents at p1, M and p2 meet:
    // o, p1, A, B, p2 is the pentagon over the sector (Fig. 4(B)) and
    // p1, A, B, p2 the quadrilateral over the arc. Every relation is
    // bilinear: |M - o| = r_a, |M - p1|^2 = |M - p2|^2,
    // (A - p1) . (p1 - o) = 0, (A - M) . (M - o) = 0, and so for B.
    void add_swept_app() {
        const int r_a = f_.r[f_.dof - 2];
        for (int j = 0; j < static_cast<int>(elbows_.size()); ++j) {
            const std::vector<Point>& es = elbows_[j];
            if (es.empty()) continue;
            const Point& o = origin(j);
            const Where here = Where::primitive_of(t_, j);
            const std::string& name = here.text;
            std::vector<std::pair<double, int>> angle;
            for (int i = 0; i < static_cast<int>(es.size()); ++i) {
                const Vec2 d = es[i].value - o.value;
                angle.push_back({std::atan2(d.y(), d.x()), i});
            }
            std::sort(angle.begin(), angle.end());
            // The arc is the circle less its largest gap between elbows.
            int after_gap = 0;
            double gap = angle.front().first + geometry::kTau - angle.back().first;
            for (int i = 1; i < static_cast<int>(angle.size()); ++i)
                if (angle[i].first - angle[i - 1].first > gap) {
                    gap = angle[i].first - angle[i - 1].first;
                    after_gap = i;
                }
            const int n = static_cast<int>(angle.size());
            const Point& p1 = es[angle[after_gap].second];
            const Point& p2 = es[angle[(after_gap + n - 1) % n].second];
            const double span = geometry::kTau - gap;
            std::vector<Point> sector{o, p1}, quad{p1};
            if (span > 1e-3) {
                const double a1 = angle[after_gap].first;
                const double r0 = p_.start.link_lengths[f_.dof - 2];
                const double far = r0 / std::cos(span / 4);
                const Point m =
                    new_point("SV arc middle " + name, o.value + r0 * geometry::unit(a1 + span / 2),
                              here.key(Key::Family::SvArcMiddle));
                const Point a = new_point("SV arc corner 1 " + name,
                                          o.value + far * geometry::unit(a1 + span / 4),
                                          here.key(Key::Family::SvArcCorner, Key::Role::None, 1));
                const Point b = new_point("SV arc corner 2 " + name,
                                          o.value + far * geometry::unit(a1 + 3 * span / 4),
                                          here.key(Key::Family::SvArcCorner, Key::Role::None, 2));
                link(o, m, r_a, "SV arc middle " + name,
                     here.key(Key::Family::None, Key::Role::SvArcMiddle));
                Quadratic bisector = squared_distance(m, p1);
                add_scaled(bisector, squared_distance(m, p2), -1.0);
                qp_.add_constraint(bisector, 0.0, 0.0, "SV arc middle " + name,
                                   here.key(Key::Family::SvArcMiddle));
                qp_.add_constraint(cross(o, p1, m), 0.0, kInfinity, "SV arc side " + name,
                                   here.key(Key::Family::SvArcSide));
                const auto tangent = [&](int k) {
                    return here.key(Key::Family::SvTangent, Key::Role::None, k);
                };
                qp_.add_constraint(dot(a, p1, p1, o), 0.0, 0.0, "SV tangent 1 " + name, tangent(1));
                qp_.add_constraint(dot(a, m, m, o), 0.0, 0.0, "SV tangent 2 " + name, tangent(2));
                qp_.add_constraint(dot(b, m, m, o), 0.0, 0.0, "SV tangent 3 " + name, tangent(3));
                qp_.add_constraint(dot(b, p2, p2, o), 0.0, 0.0, "SV tangent 4 " + name, tangent(4));
                for (const Point* v : {&a, &b}) {
                    sector.push_back(*v);
                    quad.push_back(*v);
                }
            }
            sector.push_back(p2);
            quad.push_back(p2);
            for (int k = 0; k < static_cast<int>(t_.obstacles.size()); ++k) {
                const std::string tag = obstacle_name(k) + " on " + name;
                const int l1 = f_.dof - 1, l2 = f_.dof;
                separate(sector, std::nullopt, nullptr, t_.obstacles[k],
                         {"link " + std::to_string(l1) + " " + tag, l1, k, j});
                separate(quad, std::nullopt, &t_.trajectory[j], t_.obstacles[k],
                         {"link " + std::to_string(l2) + " " + tag, l2, k, j});
            }
        }
    }

    const ArmProblem& p_;
    const task::Task& t_;
    Formulation& f_;
    QuadraticProgram& qp_;
    const kinematics::ClearanceRule rule_;
    Point base_;
    std::vector<Point> proximal_;
    std::vector<std::vector<Point>> elbows_;  ///< per primitive, at its chosen points
};

}  // namespace

Formulation formulate(const ArmProblem& problem) {
    Formulation f;
    Builder(problem, f).build();
    return f;
}

kinematics::Robot robot_from(const Formulation& f, const std::vector<double>& x) {
    assert(x.size() == static_cast<std::size_t>(f.program.num_variables()));
    kinematics::Robot robot;
    robot.base = Vec2(x[f.base_x], x[f.base_y]);
    for (int r : f.r) robot.link_lengths.push_back(x[r]);
    robot.link_diameter = f.link_diameter;
    robot.elbow = f.elbow;
    for (const auto& [ix, iy] : f.proximal)
        robot.proximal_angles.push_back(std::atan2(x[iy] - robot.base.y(), x[ix] - robot.base.x()));
    return robot;
}

}  // namespace modsynth::nlp
