#include <modsynth/geometry/primitive.h>
#include <modsynth/prove/no_go.h>
#include <modsynth/task/strokes.h>

namespace modsynth::prove {

std::vector<NoGoDisc> no_go_discs(const task::Task& task, const std::vector<int>& obstacles) {
    std::vector<NoGoDisc> out;
    for (int i : obstacles) {
        const auto& o = task.obstacles.at(i);
        out.push_back({o.center, o.radius + task.robot.link_diameter / 2, i});
    }
    return out;
}

std::vector<int> all_obstacles(const task::Task& task) {
    std::vector<int> out;
    for (int i = 0; i < static_cast<int>(task.obstacles.size()); ++i) out.push_back(i);
    return out;
}

double overlap(const NoGoDisc& a, const NoGoDisc& b) {
    return a.radius + b.radius - (a.center - b.center).norm();
}

std::vector<PathPoint> path_points(const task::Task& task) {
    std::vector<PathPoint> out;
    for (int j = 0; j < static_cast<int>(task.trajectory.size()); ++j) {
        const auto& p = task.trajectory[j];
        out.push_back({j, p.start});
        out.push_back({j, geometry::point_at(p, geometry::length(p) / 2)});
        if (task::ends_stroke(task, j)) out.push_back({j, p.end});
    }
    if (out.size() <= kMaxPathPoints) return out;
    std::vector<PathPoint> spread;
    for (std::size_t k = 0; k < kMaxPathPoints; ++k)
        spread.push_back(out[k * (out.size() - 1) / (kMaxPathPoints - 1)]);
    return spread;
}

bool free_point(const std::vector<NoGoDisc>& discs, const geometry::Vec2& p) {
    for (const auto& d : discs)
        if ((p - d.center).norm() <= d.radius + kNoGoSlack) return false;
    return true;
}

}  // namespace modsynth::prove
