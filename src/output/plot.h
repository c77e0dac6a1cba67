#pragma once
// The report's drawing surface: task-plane metres to SVG pixels (y up in
// the task, down on screen) and the few SVG snippets every layer uses.
#include <string>
#include <vector>

#include <modsynth/geometry/primitive.h>
#include <modsynth/synth/solution.h>
#include <modsynth/task/task.h>

namespace modsynth::output::plot {

using geometry::Vec2;

struct Frame {
    Vec2 min = Vec2::Zero();  ///< task-plane corner drawn at the bottom left
    Vec2 max = Vec2::Zero();
    double scale = 1.0;  ///< pixels per metre
    double pad = 24.0;   ///< pixels around the drawing
    double width() const { return (max.x() - min.x()) * scale + 2.0 * pad; }
    double height() const { return (max.y() - min.y()) * scale + 2.0 * pad; }
    Vec2 px(const Vec2& p) const {
        return {pad + (p.x() - min.x()) * scale, pad + (max.y() - p.y()) * scale};
    }
};

/// A frame that shows the whole task and every position the arm takes,
/// fitted into at most max_width x max_height pixels.
Frame fit_frame(const task::Task& task, const synth::Solution& solution, double max_width,
                double max_height);

/// Number with 2 decimals: a hundredth of a pixel.
std::string n2(double v);
/// "x,y" of a task-plane point in pixels.
std::string pt(const Frame& f, const Vec2& p);
/// Points along a primitive, dense enough to look smooth at the frame's scale.
std::vector<Vec2> polyline(const geometry::Primitive& p, const Frame& f);
/// Path data "M .. L .." through the points (closed with Z when asked).
std::string path_data(const Frame& f, const std::vector<Vec2>& points, bool closed);
/// One colour per primitive, repeating after ten.
std::string primitive_colour(int j);

}  // namespace modsynth::output::plot
