#pragma once
// What the drawing import targets share: one file, imported as `modsynth
// import` imports it (read, placed, every curve fitted, strokes ordered,
// the task written and read back, and placed on a plane and round a
// cylinder in space as `import --plane` and `--cylinder` place it) under a
// time limit. Every input is a
// task, an InputError with a short printable message, or a stop at the
// time limit; the import returns within the limit plus a margin, and what
// it returns is within the tolerance.
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

#include <algorithm>

#include <modsynth/drawing/import.h>
#include <modsynth/drawing/surface.h>
#include <modsynth/task/input_error.h>
#include <modsynth/task/limits.h>
#include <modsynth/text/printable.h>

#include "imported_task.h"

namespace modsynth::fuzz {

// Under the sanitizers an import runs several times slower than in a
// release build: this is a limit for the fuzzer, not the program's.
constexpr double kImportSeconds = 2.0;
// The cooperative deadline is checked between steps of bounded work: past
// the limit by more than this, an import has a loop that does not check it.
constexpr double kOverrun = 1.5;

[[noreturn]] inline void finding(const char* what, const std::string& detail) {
    std::fprintf(stderr, "import fuzzer: %s: %s\n", what, detail.c_str());
    std::abort();
}

inline void check_message(const std::string& message) {
    if (message.size() >= 1000 || text::printable(message, message.size()) != message)
        finding("a message that is long or not printable", text::printable(message, 200));
}

/// Imports with these options; false when the file states no units (then
/// the caller gives a scale).
inline bool import_once(std::string_view text, drawing::DrawingFormat format,
                        drawing::ImportOptions options) {
    using Clock = drawing::Clock;
    const auto start = Clock::now();
    options.deadline = start + std::chrono::duration_cast<Clock::duration>(
                                   std::chrono::duration<double>(kImportSeconds));
    const auto check_time = [&] {
        const double took = std::chrono::duration<double>(Clock::now() - start).count();
        if (took > kImportSeconds + kOverrun)
            finding("an import past its time limit", std::to_string(took) + " s");
    };
    try {
        const drawing::ImportResult r = drawing::import_drawing(text, format, options);
        check_time();
        if (!(r.deviation <= options.tolerance))
            finding("a deviation beyond the tolerance", std::to_string(r.deviation));
        // The task reader accepts what the import makes, or names the part.
        task::Task base;
        base.name = "fuzz";
        (void)app::imported_task_json(r, base);
        // On a tilted plane, and round a cylinder a half again as round as
        // the drawing is wide: the spatial reader accepts the tasks, or
        // names the part.
        task::SpatialTask space;
        space.name = "fuzz";
        const drawing::PlaneSurface plane = drawing::plane_surface({0, 0, 0, 0, 0.6, 0.8, 1, 0, 0});
        (void)app::imported_spatial_task_json(drawing::place_on_plane(r.strokes, plane), {}, space);
        const double radius =
            std::max(1.5 * drawing::drawing_width(r.strokes) / (2 * geometry::kPi), 1e-3);
        const drawing::CylinderSurface cylinder =
            drawing::cylinder_surface({0, 0, 0, 0.6, 0, 0.8, radius}, geometry::Vec3::UnitX());
        const drawing::PlacedStrokes wrapped = drawing::place_on_cylinder(
            r.strokes, cylinder, options.tolerance, task::kMaxPrimitives, options.deadline);
        check_time();
        if (!(wrapped.deviation <= options.tolerance))
            finding("a wrapping beyond the tolerance", std::to_string(wrapped.deviation));
        (void)app::imported_spatial_task_json(wrapped, {}, space);
    } catch (const task::InputError& e) {
        check_time();
        check_message(e.what());
        return e.part() != "--scale";
    } catch (const drawing::ImportTimeout& e) {
        check_time();
        check_message(e.what());
    }
    return true;
}

inline int import_one(const std::uint8_t* data, std::size_t size, drawing::DrawingFormat format) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    drawing::ImportOptions options;
    options.tolerance = 1e-4;
    if (!import_once(text, format, options)) {
        // A drawing without units: placed as millimetres, as a user would.
        options.placement.scale = 1e-3;
        import_once(text, format, options);
    }
    // The obstacle layers of the seeds, where a file names one: obstacles
    // are read, placed and checked against every stroke.
    const std::string layer = format == drawing::DrawingFormat::Svg ? "Obstacles" : "keepout";
    if (text.find(layer) != std::string_view::npos) {
        options.read.obstacle_layer = layer;
        import_once(text, format, options);
    }
    return 0;
}

}  // namespace modsynth::fuzz
