#include <modsynth/synth/swept_choice.h>

#include <modsynth/geometry/distance.h>
#include <modsynth/geometry/polygon.h>
#include <modsynth/geometry/primitive.h>
#include <modsynth/kinematics/chain_layout.h>
#include <modsynth/kinematics/clearance_rule.h>

namespace modsynth::synth {

const char* to_string(SweptChoice choice) {
    switch (choice) {
        case SweptChoice::Auto:
            return "auto";
        case SweptChoice::App:
            return "app";
        case SweptChoice::Over:
            return "over";
        case SweptChoice::Lines:
            return "lines";
    }
    return "auto";
}

std::optional<SweptChoice> swept_choice_from(const std::string& name) {
    for (SweptChoice c :
         {SweptChoice::Auto, SweptChoice::App, SweptChoice::Over, SweptChoice::Lines})
        if (name == to_string(c)) return c;
    return std::nullopt;
}

const char* name_of(const SweptAttempt& attempt) {
    switch (attempt.swept) {
        case nlp::SweptVolume::Over:
            return attempt.paper ? "SV-over" : "SV-over+lines";
        case nlp::SweptVolume::App:
            return "SV-app";
        case nlp::SweptVolume::Sampled:
            return "sampled";
    }
    return "sampled";
}

namespace {

// How far a point lies outside the part of SV^over's bound a primitive
// fixes: its segment, or the disc of an arc's or circle's circle.
double own_part_gap(const geometry::Primitive& prim, const geometry::Vec2& c) {
    switch (prim.kind) {
        case geometry::PrimitiveKind::Line:
            return geometry::point_segment(c, prim.start, prim.end);
        case geometry::PrimitiveKind::Arc:
        case geometry::PrimitiveKind::Circle:
            return (c - prim.center).norm() - prim.radius;
    }
    geometry::invalid_kind(prim.kind);
}

}  // namespace

bool swept_over_plausible(const task::Task& task, const kinematics::Robot& robot) {
    // Nor can it be met at all when an obstacle's clearance circle meets the
    // primitive's own part of the bound (the segment; for an arc, the disc of
    // its circle): that part has no variables, so no robot separates them.
    const kinematics::ClearanceRule rule{task.robot.link_diameter};
    const nlp::Margins margins;
    for (const auto& prim : task.trajectory) {
        for (const auto& ob : task.obstacles) {
            const double need = rule.obstacle_distance(ob) + margins.clearance;
            if (own_part_gap(prim, ob.center) < need) return false;
        }
    }
    const int dof = robot.dof();
    for (int j = 0; j < static_cast<int>(task.trajectory.size()); ++j) {
        const auto& prim = task.trajectory[j];
        const bool known =
            !robot.has_proximal_link() || j < static_cast<int>(robot.proximal_angles.size());
        const geometry::Vec2 origin = known ? robot.tracing_origin(j) : robot.base;
        std::vector<geometry::Vec2> pts;
        const double len = geometry::length(prim);
        for (int i = 0; i <= 16; ++i) pts.push_back(geometry::point_at(prim, len * i / 16));
        for (int i = 0; i < 32; ++i)
            pts.push_back(origin +
                          robot.link_lengths[dof - 2] * geometry::unit(geometry::kTau * i / 32));
        const auto hull = geometry::convex_hull(pts);
        for (const auto& ob : task.obstacles)
            if (geometry::point_in_convex_polygon(ob.center, hull)) return false;
    }
    return true;
}

std::vector<SweptAttempt> swept_attempts(SweptChoice choice, const task::Task& task,
                                         const smt::Skeleton& skeleton,
                                         const kinematics::Robot& guess) {
    const SweptAttempt lines{nlp::SweptVolume::Sampled, false};
    switch (choice) {
        case SweptChoice::Auto:
            // SV^over bounds a 2-link arm here; with three joints the
            // sampled model is used directly.
            if (!kinematics::has_proximal_link(skeleton.dof) && !task.obstacles.empty() &&
                swept_over_plausible(task, guess))
                return {{nlp::SweptVolume::Over, false}, lines};
            return {lines};
        case SweptChoice::Over:
            // Asked for by name, SV^over is tried even where the guess says
            // it cannot hold: the refinement may move the arm until it does.
            return {{nlp::SweptVolume::Over, true}, lines};
        case SweptChoice::App:
            return {{nlp::SweptVolume::App, true}, lines};
        case SweptChoice::Lines:
            return {lines};
    }
    return {lines};
}

}  // namespace modsynth::synth
