#include <modsynth/hardware/dh_dynamics.h>

#include <stdexcept>
#include <string>

#include <Eigen/Geometry>
#include <kdl/chain.hpp>
#include <kdl/chainidsolver_recursive_newton_euler.hpp>

namespace modsynth::hardware {

struct DhInverseDynamics::Impl {
    KDL::Chain chain;
    std::unique_ptr<KDL::ChainIdSolver_RNE> solver;
    unsigned dof = 0;
};

namespace {

KDL::Vector kdl(const geometry::Vec3& v) { return KDL::Vector(v.x(), v.y(), v.z()); }

/// A body given in the link's joint frame, as KDL wants it: in the
/// segment's tip frame (frame k = joint frame * f_tip).
KDL::RigidBodyInertia tip_inertia(const RigidBody& b, const KDL::Frame& f_tip) {
    const Eigen::Matrix3d& I = b.inertia;
    const KDL::RigidBodyInertia joint_frame(
        b.mass, kdl(b.com),
        KDL::RotationalInertia(I(0, 0), I(1, 1), I(2, 2), I(0, 1), I(0, 2), I(1, 2)));
    // T_a_b * I_b is I in frame a, T_a_b the pose of b in a: here a is the
    // tip frame and b the joint frame, whose pose in the tip frame is
    // f_tip's inverse.
    return f_tip.Inverse() * joint_frame;
}

}  // namespace

DhInverseDynamics::DhInverseDynamics(const DhArmModel& model) : impl_(std::make_unique<Impl>()) {
    const kinematics::DhChain& c = model.chain;
    if (model.links.size() != c.rows.size())
        throw std::invalid_argument("DhInverseDynamics: one body per joint");
    // Frame 0 is the task frame's axes moved to the base.
    impl_->chain.addSegment(KDL::Segment(KDL::Joint(KDL::Joint::None), KDL::Frame(kdl(c.base))));
    for (std::size_t k = 0; k < c.rows.size(); ++k) {
        const kinematics::DhRow& r = c.rows[k];
        const KDL::Frame f_tip = KDL::Frame::DH(r.a, r.alpha, r.d, 0.0);
        impl_->chain.addSegment(
            KDL::Segment(KDL::Joint(KDL::Joint::RotZ), f_tip, tip_inertia(model.links[k], f_tip)));
    }
    impl_->dof = impl_->chain.getNrOfJoints();
    impl_->solver = std::make_unique<KDL::ChainIdSolver_RNE>(impl_->chain, kdl(model.gravity));
}

DhInverseDynamics::~DhInverseDynamics() = default;

std::vector<double> DhInverseDynamics::torques(const std::vector<double>& q,
                                               const std::vector<double>& qd,
                                               const std::vector<double>& qdd) const {
    const unsigned n = impl_->dof;
    if (q.size() != n || qd.size() != n || qdd.size() != n)
        throw std::invalid_argument("inverse_dynamics: q, qd and qdd need " + std::to_string(n) +
                                    " entries each");
    KDL::JntArray jq(n), jqd(n), jqdd(n), tau(n);
    for (unsigned k = 0; k < n; ++k) {
        jq(k) = q[k];
        jqd(k) = qd[k];
        jqdd(k) = qdd[k];
    }
    const KDL::Wrenches no_external(impl_->chain.getNrOfSegments(), KDL::Wrench::Zero());
    const int status = impl_->solver->CartToJnt(jq, jqd, jqdd, no_external, tau);
    if (status < 0)
        throw std::runtime_error("inverse_dynamics: KDL's solver failed (" +
                                 std::string(impl_->solver->strError(status)) + ")");
    std::vector<double> out(n);
    for (unsigned k = 0; k < n; ++k) out[k] = tau(k);
    return out;
}

std::vector<double> inverse_dynamics(const DhArmModel& model, const std::vector<double>& q,
                                     const std::vector<double>& qd,
                                     const std::vector<double>& qdd) {
    return DhInverseDynamics(model).torques(q, qd, qdd);
}

}  // namespace modsynth::hardware
