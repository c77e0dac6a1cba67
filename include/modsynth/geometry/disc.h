#pragma once
// A closed disc: what an obstacle is (formats.md), kept in geometry so that
// the arm's geometry can reason about obstacles without knowing tasks.
#include <modsynth/geometry/vec.h>

namespace modsynth::geometry {

struct Disc {
    Vec2 center = Vec2::Zero();
    double radius = 0.0;
};

}  // namespace modsynth::geometry
