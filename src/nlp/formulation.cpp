#include <modsynth/nlp/formulation.h>

#include <algorithm>
#include <cmath>
#include <string>

#include <modsynth/geometry/distance.h>
#include <modsynth/kinematics/kinematics.h>

namespace modsynth::nlp {
namespace {

using geometry::Vec2;

std::string at(const PathPoint& p) {
    return "trajectory[" + std::to_string(p.primitive) + "]@" + std::to_string(p.s);
}

// Elbow position that the start robot would use for target: the IK on the
// chosen branch, or for an unreachable target the elbow pointing at it.
Vec2 initial_elbow(const kinematics::Robot& robot, const Vec2& target, int elbow) {
    const double r1 = robot.link_lengths[0], r2 = robot.link_lengths[1];
    if (auto ik = kinematics::inverse_two_link(robot.base, r1, r2, target, elbow))
        return robot.base + r1 * geometry::unit(ik->phi1);
    const Vec2 d = target - robot.base;
    const double n = d.norm();
    const Vec2 dir = n > 1e-12 ? Vec2(d / n) : Vec2(1.0, 0.0);
    // Bend towards the requested side so the elbow constraint starts close.
    const Vec2 side = -elbow * geometry::perp(dir);
    return robot.base + r1 * (0.8 * dir + 0.6 * side).normalized();
}

// Quadratic of n . (a - c) where a = (ax, ay) are variables (or constants
// when the index is -1, with value a_const) and n = (nx, ny) are variables.
Quadratic separation(int nx, int ny, int ax, int ay, const Vec2& a_const, const Vec2& c) {
    Quadratic g;
    if (ax >= 0) {
        g.add(nx, ax, 1.0).add(ny, ay, 1.0);
    } else {
        g.add(nx, a_const.x()).add(ny, a_const.y());
    }
    g.add(nx, -c.x()).add(ny, -c.y());
    return g;
}

Quadratic unit_ball(int nx, int ny) {
    Quadratic g;
    g.add(nx, nx, 1.0).add(ny, ny, 1.0);
    return g;
}

// Unit direction from c towards the nearest point of segment ab.
Vec2 away_from(const Vec2& c, const Vec2& a, const Vec2& b) {
    const double t = geometry::segment_parameter(c, a, b);
    const Vec2 d = a + t * (b - a) - c;
    const double n = d.norm();
    return n > 1e-12 ? Vec2(d / n) : Vec2(1.0, 0.0);
}

}  // namespace

Formulation formulate_two_link(const TwoLinkProblem& problem) {
    const task::Task& task = *problem.task;
    const kinematics::Robot& start = problem.start;
    Formulation f;
    f.elbow = problem.skeleton.elbow;
    f.link_diameter = task.robot.link_diameter;
    QuadraticProgram& qp = f.program;

    double bx_lo = -kInfinity, bx_hi = kInfinity, by_lo = -kInfinity, by_hi = kInfinity;
    if (problem.skeleton.base_region >= 0) {
        const task::BaseRegion& r = task.base_regions[problem.skeleton.base_region];
        bx_lo = r.min.x(), bx_hi = r.max.x(), by_lo = r.min.y(), by_hi = r.max.y();
    }
    f.base_x = qp.add_variable(bx_lo, bx_hi, start.base.x(), "base.x");
    f.base_y = qp.add_variable(by_lo, by_hi, start.base.y(), "base.y");
    const double lo = task.robot.min_link_length, hi = task.robot.max_link_length;
    f.r1 = qp.add_variable(lo, hi, start.link_lengths[0], "r1");
    f.r2 = qp.add_variable(lo, hi, start.link_lengths[1], "r2");
    qp.set_objective(Quadratic{}.add(f.r1, 1.0).add(f.r2, 1.0));

    const int sigma = f.elbow;
    const double k_self = task.robot.link_diameter + problem.margins.self;
    const double half = task.robot.link_diameter / 2.0 + problem.margins.clearance;
    const int bx = f.base_x, by = f.base_y;

    for (const PathPoint& pt : problem.points) {
        const Vec2 p = geometry::point_at(task.trajectory[pt.primitive], pt.s);
        const Vec2 e0 = initial_elbow(start, p, sigma);
        const std::string where = at(pt);
        const int ex = qp.add_variable(-kInfinity, kInfinity, e0.x(), "elbow.x " + where);
        const int ey = qp.add_variable(-kInfinity, kInfinity, e0.y(), "elbow.y " + where);

        // eq. (11): |e - b| = r1 and |p - e| = r2.
        Quadratic link1;
        link1.add(ex, ex, 1.0).add(ey, ey, 1.0).add(bx, bx, 1.0).add(by, by, 1.0);
        link1.add(ex, bx, -2.0).add(ey, by, -2.0).add(f.r1, f.r1, -1.0);
        qp.add_constraint(link1, 0.0, 0.0, "link 1 length " + where);
        Quadratic link2;
        link2.add(ex, ex, 1.0).add(ey, ey, 1.0).add(ex, -2.0 * p.x()).add(ey, -2.0 * p.y());
        link2.add(p.squaredNorm()).add(f.r2, f.r2, -1.0);
        qp.add_constraint(link2, 0.0, 0.0, "link 2 length " + where);

        // eqs. (5) and (8) in one: sigma * cross(e - b, p - b) >= k * r1.
        // The cross product is r1 * (height of p above link 1), so this
        // keeps the elbow on its branch, away from the singular straight and
        // folded poses, and the EE at least k from the line of link 1 (a
        // bound on its distance from the link segment).
        Quadratic side;
        side.add(ex, sigma * p.y()).add(ey, -sigma * p.x());
        side.add(bx, -sigma * p.y()).add(by, sigma * p.x());
        side.add(ex, by, -sigma).add(ey, bx, sigma);
        side.add(f.r1, -k_self);
        qp.add_constraint(side, 0.0, kInfinity, "elbow side " + where);

        if (problem.swept != SweptVolume::Sampled) continue;
        for (std::size_t o = 0; o < task.obstacles.size(); ++o) {
            const task::Obstacle& ob = task.obstacles[o];
            const double need = ob.radius + half;
            struct Link {
                int ax, ay, bx, by;
                Vec2 a0, b0, a_const, b_const;
            };
            const Link links[2] = {
                {bx, by, ex, ey, start.base, e0, Vec2::Zero(), Vec2::Zero()},
                {ex, ey, -1, -1, e0, p, Vec2::Zero(), p},
            };
            for (int k = 0; k < 2; ++k) {
                const Link& l = links[k];
                if (geometry::point_segment(ob.center, l.a0, l.b0) - need > problem.obstacle_horizon)
                    continue;
                const Vec2 n0 = away_from(ob.center, l.a0, l.b0);
                const std::string tag = "obstacles[" + std::to_string(o) + "] link " +
                                        std::to_string(k + 1) + " " + where;
                const int nx = qp.add_variable(-1.0, 1.0, n0.x(), "normal.x " + tag);
                const int ny = qp.add_variable(-1.0, 1.0, n0.y(), "normal.y " + tag);
                qp.add_constraint(separation(nx, ny, l.ax, l.ay, l.a_const, ob.center), need,
                                  kInfinity, "clearance " + tag);
                qp.add_constraint(separation(nx, ny, l.bx, l.by, l.b_const, ob.center), need,
                                  kInfinity, "clearance " + tag);
                qp.add_constraint(unit_ball(nx, ny), -kInfinity, 1.0, "unit normal " + tag);
            }
        }
    }

    if (problem.swept == SweptVolume::Over) {
        // conv(disc(b, r1) and primitive j) holds the whole arm during j.
        for (std::size_t j = 0; j < task.trajectory.size(); ++j) {
            const geometry::Primitive& prim = task.trajectory[j];
            for (std::size_t o = 0; o < task.obstacles.size(); ++o) {
                const task::Obstacle& ob = task.obstacles[o];
                const double need = ob.radius + half;
                const std::string tag =
                    "obstacles[" + std::to_string(o) + "] trajectory[" + std::to_string(j) + "]";
                const Vec2 mid = geometry::point_at(prim, geometry::length(prim) / 2);
                const Vec2 n0 = away_from(ob.center, start.base, mid);
                const int nx = qp.add_variable(-1.0, 1.0, n0.x(), "sv normal.x " + tag);
                const int ny = qp.add_variable(-1.0, 1.0, n0.y(), "sv normal.y " + tag);
                qp.add_constraint(separation(nx, ny, bx, by, Vec2::Zero(), ob.center).add(f.r1, -1.0),
                                  need, kInfinity, "SV disc " + tag);
                if (prim.kind == geometry::PrimitiveKind::Line) {
                    for (const Vec2& v : {prim.start, prim.end})
                        qp.add_constraint(separation(nx, ny, -1, -1, v, ob.center), need, kInfinity,
                                          "SV primitive " + tag);
                } else {
                    // The arc lies in its circle's disc: a sound, simpler bound.
                    qp.add_constraint(
                        separation(nx, ny, -1, -1, prim.center, ob.center).add(-prim.radius), need,
                        kInfinity, "SV primitive " + tag);
                }
                qp.add_constraint(unit_ball(nx, ny), -kInfinity, 1.0, "SV unit normal " + tag);
            }
        }
    }
    qp.finalize();
    return f;
}

kinematics::Robot robot_from(const Formulation& f, const std::vector<double>& x) {
    kinematics::Robot robot;
    robot.base = Vec2(x[f.base_x], x[f.base_y]);
    robot.link_lengths = {x[f.r1], x[f.r2]};
    robot.link_diameter = f.link_diameter;
    robot.elbow = f.elbow;
    return robot;
}

}  // namespace modsynth::nlp
