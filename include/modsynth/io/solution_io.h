#pragma once
// Reading and writing modsynth-solution/1 documents (formats.md): what
// `solve` writes, and what `export`, `batch` and the server read back. Every
// reader validates fully and throws task::InputError naming the JSON path of
// the offending part ("samples[12].q[1]").
#include <string>
#include <string_view>

#include <nlohmann/json_fwd.hpp>

#include <modsynth/synth/solution.h>
#include <modsynth/task/input_error.h>
#include <modsynth/task/spatial_task.h>
#include <modsynth/task/task.h>

namespace modsynth::io {

struct ParsedSolution {
    synth::Solution solution;
    /// The document carried a "certificate" (optional: other tools may not
    /// write one). Without it solution.certificate is default (not ok).
    bool has_certificate = false;
};

ParsedSolution parse_solution(const nlohmann::json& doc);
/// Parses JSON text; syntax errors name the line and column.
ParsedSolution parse_solution_text(std::string_view text);
/// Reads and parses a file; an unreadable file is an InputError too.
ParsedSolution load_solution(const std::string& path);

/// Throws InputError when the solution cannot belong to the task: another
/// task's name, a spatial robot (`dh`) for a planar task or a planar one for
/// a spatial task, or samples tracing primitives the task does not have.
void check_solution_fits(const task::Task& task, const synth::Solution& solution);
void check_solution_fits(const task::SpatialTask& task, const synth::Solution& solution);

nlohmann::json to_json(const synth::Solution& solution);
/// A spatial solution's `robot`: {"dof", "base": [x, y, z], "dh": [{"a",
/// "alpha", "d"}, ...], "link_diameter"} (formats.md "Spatial tasks").
nlohmann::json to_json(const kinematics::DhChain& chain);
/// The witnesses of an obstacle proof, as in "explanation.separation" and
/// "explanation.geodesic" (formats.md).
nlohmann::json to_json(const prove::SeparationWitness& witness);
nlohmann::json to_json(const prove::GeodesicWitness& witness);
nlohmann::json to_json(const prove::EnclosureWitness& witness);
/// Adds to `out` the keys "separation", "geodesic" and "enclosure" that `e`
/// carries.
void add_witnesses(const synth::Explanation& e, nlohmann::json& out);
/// Writes the document atomically; throws std::runtime_error naming the
/// path on failure.
void write_solution(const synth::Solution& solution, const std::string& path);

}  // namespace modsynth::io
