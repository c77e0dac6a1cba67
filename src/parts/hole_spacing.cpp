#include <modsynth/parts/hole_spacing.h>

#include <cmath>

#include <modsynth/text/format.h>

namespace modsynth::parts {

namespace {

using geometry::Vec2;

/// Two diameters (m) count as one within this: OpenSCAD's 96-gon is
/// 0.07 % short of its circle's area.
constexpr double kDiameterTolerance = 1e-4;

}  // namespace

std::vector<SectionLoop> section_loops(const Mesh& mesh, double z) {
    std::vector<SectionLoop> out;
    for (const auto& loop : section(mesh, z)) {
        double area = 0.0;
        Vec2 moment = Vec2::Zero();
        for (std::size_t i = 0; i < loop.size(); ++i) {
            const Vec2& a = loop[i];
            const Vec2& b = loop[(i + 1) % loop.size()];
            const double c = geometry::cross(a, b);
            area += c / 2.0;
            moment += c / 6.0 * (a + b);
        }
        if (area == 0.0) continue;
        out.push_back({moment / area, 2.0 * std::sqrt(std::abs(area) / geometry::kPi)});
    }
    return out;
}

SpacingCheck check_spacing(const Mesh& mesh, const LinkDesign& link) {
    SpacingCheck out;
    out.expected = link.length;
    // Through the end plates, clear of their faces (which hold vertices).
    const double z_mm = 0.4817 * link.beam.plate * 1000.0;
    const std::vector<SectionLoop> loops = section_loops(mesh, z_mm);
    const auto find = [&](double diameter, const char* what, std::optional<Vec2>& at) {
        int found = 0;
        for (const auto& l : loops) {
            if (std::abs(l.diameter / 1000.0 - diameter) > kDiameterTolerance) continue;
            at = l.centre / 1000.0;
            ++found;
        }
        if (found == 1) return true;
        out.message = text::format(
            "link %d: %d loops of the %s's diameter (%.2f mm) in the section "
            "at z = %.2f mm, not 1",
            link.index, found, what, diameter * 1000.0, z_mm);
        return false;
    };
    std::optional<Vec2> horn, axis;
    if (!find(link.horn_bore, "horn bore", horn) ||
        !find(link.axis_hole, link.body ? "axis hole" : "rod hole", axis))
        return out;
    out.measured = (*axis - *horn).norm();
    out.ok = std::abs(out.measured - out.expected) <= kSpacingTolerance;
    out.message = text::format("link %d: axes %.4f mm apart in the mesh, link length %.4f mm%s",
                               link.index, out.measured * 1000.0, out.expected * 1000.0,
                               out.ok ? "" : " (more than 0.1 mm off)");
    return out;
}

}  // namespace modsynth::parts
