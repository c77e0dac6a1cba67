#include <modsynth/hardware/dynamics.h>

#include <cmath>
#include <stdexcept>

namespace modsynth::hardware {
namespace {

using geometry::Vec2;

/// z-component of the cross product of two plane vectors.
double cross(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }
/// omega x v for an angular rate about z.
Vec2 perp(double omega, const Vec2& v) { return Vec2(-omega * v.y(), omega * v.x()); }

}  // namespace

std::vector<double> inverse_dynamics(const ArmModel& model, const std::vector<double>& q,
                                     const std::vector<double>& qd,
                                     const std::vector<double>& qdd) {
    const std::size_t n = model.link_lengths.size();
    if (model.links.size() != n || q.size() != n || qd.size() != n || qdd.size() != n)
        throw std::invalid_argument("inverse_dynamics: one body, q, qd and qdd per link");
    // Outward pass: the acceleration of each joint and of each centre of
    // mass. Gravity enters as an upward acceleration of the base, so that
    // the inward pass need not add weights.
    std::vector<Vec2> link(n), com_acc(n), com(n);
    std::vector<double> omega(n), alpha(n);
    Vec2 joint_acc = -model.gravity;
    double theta = 0.0, w = 0.0, a = 0.0;
    for (std::size_t k = 0; k < n; ++k) {
        theta += q[k];
        w += qd[k];
        a += qdd[k];
        omega[k] = w;
        alpha[k] = a;
        const Vec2 u(std::cos(theta), std::sin(theta));
        link[k] = model.link_lengths[k] * u;
        com[k] = model.links[k].com * u;
        com_acc[k] = joint_acc + perp(a, com[k]) - w * w * com[k];
        joint_acc += perp(a, link[k]) - w * w * link[k];
    }
    // Inward pass: the force and moment each joint passes to its link.
    std::vector<double> tau(n);
    Vec2 force = Vec2::Zero();  // what link k + 1 takes from link k, at joint k + 1
    double moment = 0.0;
    for (std::size_t k = n; k-- > 0;) {
        const LinkBody& b = model.links[k];
        const Vec2 f_inertial = b.mass * com_acc[k];
        moment += cross(link[k], force) + cross(com[k], f_inertial) + b.inertia * alpha[k];
        force += f_inertial;
        tau[k] = moment;
    }
    return tau;
}

}  // namespace modsynth::hardware
