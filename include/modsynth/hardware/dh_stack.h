#pragma once
// How a spatial arm (a DH chain, formats.md "Spatial tasks") is built from
// modules, tubes and brackets: what the build sheet lists, the URDF draws
// and the arm's mass model carries, so that what is cut is what is
// simulated.
//
// Module k's housing is a box centred on its joint's point o_{k-1}, its
// height along the joint axis z_{k-1}, its length along x_{k-1} and its
// width along y_{k-1}; it rides on link k - 1 (module 1 on the base). Each
// non-zero segment of the chain (the d part, then the a part, of each link)
// is a tube of the link diameter. Where a link has both, a right-angle
// bracket joins its two tubes at the corner. Module k + 1 is mounted on the
// end of link k with a tube adapter when the twist alpha_k is 0 (or pi: the
// same adapter, the module turned over), a right-angle bracket when it is
// +-pi/2, and a bracket made for the angle otherwise. The last
// `tool_length` m of the chain are the tool.
//
// Positions are in the joint frame of a link: link k's frame k - 1 turned
// by q_k, so o_{k-1} is its origin, z joint k's axis and x the direction of
// a_k; the link's segments run from (0, 0, 0) to (0, 0, d_k) and on to
// (a_k, 0, d_k) = o_k, where frame k is turned by Rx(alpha_k).
#include <vector>

#include <modsynth/geometry/vec3.h>
#include <modsynth/kinematics/dh_chain.h>
#include <modsynth/task/spatial_task.h>

namespace modsynth::hardware {

/// One tube to cut: a segment of the chain less what the parts at its ends
/// take: cut_length = segment_length - proximal_allowance - distal_allowance.
struct DhTube {
    int link = 0;             ///< 0-based: a tube of link link + 1
    bool along_axis = false;  ///< the d part (along joint link + 1's axis), else the a part
    geometry::Vec3 from = geometry::Vec3::Zero();  ///< the segment's ends in the joint frame
    geometry::Vec3 to = geometry::Vec3::Zero();
    double segment_length = 0.0;
    /// At `from`: module link + 1's output (half its height along the axis,
    /// half its width across it) or the corner bracket (half the tube
    /// diameter), plus an adapter.
    double proximal_allowance = 0.0;
    /// At `to`: module link + 2's housing (as far as the tube's line runs
    /// inside it), or the corner bracket, plus an adapter; the tool at the
    /// chain's end.
    double distal_allowance = 0.0;
    double cut_length = 0.0;  ///< <= 0: the segment is too short for the hardware
    bool last = false;        ///< ends at the tool
};

/// How a module is fixed to the link that carries it.
enum class DhMountKind { TubeAdapter, RightAngleBracket, OtherBracket };

struct DhMount {
    int joint = 0;       ///< 1-based joint whose module is mounted (2 .. dof)
    double twist = 0.0;  ///< alpha of the link that carries it, rad
    DhMountKind kind = DhMountKind::TubeAdapter;
    bool on_tube = true;  ///< false: bolted straight to the previous module's output
};

struct DhStack {
    std::vector<DhTube> tubes;    ///< in chain order
    std::vector<DhMount> mounts;  ///< joints 2 .. dof
    /// 0-based links whose d and a tubes meet at a right-angle bracket.
    std::vector<int> corners;
};

/// Twists within this of 0, +-pi/2 or pi (rad) get the standard part.
inline constexpr double kTwistTolerance = 1e-6;

DhMountKind mount_kind(double twist);

DhStack dh_stack(const task::SpatialRobotSpec& spec, const kinematics::DhChain& chain);

/// The distance (m) from the centre of a box with half-sizes `half` along
/// its own axes to its surface along the unit direction `u` (in the box's
/// axes).
double box_exit(const geometry::Vec3& half, const geometry::Vec3& u);

}  // namespace modsynth::hardware
