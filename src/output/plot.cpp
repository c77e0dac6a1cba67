#include "plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <modsynth/kinematics/kinematics.h>
#include <modsynth/text/format.h>

namespace modsynth::output::plot {
namespace {

struct Bounds {
    Vec2 min = Vec2::Constant(1e300);
    Vec2 max = Vec2::Constant(-1e300);
    void add(const Vec2& p, double margin = 0.0) {
        min = min.cwiseMin(p - Vec2::Constant(margin));
        max = max.cwiseMax(p + Vec2::Constant(margin));
    }
};

void add_task(const task::Task& task, Bounds& b) {
    for (const auto& p : task.trajectory) {
        const double len = geometry::length(p);
        for (int i = 0; i <= 64; ++i) b.add(geometry::point_at(p, len * i / 64.0));
    }
    for (const auto& o : task.obstacles) b.add(o.center, o.radius);
    for (const auto& r : task.base_regions) {
        b.add(r.min);
        b.add(r.max);
    }
}

void add_motion(const synth::Solution& s, Bounds& b) {
    if (s.status != synth::Status::Solved) return;
    const double margin = s.robot.link_diameter / 2.0;
    for (const auto& x : s.samples) {
        for (const Vec2& j : kinematics::forward(s.robot.base, s.robot.link_lengths, x.q)) {
            b.add(j, margin);
        }
    }
}

}  // namespace

Frame fit_frame(const task::Task& task, const synth::Solution& solution, double max_width,
                double max_height) {
    Bounds b;
    add_task(task, b);
    add_motion(solution, b);
    const Vec2 size = (b.max - b.min).cwiseMax(Vec2::Constant(0.05));
    const Vec2 middle = (b.max + b.min) / 2.0;
    const Vec2 half = 0.54 * size;  // a little room around everything
    Frame f;
    f.min = middle - half;
    f.max = middle + half;
    f.scale = std::min((max_width - 2.0 * f.pad) / (2.0 * half.x()),
                       (max_height - 2.0 * f.pad) / (2.0 * half.y()));
    return f;
}

std::string n2(double v) {
    std::string s;
    text::append_fixed(s, v, 2);
    return s == "-0.00" ? "0.00" : s;
}

std::string pt(const Frame& f, const Vec2& p) {
    const Vec2 q = f.px(p);
    return n2(q.x()) + "," + n2(q.y());
}

std::vector<Vec2> polyline(const geometry::Primitive& p, const Frame& f) {
    const double len = geometry::length(p);
    int n = 1;
    switch (p.kind) {
        case geometry::PrimitiveKind::Line:
            break;
        case geometry::PrimitiveKind::Arc:
        case geometry::PrimitiveKind::Circle:
            n = std::clamp(static_cast<int>(std::ceil(len * f.scale / 3.0)), 8, 2000);
            break;
    }
    std::vector<Vec2> out;
    for (int i = 0; i <= n; ++i) out.push_back(geometry::point_at(p, len * i / n));
    return out;
}

std::string path_data(const Frame& f, const std::vector<Vec2>& points, bool closed) {
    std::string d;
    for (std::size_t i = 0; i < points.size(); ++i) d += (i == 0 ? "M" : "L") + pt(f, points[i]);
    return closed ? d + "Z" : d;
}

std::string primitive_colour(int j) {
    // No red (obstacles, and the parts in conflict), green (a wall's
    // enclosed cells) or grey (the arm, base regions): each colour of a
    // view means one thing.
    static const char* const kColours[] = {"#1f77b4", "#ff7f0e", "#e7ba52", "#9467bd", "#8c564b",
                                           "#e377c2", "#17becf", "#bcbd22", "#006d77", "#393b79"};
    return kColours[j % 10];
}

}  // namespace modsynth::output::plot
