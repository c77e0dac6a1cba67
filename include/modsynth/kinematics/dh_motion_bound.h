#pragma once
// How far a point of a DH chain strays from its chord while the joints move
// linearly from one sample to the next (docs/verification.md, "Spatial
// chains"): the bound that makes a check at the samples a proof for the
// continuous motion.
#include <vector>

#include <modsynth/kinematics/dh_chain.h>

namespace modsynth::kinematics {

/// Along q(tau) = q_a + tau dq, tau in [0, 1], a point p rigidly attached to
/// the chain and moved by joints frame + 1 .. last_joint (1-based; a point
/// of link m's a part has last_joint = m, one of its d part m - 1, which
/// lies on joint m's axis), seen from frame `frame` (0: the world; k: moving
/// with link k), lying at most `reach` m along the chain from the base,
/// stays within the returned distance of its chord
/// (1 - tau) p(0) + tau p(1):
///     |p''| <= E = sum_i |dq_i| (2 A_i L_i + sum_{j >= i} |dq_j| L_j),
/// over the moving joints i, j, with A_i = sum_{j < i} |dq_j| and L_i the
/// chain length from o_{i-1} to `reach`, and |p - chord| <= E / 8.
double chord_gap(const DhChain& chain, const std::vector<double>& dq, int frame, int last_joint,
                 double reach);

}  // namespace modsynth::kinematics
