#pragma once
// An arm family: a pattern of DH chains that modsynth designs in space (a
// yaw column with pitch links, a SCARA, ...), as a plug-in of the spatial
// search. A family knows which joint counts and twists it can use, its
// design variables and their bounds, its closed-form IK with its branches
// (kinematics::ArmModel), the front stage's conditions on its designs
// (smt/pattern.h), how to draw initial guesses, and how to read a design
// back from a DH chain. Adding a family is one folder under src/arms/ and
// one line in src/arms/families.cpp (docs/design.md "Adding an arm family").
#include <optional>
#include <random>
#include <string>
#include <string_view>
#include <vector>

#include <modsynth/geometry/vec3.h>
#include <modsynth/kinematics/arm_model.h>
#include <modsynth/smt/pattern.h>
#include <modsynth/task/spatial_task.h>

namespace modsynth::arms {

class Family;

/// The discrete choices of a spatial design, which the front stage hands to
/// the initial guesses and the refinement.
struct Skeleton {
    const Family* family = nullptr;
    int dof = 3;
    int variant = 0;       ///< the family's pattern choice (kinematics::ArmShape::variant)
    int base_region = -1;  ///< index in the task's base_regions, -1: anywhere
};

struct Bound {
    double lower = 0.0;
    double upper = 0.0;
};

/// What a family's front-stage conditions are written on.
struct PatternContext {
    const task::SpatialTask& task;
    int dof = 3;
    int variant = 0;
    /// Points sampled along each primitive (its ends among them).
    const std::vector<std::vector<geometry::Vec3>>& points;
    /// m (m^2 for squared atoms): every condition loosened by this, so that
    /// decimal rounding never rules a design out.
    double slack = 1e-7;
    kinematics::PoseMargins margins;
};

/// What a family draws initial guesses within.
struct DrawContext {
    const task::SpatialTask& task;
    int dof = 3;
    int variant = 0;
    geometry::Box3 base_box;  ///< where the base may stand
    /// A few points of the path, and the box round the whole path.
    std::vector<geometry::Vec3> probe;
    geometry::Vec3 path_min, path_max;
};

class Family : public kinematics::ArmModel {
public:
    /// The variants a chain of `dof` joints of this family may take under
    /// the task's robot spec (its twists above all), in the order the
    /// search tries them; empty when the family builds no such chain.
    virtual std::vector<int> variants(int dof, const task::SpatialRobotSpec& spec) const = 0;
    /// What the family needs of robot.twists, in words, for an answer that
    /// no family fits the task.
    virtual std::string_view needs() const = 0;
    /// "column up", "quill": a variant in words.
    virtual std::string describe_variant(int variant) const = 0;
    /// A design's numbers in words: "base (...), d1 0.3000, links ...".
    virtual std::string describe(const kinematics::ArmDesign& design) const = 0;

    /// Bounds of a design's values (kinematics::ArmShape::values) and of
    /// each of its free numbers per primitive end (ArmDesign::along).
    virtual std::vector<Bound> value_bounds(const task::SpatialRobotSpec& spec, int dof,
                                            int variant) const = 0;
    virtual Bound along_bound(int dof) const = 0;
    /// The chain's length, sum |a_k| + |d_k|, as weights of the values
    /// (what the refinement minimises; the signs of a variant are fixed).
    virtual std::vector<double> length_weights(int dof, int variant) const = 0;
    /// Linear conditions on a design alone that the values' bounds cannot
    /// say (a SCARA's EE height fixed by its offsets).
    virtual std::vector<kinematics::DesignRow> design_rows(const task::SpatialTask& task, int dof,
                                                           int variant) const = 0;
    /// Where the arm reaches from (its shoulder): the refinement also
    /// constrains each primitive's nearest and farthest points from it.
    virtual geometry::Vec3 reach_centre(const kinematics::ArmDesign& design) const = 0;

    /// The front stage's conditions on the designs of a skeleton: necessary
    /// for a design of the variant to reach every sampled point.
    virtual smt::Pattern pattern(const PatternContext& context) const = 0;
    /// The shape of one random candidate for the initial guesses (base in
    /// the box, design rows met), the `candidate`-th of a run; nothing when
    /// the draw found none.
    virtual std::optional<kinematics::ArmShape<double>> draw(const DrawContext& context,
                                                             std::mt19937& rng,
                                                             int candidate) const = 0;
    /// Free numbers per primitive end (ArmDesign::along) the guesses try,
    /// the same along a whole stroke; one empty list for families with
    /// none.
    virtual std::vector<std::vector<double>> along_grid(int dof, int variant) const = 0;

    /// The design a DH chain is, when it has this family's pattern.
    virtual std::optional<kinematics::ArmShape<double>> read(
        const kinematics::DhChain& chain) const = 0;
};

/// Every family, in the order the search tries them for a joint count.
const std::vector<const Family*>& families();

}  // namespace modsynth::arms
