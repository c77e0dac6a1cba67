#pragma once
// A yaw-pitch arm together with how it traces a path: the IK branch of each
// stroke and, with four to six joints, the absolute pitch of each hand link
// at the start and the end of each primitive (varied linearly in between).
// This is what the spatial refinement designs and the spatial motion
// follows.
#include <vector>

#include <modsynth/kinematics/yaw_pitch_ik.h>

namespace modsynth::kinematics {

/// The absolute pitch (rad, q_2 + ... + q_k) of one hand link at the start
/// and the end of a primitive.
struct HandPitch {
    double start = 0.0;
    double end = 0.0;
};

struct YawPitchDesign {
    YawPitchArm arm;
    double link_diameter = 0.0;
    /// One per stroke: a three-joint arm cannot change branch while its EE
    /// holds a point, and between strokes the travel may change it.
    std::vector<IkBranch> branches;
    /// Per primitive (numbered as in the task's trajectory), one per hand
    /// link (links 4..n); empty lists with three joints.
    std::vector<std::vector<HandPitch>> pitches;

    int hand_links() const { return arm.dof() - 3; }
    DhChain chain() const { return to_chain(arm, link_diameter); }
    /// The hand pitches at fraction u in [0, 1] of primitive j.
    std::vector<double> hand_pitches_at(int j, double u) const {
        std::vector<double> out;
        if (pitches.empty()) return out;
        for (const HandPitch& h : pitches[static_cast<std::size_t>(j)])
            out.push_back(h.start + u * (h.end - h.start));
        return out;
    }
};

}  // namespace modsynth::kinematics
