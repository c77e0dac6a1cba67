#pragma once
// The largest task modsynth accepts. A robot arm that a workshop can build
// spans metres, not kilometres, and a path of a few thousand primitives
// already describes any real job (a dense engraving, a long weld seam); past
// these sizes the work and memory of the pipeline would grow without any
// design becoming possible. Within them memory stays well under 2 GB and
// every stage keeps to its time limit. Larger tasks are rejected naming the
// part and the cap.
#include <cstddef>

namespace modsynth::task {

/// Primitives in the trajectory.
constexpr std::size_t kMaxPrimitives = 5000;
/// Obstacles.
constexpr std::size_t kMaxObstacles = 1000;
/// Base regions.
constexpr std::size_t kMaxBaseRegions = 100;
/// Every coordinate lies within this many metres of the origin.
constexpr double kMaxCoordinate = 1000.0;
/// Radii and lengths (obstacle radius, link lengths and diameter, module
/// sizes), in metres.
constexpr double kMaxLength = 1000.0;
/// Size of a task file, in bytes.
constexpr std::size_t kMaxTaskBytes = 16u << 20;
/// Size of a solution file, in bytes. What is read stays within the memory
/// above: the reader keeps a sample, not the document's text or tree, per
/// sample (io/solution_io.h).
constexpr std::size_t kMaxSolutionBytes = 256u << 20;

/// The longest motion a solution holds, in seconds (32 years): a ROS 2
/// Duration holds its whole seconds in 32 bits, and no robot runs longer.
constexpr double kLongestMotion = 1e9;

/// The most bytes a timed sample of a motion of `dof` joints takes in a
/// solution file as io::write_solution lays it out, every number at its
/// longest (24 characters) and every index at 10 digits: 172 bytes of keys,
/// indices and time, and 30 per number (q, qd and qdd).
constexpr std::size_t max_sample_bytes(int dof) {
    return 180 + 90 * static_cast<std::size_t>(dof < 1 ? 1 : dof);
}

/// The most samples a motion of `dof` joints may have: the most whose
/// solution file stays within kMaxSolutionBytes whatever its numbers, with
/// room for the rest of the document (a task name as long as a task file
/// may be). So every solution a run writes can be read back; planning
/// stops there (control/motion.h, spatial_motion.h) and a longer motion is
/// answered "unknown" with the reason (synth/solve.h). 559,240 for three
/// joints, 349,525 for six.
constexpr std::size_t max_motion_samples(int dof) {
    return (kMaxSolutionBytes - kMaxTaskBytes) / max_sample_bytes(dof);
}

}  // namespace modsynth::task
