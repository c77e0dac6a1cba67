#pragma once
// The spatial refinement as a reduced nonlinear program: its variables are
// the design alone (the base in its box, the column d_1, the pitch links
// a_2..a_n and, with four to six joints, each hand link's pitch at the
// start and the end of each primitive); the joint positions at each point
// of the path come from the closed-form IK of the skeleton's branch
// (kinematics/yaw_pitch_pose.h), and the constraints' derivatives by
// forward-mode automatic differentiation through it. Constraints at each
// point: the elbow kept from its fold and stretch, the path kept off the
// column's axis, the chain's self-collision rules and every clearance part
// clear of the obstacles near it, each with a margin. The objective is the
// chain's length, |d_1| + sum a_k.
#include <memory>
#include <string>
#include <vector>

#include <modsynth/geometry/vec3.h>
#include <modsynth/kinematics/yaw_pitch_design.h>
#include <modsynth/nlp/smooth_program.h>
#include <modsynth/task/spatial_task.h>

namespace modsynth::nlp {

/// Where the refinement constrains the arm: arc length s of primitive j
/// (index in the task's trajectory), or, in the transition after primitive
/// j, fraction t of the hand pitches' sweep (EE held at the join).
struct SpatialPoint {
    int primitive = 0;
    double s = 0.0;
    bool transition = false;
    double t = 0.0;
};

/// What each constraint keeps beyond the rule, so that the motion between
/// the constrained points and the certified verifier's bounds have room.
struct SpatialMargins {
    /// |cos q_3| at most this: the elbow stays 14 degrees from its fold and
    /// its stretch, where the joints would have to turn fast (and the IK
    /// loses precision).
    double elbow_cos = 0.97;
    /// m: the path's distance from the column's axis, at least (the yaw is
    /// undefined on it and turns fast near it).
    double axis = 0.05;
    /// m beyond the link diameter, for the self-collision rules.
    double self = 0.002;
    /// m beyond half the link diameter, for obstacle clearance.
    double clearance = 0.002;
    /// m: at each point, a (part, obstacle) pair farther apart than this in
    /// the start design is left out of the program; the verifier's
    /// counterexamples bring it back where the design comes near.
    double near = 0.15;
    /// Weight of the squared pitch changes at joins in the objective: a
    /// transition costs time, and without it the pitches at a join are
    /// free to differ for nothing.
    double sweep_weight = 1e-3;
};

struct SpatialProblem {
    const task::SpatialTask* task = nullptr;
    /// The skeleton (joint count, column twist, branches per stroke) and the
    /// design the solve starts from.
    kinematics::YawPitchDesign start;
    /// Sign of d_1: +1 the shoulder above the base, -1 below it (a hanging
    /// arm), 0 no column (d_1 = 0, the shoulder at the base).
    int column = 1;
    /// The base region of the skeleton; empty (nullopt) when the base may
    /// be anywhere.
    std::optional<geometry::Box3> base_box;
    std::vector<SpatialPoint> points;
    SpatialMargins margins;
};

class SpatialFormulation : public SmoothProgram {
public:
    /// Throws std::invalid_argument when the problem does not fit its task
    /// (a design of another pattern, branches or pitches missing).
    explicit SpatialFormulation(const SpatialProblem& problem);
    ~SpatialFormulation() override;

    int num_variables() const override;
    int num_constraints() const override;
    const std::vector<double>& variable_lower() const override;
    const std::vector<double>& variable_upper() const override;
    const std::vector<double>& start() const override;
    double constraint_lower(int m) const override;
    double constraint_upper(int m) const override;
    const std::string& constraint_label(int m) const override;
    const std::vector<Entry>& jacobian_structure() const override;
    double eval_objective(const double* x) const override;
    void eval_gradient(const double* x, double* grad) const override;
    void eval_constraints(const double* x, double* g) const override;
    void eval_jacobian(const double* x, double* values) const override;

    /// The design at x (the problem's skeleton with x's values).
    kinematics::YawPitchDesign design(const std::vector<double>& x) const;
    /// The variables of a design of this skeleton.
    std::vector<double> variables(const kinematics::YawPitchDesign& design) const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace modsynth::nlp
