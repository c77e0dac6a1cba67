#include <modsynth/synth/design_choice.h>

#include <algorithm>
#include <cassert>
#include <limits>
#include <stdexcept>

namespace modsynth::synth {

std::size_t choose_design(std::span<const DesignMerit> designs, double tie, double time_tie) {
    if (designs.empty()) throw std::invalid_argument("choose_design: no design to choose from");
    const auto shorter = [](const DesignMerit& a, const DesignMerit& b) {
        return a.total_length < b.total_length;
    };
    const double longest =
        std::min_element(designs.begin(), designs.end(), shorter)->total_length + tie;
    double clearest = -std::numeric_limits<double>::infinity();
    for (const DesignMerit& d : designs)
        if (d.total_length <= longest) clearest = std::max(clearest, d.clearance);
    // inf - tie == inf: among designs that meet no obstacle, length decides.
    const auto candidate = [&](const DesignMerit& d) {
        return d.total_length <= longest && d.clearance >= clearest - tie;
    };
    double fastest = std::numeric_limits<double>::infinity();
    for (const DesignMerit& d : designs)
        if (candidate(d)) fastest = std::min(fastest, d.motion_time);
    // Untimed designs (infinity) are all equally fast.
    const double slowest = fastest * (1.0 + time_tie);
    std::size_t chosen = designs.size();
    for (std::size_t i = 0; i < designs.size(); ++i) {
        const DesignMerit& d = designs[i];
        if (!candidate(d) || d.motion_time > slowest) continue;
        if (chosen == designs.size() || shorter(d, designs[chosen])) chosen = i;
    }
    // The shortest design is within the tie and, if it is not the
    // clearest, within the tie of it: something is always chosen.
    assert(chosen < designs.size());
    return chosen;
}

}  // namespace modsynth::synth
