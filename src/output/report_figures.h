#pragma once
// The parts of a report's figures table and explanation that the planar
// and the 3-D report share: rows, lengths, margins, stage times, the
// certificate, and the section that says why there is no robot.
#include <functional>
#include <string>

#include <modsynth/output/report.h>
#include <modsynth/synth/solution.h>
#include <modsynth/task/part.h>

namespace modsynth::output::figures {

/// "12.3 mm" (metres in, millimetres out).
std::string mm(double metres, const char* format = "%.1f");
/// One row of the figures table, id'd for the tests and the page's script.
std::string row(const char* id, const std::string& name, const std::string& value);
/// "2.20 mm <what>", or "nothing to check" for an infinite margin.
std::string margin_text(double metres, const char* what);
/// Seconds per stage, or why a saved solution has none.
std::string stage_text(const ReportFigures& f);
/// Clearance, self-collision margin, deviation, joint step, and the
/// certificate's state and source; `clearance_beyond` says what the
/// clearance is measured beyond.
std::string certificate_rows(const synth::Solution& s, const ReportFigures& figures,
                             const char* clearance_beyond);
/// The figures table of a solution without a robot.
std::string failed_figures(const synth::Solution& s, const ReportFigures& figures);
/// The section id="explanation": the message, the core (each part named,
/// with `describe(part)` after it where that is not empty, under
/// `core_caption`), then `proof` (HTML).
std::string explanation(const synth::Solution& s, const char* core_caption,
                        const std::function<std::string(const task::TaskPart&)>& describe,
                        const std::string& proof);

}  // namespace modsynth::output::figures
