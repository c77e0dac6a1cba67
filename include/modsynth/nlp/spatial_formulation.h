#pragma once
// The spatial refinement as a reduced nonlinear program, for an arm of any
// family (kinematics/arm_model.h): its variables are the design alone (the
// base in its box, the family's lengths and offsets and, where the family
// has them, its free numbers at the start and the end of each primitive);
// the pose at each point of the path comes from the family's closed-form
// IK, and the constraints' derivatives by forward-mode automatic
// differentiation through it. Constraints at each point: the family's pose
// limits (an elbow kept from its fold, the path off a yaw axis), the
// chain's self-collision rules and every clearance part clear of the
// obstacles near it, each with a margin; and once, the family's linear
// conditions on the design. The objective is the chain's length.
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <modsynth/geometry/vec3.h>
#include <modsynth/kinematics/arm_model.h>
#include <modsynth/nlp/smooth_program.h>
#include <modsynth/task/spatial_task.h>

namespace modsynth::nlp {

/// Where the refinement constrains the arm: arc length s of primitive j
/// (index in the task's trajectory), or, in the transition after primitive
/// j, fraction t of the free numbers' sweep (EE held at the join).
struct SpatialPoint {
    int primitive = 0;
    double s = 0.0;
    bool transition = false;
    double t = 0.0;
};

/// What each constraint keeps beyond the rule, so that the motion between
/// the constrained points and the certified verifier's bounds have room.
struct SpatialMargins {
    /// |cos| of an elbow at most this (kinematics::PoseMargins).
    double elbow_cos = 0.97;
    /// m: the path's distance from a yaw axis, at least.
    double axis = 0.05;
    /// m beyond the link diameter, for the self-collision rules.
    double self = 0.002;
    /// m beyond half the link diameter, for obstacle clearance.
    double clearance = 0.002;
    /// m: at each point, a (part, obstacle) pair farther apart than this in
    /// the start design is left out of the program; the verifier's
    /// counterexamples bring it back where the design comes near.
    double near = 0.15;
    /// Weight of the squared changes of the free numbers at joins in the
    /// objective: a transition costs time, and without it the numbers at a
    /// join are free to differ for nothing.
    double sweep_weight = 1e-3;

    kinematics::PoseMargins pose() const { return {elbow_cos, axis}; }
};

/// What the program needs of the design's family, besides its poses.
struct FamilyBounds {
    std::vector<std::pair<double, double>> values;  ///< per value of the shape
    std::pair<double, double> along{0.0, 0.0};      ///< per free number
    std::vector<double> length_weights;             ///< the chain's length per value
    std::vector<kinematics::DesignRow> rows;        ///< once, on the design alone
};

struct SpatialProblem {
    const task::SpatialTask* task = nullptr;
    /// The skeleton (family, joint count, variant, branches per stroke) and
    /// the design the solve starts from.
    kinematics::ArmDesign start;
    FamilyBounds family;
    /// The base region of the skeleton; empty (nullopt) when the base may
    /// be anywhere.
    std::optional<geometry::Box3> base_box;
    std::vector<SpatialPoint> points;
    SpatialMargins margins;
};

class SpatialFormulation : public SmoothProgram {
public:
    /// Throws std::invalid_argument when the problem does not fit its task
    /// (bounds or free numbers missing, a branch per stroke missing).
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
    kinematics::ArmDesign design(const std::vector<double>& x) const;
    /// The variables of a design of this skeleton.
    std::vector<double> variables(const kinematics::ArmDesign& design) const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace modsynth::nlp
