#pragma once
// `--parts DIR` of solve and export: the printed parts of a solved arm
// (parts/printed_parts.h) written for the modules chosen for it, and the
// modules chosen again with the printed links' masses in the dynamics in
// place of the tubes' (hardware/arm_model.h, hardware/dh_arm_model.h), until
// the choice holds.
#include <optional>
#include <string>
#include <vector>

#include <modsynth/hardware/catalog.h>
#include <modsynth/parts/printed_parts.h>
#include <modsynth/synth/solution.h>
#include <modsynth/task/spatial_task.h>
#include <modsynth/task/task.h>

namespace modsynth::output {

/// The most rounds of printing and choosing: a link sized for a stronger
/// module is heavier, which may call for a stronger module inwards.
inline constexpr int kPartsRounds = 3;

/// For a solved planar solution with modules chosen: writes the parts to
/// `folder` (prepare_parts_folder first) and, when they were rendered,
/// sets solution.modules to the choice with the printed links. None, and
/// a line in `notes`, when there is nothing to print (not solved, no
/// catalog, no modules chosen).
std::optional<parts::PrintedParts> export_parts(const task::Task& task,
                                                const std::optional<hardware::Catalog>& catalog,
                                                synth::Solution& solution,
                                                const std::string& folder,
                                                std::vector<std::string>& notes);

/// The same for a solved spatial solution (parts::dh_links): each printed
/// link replaces the tube of its link's a part in the dynamics
/// (hardware/dh_arm_model.h); the d tubes and the brackets stay.
std::optional<parts::PrintedParts> export_parts(const task::SpatialTask& task,
                                                const std::optional<hardware::Catalog>& catalog,
                                                synth::Solution& solution,
                                                const std::string& folder,
                                                std::vector<std::string>& notes);

/// The build sheet's section: the files and what their checks found, the
/// print settings, the screws, the links' masses.
std::string printed_parts_section(const parts::PrintedParts& parts);

}  // namespace modsynth::output
