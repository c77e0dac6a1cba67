#include <modsynth/prove/loop_proof.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <unordered_map>
#include <vector>

#include <modsynth/geometry/primitive.h>
#include <modsynth/geometry/winding.h>
#include <modsynth/task/part.h>
#include <modsynth/task/strokes.h>
#include <modsynth/text/format.h>

namespace modsynth::prove {
namespace {

using geometry::Vec2;

// The format joins consecutive primitives within 1e-6 m; a run whose end is
// that near its start is closed. Points are binned in cells wider than that,
// so a closing start lies in the end's cell or a neighbour.
constexpr double kJoin = 1e-6;
constexpr double kCell = 1e-5;
// A path that comes back to the same point very often (a star drawn through
// its centre) has as many closed runs as pairs of visits: past this many the
// search stops, unproved.
constexpr int kMostRuns = 100000;

using Cell = std::pair<std::int64_t, std::int64_t>;
struct CellHash {
    std::size_t operator()(const Cell& c) const {
        return std::hash<std::int64_t>()(c.first * 73856093 ^ c.second * 19349663);
    }
};
Cell cell_of(const Vec2& p) {
    return {static_cast<std::int64_t>(std::floor(p.x() / kCell)),
            static_cast<std::int64_t>(std::floor(p.y() / kCell))};
}

// The turn of the path round c up to each primitive of a stroke, and how
// many of those primitives pass within kJoin of c (a loop through c winds
// round nothing).
struct Turns {
    std::vector<double> angle{0.0};
    std::vector<int> near{0};
};

Turns turns_round(const task::Task& task, int first, int last, const Vec2& c) {
    Turns t;
    for (int j = first; j <= last; ++j) {
        const geometry::Primitive& p = task.trajectory[static_cast<std::size_t>(j)];
        const bool near = !(geometry::nearest(p, c).distance > kJoin);
        t.angle.push_back(t.angle.back() + (near ? 0.0 : geometry::turning_angle(p, c)));
        t.near.push_back(t.near.back() + (near ? 1 : 0));
    }
    return t;
}

// Whole turns of a closed run's angle (the join from its end to its start
// included); 0 where rounding left it far from whole.
int whole_turns(double angle) {
    const double turns = angle / geometry::kTau;
    const double whole = std::round(turns);
    return std::abs(turns - whole) < 1e-6 ? static_cast<int>(whole) : 0;
}

double join_angle(const Vec2& from, const Vec2& to, const Vec2& c) {
    if (from == to) return 0.0;
    const Vec2 u = from - c;
    const Vec2 v = to - c;
    return std::atan2(u.x() * v.y() - u.y() * v.x(), u.dot(v));
}

std::string times(int turns) {
    const int n = std::abs(turns);
    return n == 1 ? "once" : n == 2 ? "twice" : std::to_string(n) + " times";
}

}  // namespace

std::optional<LoopAroundObstacle> loop_around_obstacle(const task::Task& task, int longest) {
    std::vector<int> keep_off;
    for (int i = 0; i < static_cast<int>(task.obstacles.size()); ++i)
        if (task.obstacles[static_cast<std::size_t>(i)].radius + task.robot.link_diameter / 2.0 >
            0.0)
            keep_off.push_back(i);
    if (keep_off.empty()) return std::nullopt;
    int runs = 0;
    for (int s = 0; s < task::stroke_count(task); ++s) {
        const int first = task::stroke_first(task, s);
        const int last = task::stroke_last(task, s);
        std::vector<Turns> turns;  // per obstacle kept off, computed at the first closed run
        std::unordered_multimap<Cell, int, CellHash> starts;
        for (int b = first; b <= last; ++b) {
            const geometry::Primitive& pb = task.trajectory[static_cast<std::size_t>(b)];
            starts.emplace(cell_of(pb.start), b);
            const Cell e = cell_of(pb.end);
            std::vector<int> closing;
            for (std::int64_t dx = -1; dx <= 1; ++dx)
                for (std::int64_t dy = -1; dy <= 1; ++dy) {
                    const auto [lo, hi] = starts.equal_range({e.first + dx, e.second + dy});
                    for (auto it = lo; it != hi; ++it) {
                        const int a = it->second;
                        const Vec2& start = task.trajectory[static_cast<std::size_t>(a)].start;
                        if ((start - pb.end).norm() <= kJoin &&
                            (longest < 0 || b - a + 1 <= longest))
                            closing.push_back(a);
                    }
                }
            // Shortest runs first: the core is the loop's primitives.
            std::sort(closing.begin(), closing.end(), std::greater<>());
            for (int a : closing) {
                if (++runs > kMostRuns) return std::nullopt;
                if (turns.empty())
                    for (int i : keep_off)
                        turns.push_back(turns_round(
                            task, first, last, task.obstacles[static_cast<std::size_t>(i)].center));
                const Vec2& start = task.trajectory[static_cast<std::size_t>(a)].start;
                for (std::size_t k = 0; k < keep_off.size(); ++k) {
                    const Turns& t = turns[k];
                    const int ia = a - first;
                    const int ib = b - first + 1;
                    if (t.near[static_cast<std::size_t>(ib)] !=
                        t.near[static_cast<std::size_t>(ia)])
                        continue;
                    const Vec2& c = task.obstacles[static_cast<std::size_t>(keep_off[k])].center;
                    const double angle = t.angle[static_cast<std::size_t>(ib)] -
                                         t.angle[static_cast<std::size_t>(ia)] +
                                         join_angle(pb.end, start, c);
                    if (const int n = whole_turns(angle); n != 0)
                        return LoopAroundObstacle{a, b, keep_off[k], n};
                }
            }
        }
    }
    return std::nullopt;
}

std::string describe_loop(const task::Task& task, const LoopAroundObstacle& loop) {
    std::string run = task::to_string(task::TaskPart::primitive(task, loop.first));
    if (loop.last != loop.first)
        run += " to " + task::to_string(task::TaskPart::primitive(task, loop.last));
    return text::format("%s is a closed loop that winds %s %s round the centre of obstacles[%d]",
                        run.c_str(), times(loop.turns).c_str(),
                        loop.turns > 0 ? "counter-clockwise" : "clockwise", loop.obstacle);
}

Proof two_joint_loop_proof(const task::Task& task, const LoopAroundObstacle& loop) {
    Proof proof;
    for (int j = loop.first; j <= loop.last; ++j)
        proof.core.push_back(task::TaskPart::primitive(task, j));
    proof.core.push_back(task::TaskPart::obstacle(loop.obstacle));
    proof.core.push_back(task::TaskPart::robot(task::RobotKey::Dof));
    if (!(task.obstacles[static_cast<std::size_t>(loop.obstacle)].radius > 0.0))
        proof.core.push_back(task::TaskPart::robot(task::RobotKey::LinkDiameter));
    proof.message = describe_loop(task, loop) +
                    "; an arm of 2 joints keeps one elbow branch, so it comes back to that "
                    "point in the pose it left it in, and on the way its links sweep over "
                    "every point the loop winds round.";
    return proof;
}

std::optional<Proof> prove_two_joint_loop(const task::Task& task) {
    const auto loop = loop_around_obstacle(task);
    if (!loop) return std::nullopt;
    return two_joint_loop_proof(task, *loop);
}

}  // namespace modsynth::prove
