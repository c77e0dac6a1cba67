#pragma once
// Closed-form inverse kinematics of the chain the spatial search proposes
// first: a yaw column then pitch links. Row 1 is the column (a_1 = 0,
// d_1 > 0, alpha_1 = +-pi/2), rows 2..n are pitch links (alpha_k = 0,
// d_k = 0, a_k > 0), so every pitch joint turns about the same horizontal
// axis z_1 and the links stay in the vertical plane through the column at
// yaw q_1. With three joints the EE fixes the pose up to two branches; with
// four to six the absolute pitches of the hand links (links 4..n) are given
// and the wrist point (the end of link 3) is solved with the 3-joint IK, as
// a tool held at a pitch.
#include <optional>
#include <vector>

#include <modsynth/kinematics/dh_chain.h>

namespace modsynth::kinematics {

/// The pattern, read off a DhChain.
struct YawPitchArm {
    geometry::Vec3 base = geometry::Vec3::Zero();
    double column = 0.0;        ///< d_1
    int column_twist = 1;       ///< sign of alpha_1: +1 (pitch up is +q) or -1
    std::vector<double> links;  ///< a_2 .. a_n
    int dof() const { return 1 + static_cast<int>(links.size()); }
    /// The shoulder: the top of the column, where the pitch links turn.
    geometry::Vec3 shoulder() const { return base + geometry::Vec3(0.0, 0.0, column); }
};

/// The chain as a yaw-pitch arm, when it has that pattern (within 1e-9) and
/// 3 to 6 joints; std::nullopt otherwise.
std::optional<YawPitchArm> as_yaw_pitch(const DhChain& chain);
DhChain to_chain(const YawPitchArm& arm, double link_diameter);

/// The branches: the shoulder faces the EE (+1, q_1 is the EE's azimuth
/// about the column) or reaches over backwards (-1, q_1 + pi); the elbow is
/// the sign of q_3.
struct IkBranch {
    int shoulder = 1;
    int elbow = 1;
};

/// Where the IK gives up rather than return a pose that rounding makes
/// meaningless: near the shoulder singularity (the EE on the column's axis,
/// where q_1 is undefined) and near the elbow's fold and full stretch (where
/// q_3 = +-acos(c) loses all precision as |c| -> 1).
struct IkOptions {
    /// m: least distance of the EE from the column's axis.
    double min_axis_distance = 1e-6;
    /// Largest |cos q_3| accepted.
    double max_elbow_cos = 1.0 - 1e-9;
};

/// The joint angles that put the EE at `target` on `branch`. With more than
/// three joints, `hand_pitches[i]` is the absolute pitch of link 4 + i,
/// q_2 + ... + q_{4+i} (one per hand link). std::nullopt when the target is
/// out of reach or near a singularity. Throws std::invalid_argument when
/// hand_pitches does not hold one pitch per hand link.
std::optional<std::vector<double>> yaw_pitch_ik(const YawPitchArm& arm,
                                                const geometry::Vec3& target, IkBranch branch,
                                                const std::vector<double>& hand_pitches = {},
                                                const IkOptions& options = {});

}  // namespace modsynth::kinematics
