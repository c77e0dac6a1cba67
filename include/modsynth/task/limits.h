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
/// Size of a solution file, in bytes. A solution's samples take about 200
/// bytes each and a run plans at most 250,000 trace samples
/// (SynthesisOptions::trace_samples) plus its transitions and travels:
/// well within this, and what is read stays within the memory above.
constexpr std::size_t kMaxSolutionBytes = 256u << 20;

}  // namespace modsynth::task
