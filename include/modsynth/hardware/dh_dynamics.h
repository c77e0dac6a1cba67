#pragma once
// Inverse dynamics of a spatial arm (hardware/dh_arm_model.h): Orocos KDL's
// recursive Newton-Euler solver (ChainIdSolver_RNE) on the DH chain with
// the arm's bodies and gravity, so that pitch joints carry the arm's
// weight. KDL stays behind this header.
#include <memory>
#include <vector>

#include <modsynth/hardware/dh_arm_model.h>

namespace modsynth::hardware {

class DhInverseDynamics {
public:
    explicit DhInverseDynamics(const DhArmModel& model);
    ~DhInverseDynamics();
    DhInverseDynamics(const DhInverseDynamics&) = delete;
    DhInverseDynamics& operator=(const DhInverseDynamics&) = delete;

    /// The joint torques (N m) that move the arm with joint angles q, rates
    /// qd and accelerations qdd (formats.md's DH angles). Each vector has one
    /// entry per joint; throws std::invalid_argument otherwise.
    std::vector<double> torques(const std::vector<double>& q, const std::vector<double>& qd,
                                const std::vector<double>& qdd) const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

/// One call of DhInverseDynamics(model).torques(q, qd, qdd).
std::vector<double> inverse_dynamics(const DhArmModel& model, const std::vector<double>& q,
                                     const std::vector<double>& qd, const std::vector<double>& qdd);

}  // namespace modsynth::hardware
