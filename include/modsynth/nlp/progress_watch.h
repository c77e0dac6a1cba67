#pragma once
// Telling a doomed refinement early. Ipopt's own limits are checked only
// between iterations on CPU time, and an iterate whose duals grow without
// bound makes each factorisation slower than the last: a refinement of a
// wrong elbow branch could spend a minute on a dozen iterations before its
// time limit was ever looked at. The watch sees each iterate's primal and
// dual infeasibility and says when to stop: the duals diverge while the
// primal infeasibility stays put, or the primal infeasibility has stayed
// flat (and far from feasible) for a window of iterations. A healthy solve
// moves its primal infeasibility by orders of magnitude, up as well as down.
#include <deque>
#include <string>

namespace modsynth::nlp {

struct ProgressWatchOptions {
    /// Dual infeasibility past which the iterates count as diverging (the
    /// problem is scaled like lengths in m: healthy solves stay below 1e3).
    double diverging_dual = 1e8;
    /// Primal infeasibility (m or m^2) above which a solve may be stalled;
    /// below it the solve is close and is left to finish.
    double stalled_primal = 1e-3;
    /// Iterations over which the primal infeasibility must move by more than
    /// the flat ratio (largest over smallest in the window).
    int stall_window = 10;
    double flat_ratio = 1.25;
    /// A diverging solve gets this many iterations to show primal progress.
    int diverging_window = 5;
    /// Programs with fewer variables are left to finish whatever the
    /// watch says: their iterations stay cheap, and the signs are sometimes
    /// wrong (Ipopt can recover from huge duals), so stopping them saves
    /// little and may lose a robot.
    int min_variables = 500;

    bool IsValid(std::string* error) const;
};

/// Fed one iterate at a time (regular iterations only: restoration has a
/// problem of its own); `doomed()` then names why to stop, or is empty.
class ProgressWatch {
public:
    explicit ProgressWatch(ProgressWatchOptions options = {});

    /// Takes iterate `iteration` (0, 1, ...) with its infeasibilities.
    void observe(int iteration, double primal_infeasibility, double dual_infeasibility);
    /// Why the solve should stop now ("" while it should go on).
    const std::string& doomed() const { return reason_; }

private:
    ProgressWatchOptions o_;
    std::string reason_;
    std::deque<double> window_;  ///< the last stall_window + 1 primal infeasibilities
    int diverging_since_ = -1;   ///< first iteration with diverging duals, or -1
    double primal_then_ = 0.0;   ///< primal infeasibility at diverging_since_
};

}  // namespace modsynth::nlp
