#pragma once
// The SVG layers of the report, bottom to top. Every element that stands
// for a part of the task carries data-part with its name as in formats.md
// ("obstacles[1]"), and class "core" when the explanation names it.
#include <string>
#include <vector>

#include <modsynth/task/part.h>

#include "plot.h"

namespace modsynth::output::layers {

using Core = std::vector<task::TaskPart>;

/// True when `part` (base_regions[0]) is named by the core, itself or
/// through a part that holds it (base_regions).
bool in_core(const Core& core, const task::TaskPart& part);

/// Obstacle-free reachable space: one path for a 2-joint arm, one per
/// primitive (data-primitive) for a 3-joint arm. `caption` says what it shows.
std::string reachable(const task::Task& task, const synth::Solution& s, const plot::Frame& f,
                      std::string* caption);
/// The region each primitive's motion sweeps (and each transition's).
std::string swept(const task::Task& task, const synth::Solution& s, const plot::Frame& f);
/// Dashed, the end-effector's way between strokes (the travel moves).
std::string travel(const synth::Solution& s, const plot::Frame& f);
std::string base_regions(const task::Task& task, const plot::Frame& f, const Core& core);
/// Each obstacle, and dashed the limit a link's axis must keep out of.
std::string obstacles(const task::Task& task, const plot::Frame& f, double diameter,
                      const Core& core);
std::string trajectory(const task::Task& task, const plot::Frame& f, const Core& core);
/// The arm at the start of each primitive.
std::string poses(const task::Task& task, const synth::Solution& s, const plot::Frame& f);
/// The animated arm, drawn at the start pose, and the end-effector's trail.
std::string robot(const synth::Solution& s, const plot::Frame& f);
/// When the core names robot.max_link_length: the farthest any allowed arm
/// reaches from the base regions (each grown by dof * max_link_length).
std::string reach_limit(const task::Task& task, const plot::Frame& f, const Core& core);
/// The proof of an obstacle-infeasible task, over the task: each closed
/// wall (the no-go discs of its cycle, the polygon through their centres,
/// and where neighbours overlap, data-pair "i-j") or each detour (the route
/// of segments and arcs, labelled with its length against the reach), and
/// the path point it is about. Empty without such a witness.
std::string proof(const task::Task& task, const synth::Solution& s, const plot::Frame& f);
std::string scale_bar(const plot::Frame& f);

}  // namespace modsynth::output::layers
