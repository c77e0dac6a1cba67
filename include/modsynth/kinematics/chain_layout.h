#pragma once
// The chains modsynth designs (paper III-A): a distal pair of links traces
// the path, turning about the base (two joints) or about the end of a
// proximal link that stands still while a primitive is traced and moves
// only between primitives (three joints). Every stage asks here which of
// the two a joint count is, rather than comparing it with 2 or 3.

namespace modsynth::kinematics {

/// Links of the distal pair, the one that traces.
inline constexpr int kDistalLinks = 2;

/// True when a chain of `dof` joints has the static proximal link (three
/// joints); false for the distal pair alone (two).
constexpr bool has_proximal_link(int dof) { return dof == kDistalLinks + 1; }

/// The joint counts a task may ask for.
constexpr bool is_supported_dof(int dof) { return dof == kDistalLinks || has_proximal_link(dof); }

}  // namespace modsynth::kinematics
