#pragma once
// Which of several certified robots for one task to return. Length is what
// the search minimises, but two designs a fraction of a millimetre apart
// are the same length to anyone building them, while one may pass 150 mm
// from the obstacles and the other 3 mm: between those, clearance decides,
// and between designs equal in both, the one whose motion takes least time
// (a user pays for every cycle of it).
#include <cstddef>
#include <limits>
#include <span>

namespace modsynth::synth {

/// A certified robot's figures of merit.
struct DesignMerit {
    double total_length = 0.0;  ///< m, sum of the link lengths
    double clearance = 0.0;     ///< m, certified margin to the obstacles
    /// s, its motion timed within the joint limits; infinity when not
    /// timed (then it never decides).
    double motion_time = std::numeric_limits<double>::infinity();
};

/// Motions within this share of the fastest count as equally fast: a
/// design is not traded for a fraction of a per cent of a cycle.
inline constexpr double kMotionTimeTie = 0.005;

/// The index of the design to return. Lengths or clearances closer than
/// `tie` m count as equal: of the designs at most `tie` longer than the
/// shortest, those with clearance within `tie` of the clearest among them
/// are the candidates; of those, the ones whose motion time is within
/// `time_tie` (a share) of the fastest, and the shortest of those is
/// returned (then the earlier). Measured from the shortest, the clearest
/// and the fastest, not from each other, so a chain of near-ties never
/// drifts. `designs` must not be empty.
std::size_t choose_design(std::span<const DesignMerit> designs, double tie,
                          double time_tie = kMotionTimeTie);

}  // namespace modsynth::synth
