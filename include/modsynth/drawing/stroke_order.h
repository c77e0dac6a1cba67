#pragma once
// The order and direction in which the pen draws the strokes: pen-up
// travel between them is wasted time, so it is kept short (greedy nearest
// neighbour, then 2-opt); chains that touch become one stroke.
#include <vector>

#include <modsynth/geometry/primitive.h>

namespace modsynth::drawing {

using Chain = std::vector<geometry::Primitive>;

struct StrokeOrder {
    std::vector<Chain> strokes;
    double travel = 0.0;  ///< total pen-up distance, metres
};

/// Chains that end within this distance of the next one's start are drawn
/// without lifting the pen (formats.md joins primitives within 1e-6 m).
constexpr double kTouching = 1e-7;

/// keep_order: the chains as given, in order and direction (only touching
/// neighbours are joined).
StrokeOrder order_strokes(std::vector<Chain> chains, bool keep_order);

/// Pen-up distance of chains drawn in the given order.
double travel_length(const std::vector<Chain>& chains);

}  // namespace modsynth::drawing
