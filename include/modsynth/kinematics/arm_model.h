#pragma once
// An arm family's kinematics, as the refinement, the motion and the initial
// guesses use it whatever the family: a design is a few numbers (the base,
// the family's lengths and offsets, how each primitive is traced), and the
// family turns them into a DH chain, a pose with the EE at a point (in any
// scalar type, so that the refinement gets exact derivatives by automatic
// differentiation), and joint angles.
//
// The families themselves (a yaw column with pitch links, a SCARA, ...) are
// plug-ins of the arms stage (arms/family.h); this is the part of them the
// stages below need.
#include <optional>
#include <string_view>
#include <vector>

#include <modsynth/geometry/vec3.h>
#include <modsynth/kinematics/autodiff.h>
#include <modsynth/kinematics/dh_chain.h>

namespace modsynth::kinematics {

class ArmModel;

/// A design's numbers in any scalar type: what a pose is a function of.
template <class T>
struct ArmShape {
    int dof = 0;
    /// The family's discrete pattern (a column up, hanging or absent; a
    /// quill or none): the same for every design of a skeleton.
    int variant = 0;
    Point3<T> base;
    std::vector<T> values;  ///< the family's lengths and offsets, in its order
};

/// Where a pose puts its EE, and which way its tool should point there
/// (for families that hold the tool's direction).
template <class T>
struct PoseTarget {
    Point3<T> point;
    std::optional<Point3<T>> tool_axis;  ///< unit
};

/// A quantity of a pose that must stay within bounds for the pose to mean
/// anything (an elbow away from its fold, the EE off a yaw axis): the
/// refinement constrains it, the guesses score by it.
template <class T>
struct PoseLimit {
    T value;
    double lower = 0.0;
    double upper = 0.0;
    /// m per unit of value: how the guesses weigh a limit against the
    /// clearances (a cosine's margin times the shorter link).
    double scale = 1.0;
    const char* what = "";  ///< "elbow from its fold and stretch"
};

/// The chain in one pose.
template <class T>
struct ArmPose {
    /// The ends of the chain's segments in order from the base: segment k
    /// runs from points[k] to points[k + 1] (zero-length ones left out, as
    /// formats.md does), the EE is the last point.
    std::vector<Point3<T>> points;
    /// The 1-based link each segment belongs to (labels, blame).
    std::vector<int> links;
    /// The joints' centres, the frame origins o_0 .. o_{n-1} (formats.md
    /// "Joint bodies"): joint k turns about z_{k-1} through o_{k-1}.
    std::vector<Point3<T>> joints;
    std::vector<PoseLimit<T>> limits;
};

/// A linear condition on a design alone, lower <= base . b + values . v <=
/// upper (a SCARA's EE at the path's height): constrained once, not per
/// point.
struct DesignRow {
    geometry::Vec3 base = geometry::Vec3::Zero();
    std::vector<double> values;
    double lower = 0.0;
    double upper = 0.0;
    const char* what = "";
};

/// Pose limits' room: what each keeps beyond its rule, so that the motion
/// between constrained points and the verifier's bounds have room.
struct PoseMargins {
    /// |cos| of an elbow at most this: 14 degrees from its fold and its
    /// stretch, where the joints would have to turn fast (and the IK loses
    /// precision).
    double elbow_cos = 0.97;
    /// m: the EE's distance from a yaw axis, at least (the yaw is undefined
    /// on it and turns fast near it).
    double axis = 0.05;
};

/// A design of some family, and how it traces a task.
struct ArmDesign {
    const ArmModel* model = nullptr;
    ArmShape<double> shape;
    double link_diameter = 0.0;
    /// The IK branch of each stroke (the family's numbering): an arm cannot
    /// change branch while its EE holds a point; between strokes the travel
    /// may.
    std::vector<int> branches;
    /// Per primitive (numbered as in the task's trajectory): the family's
    /// free numbers of a pose (a hand link's pitch) at the primitive's start
    /// then at its end, varied linearly in between and swept in the
    /// transition to the next primitive's. Empty lists for families with
    /// none.
    std::vector<std::vector<double>> along;

    int dof() const { return shape.dof; }
    DhChain chain() const;
    /// The free numbers at fraction u of primitive j.
    std::vector<double> along_at(int j, double u) const;
    /// In the transition after primitive j, at fraction t of the sweep.
    std::vector<double> transition_along(int j, double t) const;
    /// Whether the free numbers change at the join after primitive j.
    bool sweeps_after(int j) const;
};

class ArmModel {
public:
    virtual ~ArmModel() = default;
    /// "yaw-pitch", "scara": how designs and progress name the family.
    virtual std::string_view name() const = 0;
    /// Free numbers per end of a primitive (ArmDesign::along), for a chain
    /// of `dof` joints of a variant.
    virtual int along_count(int dof, int variant) const = 0;
    /// IK branches (ArmDesign::branches take 0 .. count - 1).
    virtual int branch_count(int dof) const = 0;
    virtual DhChain chain(const ArmDesign& design) const = 0;
    /// The pose with the EE at the target on a branch. Near singularities
    /// the points stay finite: the limits say how far from them it is.
    virtual ArmPose<double> pose(const ArmShape<double>& shape, const PoseTarget<double>& target,
                                 int branch, const std::vector<double>& along,
                                 const PoseMargins& margins) const = 0;
    virtual ArmPose<AD> pose(const ArmShape<AD>& shape, const PoseTarget<AD>& target, int branch,
                             const std::vector<AD>& along, const PoseMargins& margins) const = 0;
    /// The joint angles of that pose, or nothing when the target is out of
    /// reach or too near a singularity for the angles to mean anything.
    virtual std::optional<std::vector<double>> joint_angles(
        const ArmDesign& design, const PoseTarget<double>& target, int branch,
        const std::vector<double>& along) const = 0;
};

}  // namespace modsynth::kinematics
