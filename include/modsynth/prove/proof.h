#pragma once
// A proof that a task is infeasible for every allowed robot: the task parts
// it rests on, the proof in words, and for an obstacle proof the witness a
// reader can re-check with nothing but the task.
#include <optional>
#include <string>
#include <vector>

#include <modsynth/prove/enclosure_witness.h>
#include <modsynth/prove/wall_witness.h>
#include <modsynth/task/part.h>

namespace modsynth::prove {

struct Proof {
    /// The task parts the proof needs, minimal where `minimal` says so:
    /// without any one of them the same kind of proof no longer holds.
    std::vector<task::TaskPart> core;
    std::string message;  ///< the proof in words (no "Proved infeasible: ")
    /// False when shrinking the core ran out of time (or was not given
    /// any): the core is then sound but may list parts the proof does not
    /// need.
    bool minimal = true;
    std::optional<SeparationWitness> separation;
    std::optional<GeodesicWitness> geodesic;
    /// A spatial task's closed shell (spatial_enclosure.h).
    std::optional<EnclosureWitness> enclosure;
};

}  // namespace modsynth::prove
