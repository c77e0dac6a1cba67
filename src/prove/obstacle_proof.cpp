#include <modsynth/geometry/distance.h>
#include <modsynth/geometry/polygon.h>
#include <modsynth/prove/geodesic_reach.h>
#include <modsynth/prove/no_go.h>
#include <modsynth/prove/obstacle_proof.h>
#include <modsynth/prove/separation.h>
#include <modsynth/task/part.h>
#include <modsynth/text/format.h>

#include <algorithm>
#include <cassert>
#include <iterator>
#include <set>

namespace modsynth::prove {
namespace {

using geometry::Vec2;

// Drops obstacles one at a time while `holds` still does. Both proofs are
// monotone (fewer obstacles, less blocked), and every obstacle kept failed
// alone against a superset of what remains, so what remains is minimal.
// (Trying halves first costs more: in a wall most obstacles are needed, and
// a failed half only splits.)
template <typename Holds>
std::vector<int> minimise(std::vector<int> keep, Holds holds) {
    for (std::size_t k = keep.size(); k-- > 0;) {
        std::vector<int> fewer = keep;
        fewer.erase(fewer.begin() + static_cast<long>(k));
        if (holds(fewer)) keep = std::move(fewer);
    }
    return keep;
}

std::vector<task::TaskPart> core_of(const task::Task& task, const std::vector<int>& obstacles,
                                    const std::set<int>& primitives,
                                    const std::vector<task::RobotKey>& robot_keys) {
    std::vector<task::TaskPart> core;
    for (int j : primitives) core.push_back(task::TaskPart::primitive(task, j));
    for (int i : obstacles) {
        assert(i >= 0 && i < static_cast<int>(task.obstacles.size()));
        core.push_back(task::TaskPart::obstacle(i));
    }
    core.push_back(task::TaskPart::base_regions());
    for (task::RobotKey k : robot_keys) core.push_back(task::TaskPart::robot(k));
    return core;
}

std::string region_list(const std::set<int>& indices) {
    std::string s;
    for (int j : indices)
        s += (s.empty() ? "" : ", ") + task::to_string(task::TaskPart::base_region(j));
    return s;
}

task::Task without_tube(const task::Task& task) {
    task::Task t = task;
    t.robot.link_diameter = 0.0;
    return t;
}

std::optional<Proof> by_separation(const task::Task& task) {
    auto found = prove_separation(task, all_obstacles(task));
    if (!found) return std::nullopt;
    std::set<int> used;
    for (const auto& w : found->walls) used.insert(w.cycle.begin(), w.cycle.end());
    const std::vector<int> keep =
        minimise({used.begin(), used.end()},
                 [&](const std::vector<int>& o) { return prove_separation(task, o).has_value(); });
    Proof proof;
    proof.separation = prove_separation(task, keep);
    if (!proof.separation) return std::nullopt;  // cannot happen: keep was checked
    std::set<int> primitives;
    for (const auto& w : proof.separation->walls) primitives.insert(w.primitive);
    const bool tube = !prove_separation(without_tube(task), keep);
    proof.core = core_of(task, keep, primitives,
                         tube ? std::vector<task::RobotKey>{task::RobotKey::LinkDiameter}
                              : std::vector<task::RobotKey>{});
    // One sentence per distinct wall.
    std::string said;
    std::set<std::vector<int>> walls;
    for (const auto& w : proof.separation->walls) {
        std::vector<int> sorted = w.cycle;
        std::sort(sorted.begin(), sorted.end());
        if (!walls.insert(sorted).second) continue;
        std::vector<Vec2> poly;
        for (int i : w.cycle) poly.push_back(task.obstacles[i].center);
        const bool around_path = geometry::winding_number(poly, w.point) != 0;
        std::set<int> regions;
        for (const auto& v : proof.separation->walls) {
            std::vector<int> s = v.cycle;
            std::sort(s.begin(), s.end());
            if (s == sorted) regions.insert(v.base_region);
        }
        const bool every = regions.size() == task.base_regions.size();
        const std::string where =
            every ? (task.base_regions.size() > 1 ? "every base region" : "the base region")
                  : region_list(regions);
        const std::string path = task::to_string(task::TaskPart::primitive(task, w.primitive));
        said += (said.empty() ? "" : "; ") + std::string("obstacles ") + index_ranges(w.cycle) +
                " form a closed wall around " +
                (around_path
                     ? path + "; " + where + (regions.size() > 1 ? " are" : " is") + " outside it"
                     : where + "; " + path + " is outside it");
    }
    said +=
        tube ? text::format(
                   ": the gaps between them are narrower than the tube (%.4f m), and an arm is one "
                   "tube from its base to the path.",
                   task.robot.link_diameter)
             : ": they overlap, and an arm is one tube from its base to the path.";
    proof.message = said;
    return proof;
}

// Obstacles that overlap, directly or through others, one of `seeds`.
std::vector<int> overlap_components(const task::Task& task, const std::set<int>& seeds) {
    const auto discs = no_go_discs(task, all_obstacles(task));
    std::vector<bool> in(discs.size(), false);
    std::vector<int> stack(seeds.begin(), seeds.end());
    for (int s : stack) in[s] = true;
    while (!stack.empty()) {
        const int i = stack.back();
        stack.pop_back();
        for (std::size_t j = 0; j < discs.size(); ++j)
            if (!in[j] && overlap(discs[i], discs[j]) > kNoGoSlack)
                in[j] = true, stack.push_back(static_cast<int>(j));
    }
    std::vector<int> out;
    for (std::size_t i = 0; i < in.size(); ++i)
        if (in[i]) out.push_back(static_cast<int>(i));
    return out;
}

std::optional<Proof> by_geodesic(const task::Task& task) {
    const GeodesicProver prover(task, all_obstacles(task));
    auto found = prover.prove(all_obstacles(task));
    if (!found) return std::nullopt;
    std::vector<PathPoint> points;
    std::set<int> touched;
    for (const auto& d : found->detours) {
        points.push_back({d.primitive, d.point});
        for (const auto& s : d.route)
            if (s.around >= 0) touched.insert(s.around);
    }
    // Without any obstacle the path is out of reach: the front stage's
    // proof, which needs no obstacle, is the better explanation.
    bool straight = true;
    for (std::size_t k = 0; k < points.size(); ++k) {
        const auto& r = task.base_regions[k];
        straight = straight && geometry::point_box(points[k].point, r.min, r.max) > found->reach;
    }
    if (straight) return std::nullopt;
    // Every path point may serve, so that no obstacle left out could make
    // the proof hold again with another point.
    const auto holds = [&](const std::vector<int>& o) {
        return prover.prove(o, false).has_value();
    };
    std::vector<int> start = overlap_components(task, touched);
    if (!holds(start)) start = all_obstacles(task);
    const std::vector<int> keep = minimise(start, holds);
    Proof proof;
    proof.geodesic = prover.prove(keep);
    if (!proof.geodesic) return std::nullopt;
    std::set<int> primitives;
    for (const auto& d : proof.geodesic->detours) primitives.insert(d.primitive);
    std::vector<task::RobotKey> robot{task::RobotKey::MaxLinkLength};
    if (!prove_geodesic_reach(without_tube(task), keep, false))
        robot.push_back(task::RobotKey::LinkDiameter);
    proof.core = core_of(task, keep, primitives, robot);
    const int links = *std::max_element(task.robot.dof.begin(), task.robot.dof.end());
    std::string said;
    for (const auto& d : proof.geodesic->detours) {
        said += (said.empty() ? "" : "; ") + std::string("the shortest way around obstacles ") +
                index_ranges(keep) + " from " +
                (task.base_regions.size() > 1
                     ? task::to_string(task::TaskPart::base_region(d.base_region))
                     : "the base region") +
                " to " + task::to_string(task::TaskPart::primitive(task, d.primitive)) +
                text::format(" is %.2f m", d.lower_bound);
    }
    said += text::format("; %d links of at most %.2f m reach %.2f m.", links,
                         task.robot.max_link_length, proof.geodesic->reach);
    proof.message = said;
    return proof;
}

}  // namespace

std::string index_ranges(std::vector<int> indices) {
    std::sort(indices.begin(), indices.end());
    indices.erase(std::unique(indices.begin(), indices.end()), indices.end());
    std::string s;
    for (std::size_t k = 0; k < indices.size();) {
        std::size_t e = k;
        while (e + 1 < indices.size() && indices[e + 1] == indices[e] + 1) ++e;
        s += (s.empty() ? "" : ", ") + std::to_string(indices[k]);
        if (e > k) s += (e == k + 1 ? ", " : "-") + std::to_string(indices[e]);
        k = e + 1;
    }
    return s;
}

namespace {

bool proves(const BranchAndBoundResult& r) {
    return r.outcome == BranchAndBoundResult::Outcome::Infeasible && !r.obstacles.empty();
}

std::vector<int> sorted(std::vector<int> v) {
    std::sort(v.begin(), v.end());
    v.erase(std::unique(v.begin(), v.end()), v.end());
    return v;
}

std::vector<int> minus(const std::vector<int>& a, const std::vector<int>& b) {
    std::vector<int> out;
    std::set_difference(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(out));
    return out;
}

struct Shrunk {
    std::vector<int> keep;       ///< proved: the search refutes every box among these alone
    BranchAndBoundResult proof;  ///< the search that proved it
    bool finished = false;       ///< every obstacle left was found needed
};

// A deletion filter over the obstacles of a proof, QuickXplain-style: a
// block of obstacles is dropped when the search, re-run with the same
// options on the rest, still refutes every box (fewer obstacles are fewer
// constraints, so a proof among a subset is a proof for the task); a block
// that cannot go is halved, down to single obstacles. Each obstacle kept
// failed alone against a superset of what remains. A proof also names the
// obstacles it used, and only those are kept on. Blocks first: a corridor
// wall holds posts beyond the arm's reach that go together, where one at a
// time would cost a search each.
Shrunk shrink(const task::Task& task, const BranchAndBoundResult& first,
              const std::vector<int>& proved_among, const BranchAndBoundOptions& options,
              const run::Deadline& deadline) {
    Shrunk s{sorted(first.obstacles), first, false};
    std::vector<int> proved_set = sorted(proved_among);
    BranchAndBoundOptions run = options;
    run.time_limit = options.core_run_time_limit;
    // An obstacle is needed when the search without it stops at a box (the
    // search is deterministic: more time would find the same box); when it
    // stops at its per-run budget instead, the obstacle stays, unsettled.
    bool settled = true;
    std::vector<std::vector<int>> blocks;  // a stack: the back is tried next
    {
        const std::size_t n = s.keep.size(), size = std::max<std::size_t>(1, (n + 3) / 4);
        for (std::size_t k = 0; k < n; k += size)
            blocks.emplace_back(s.keep.begin() + static_cast<long>(k),
                                s.keep.begin() + static_cast<long>(std::min(n, k + size)));
        std::reverse(blocks.begin(), blocks.end());
    }
    while (!blocks.empty()) {
        std::vector<int> block = sorted(blocks.back());
        blocks.pop_back();
        block.erase(std::remove_if(block.begin(), block.end(),
                                   [&](int i) {
                                       return !std::binary_search(s.keep.begin(), s.keep.end(), i);
                                   }),
                    block.end());
        if (block.empty()) continue;
        const std::vector<int> rest = minus(s.keep, block);
        if (deadline.expired()) return s;
        const auto r =
            rest.empty() ? BranchAndBoundResult{} : branch_and_bound(task, rest, run, deadline);
        if (proves(r)) {
            s.keep = sorted(r.obstacles);  // a subset of rest
            s.proof = r;
            proved_set = rest;
            continue;
        }
        if (r.outcome == BranchAndBoundResult::Outcome::Unknown && deadline.expired())
            return s;  // the overall budget, not the obstacles, stopped it
        if (block.size() == 1 && r.outcome != BranchAndBoundResult::Outcome::Box) settled = false;
        if (block.size() > 1) {
            const auto mid = block.begin() + static_cast<long>(block.size() / 2);
            blocks.emplace_back(mid, block.end());
            blocks.emplace_back(block.begin(), mid);
        }
    }
    // The last proof ran among proved_set; what it used is kept, so check
    // that exactly those suffice (the filter's answer must be a proof).
    if (s.keep != proved_set) {
        const auto r = branch_and_bound(task, s.keep, run, deadline);
        if (!proves(r)) {
            s.keep = proved_set;
            return s;
        }
        s.proof = r;
    }
    s.finished = settled;
    return s;
}

}  // namespace

std::optional<Proof> prove_two_joint_infeasible(const task::Task& task,
                                                const BranchAndBoundOptions& options,
                                                run::Deadline deadline) {
    if (task.robot.dof != std::vector<int>{2} || task.base_regions.empty() ||
        task.obstacles.empty() || task.obstacles.size() > kMaxBranchObstacles)
        return std::nullopt;
    // Shrinking, within what the proof leaves of core_time_limit.
    const run::Deadline core_deadline = deadline.within(options.core_time_limit);
    BranchAndBoundResult r = branch_and_bound(task, all_obstacles(task), options, deadline);
    if (!proves(r)) return std::nullopt;  // without obstacles the front stage has the better proof
    bool minimal = false;
    if (!core_deadline.expired()) {
        Shrunk s = shrink(task, r, all_obstacles(task), options, core_deadline);
        minimal = s.finished;
        r = std::move(s.proof);
        r.obstacles = std::move(s.keep);
    }
    Proof proof;
    proof.minimal = minimal;
    proof.core = core_of(task, r.obstacles, {r.primitives.begin(), r.primitives.end()},
                         {task::RobotKey::Dof, task::RobotKey::MinLinkLength,
                          task::RobotKey::MaxLinkLength, task::RobotKey::LinkDiameter});
    std::set<int> primitives(r.primitives.begin(), r.primitives.end());
    std::string paths;
    for (int j : primitives)
        paths += (paths.empty() ? "" : ", ") + task::to_string(task::TaskPart::primitive(task, j));
    proof.message = text::format(
        "no 2-joint arm with links of %.2f-%.2f m and its base in %s reaches %s with both links "
        "clear of obstacles %s: a branch and bound over the base position, both link lengths "
        "and the first joint's angle at %d points of the path refuted every one of %ld boxes, "
        "for either elbow at every point. The proof is exact; delta = %.3f m only sizes the "
        "boxes at which the search would have stopped with a near-design instead.",
        task.robot.min_link_length, task.robot.max_link_length,
        task.base_regions.size() > 1 ? "any base region" : "the base region", paths.c_str(),
        index_ranges(r.obstacles).c_str(), r.points, r.boxes, options.delta);
    proof.message += minimal ? " Without any one of these obstacles the search finds no proof."
                             : " (core not minimised within the time limit: some of these "
                               "obstacles may not be needed.)";
    return proof;
}

std::optional<Proof> prove_obstacle_infeasible(const task::Task& task) {
    if (task.base_regions.empty() || task.obstacles.empty() || task.robot.dof.empty() ||
        task.base_regions.size() > kMaxProofRegions)
        return std::nullopt;
    if (task.obstacles.size() <= kMaxWallObstacles)
        if (auto p = by_separation(task)) return p;
    if (task.obstacles.size() <= kMaxDetourObstacles) return by_geodesic(task);
    return std::nullopt;
}

}  // namespace modsynth::prove
