#pragma once
// Spatial solutions for the output tests: the planter's solutions of the
// fixtures in tests/fixtures/spatial/ (a yaw column and pitch links, 3 or 4
// joints), timed and re-certified as export does, and chains of any joint
// count moved along a smooth joint-space curve for the outputs that do not
// look at the task.
#include <cmath>
#include <string>
#include <vector>

#include <modsynth/geometry/vec.h>
#include <modsynth/io/solution_io.h>
#include <modsynth/io/spatial_task_io.h>
#include <modsynth/output/recertify.h>
#include <modsynth/synth/solution.h>
#include <modsynth/task/spatial_task.h>

namespace modsynth::testing {

struct SpatialCase {
    task::SpatialTask task;
    synth::Solution solution;
};

inline std::string spatial_fixture(const std::string& file) {
    return std::string(MODSYNTH_SOURCE_DIR) + "/tests/fixtures/spatial/" + file;
}

/// The planted solution of fixture `name` (s3-0001, s4-0010, ...), re-certified
/// and timed by output::recertify.
inline SpatialCase planted_case(const std::string& name) {
    SpatialCase c{io::load_spatial_task(spatial_fixture(name + ".task.json")), {}};
    io::ParsedSolution parsed = io::load_solution(spatial_fixture(name + ".planted.json"));
    output::recertify(c.task, parsed);
    c.solution = std::move(parsed.solution);
    return c;
}

/// A solved solution of an n-joint chain (twists 0, +-pi/2 and 0.7, some a
/// and d zero) whose joints swing smoothly for 2 s, with rates and
/// accelerations; not a motion along any path.
inline synth::Solution swinging_chain(int n) {
    synth::Solution s;
    s.task_name = "chain" + std::to_string(n);
    s.status = synth::Status::Solved;
    kinematics::DhChain c;
    c.base = geometry::Vec3(0.1, -0.2, 0.05);
    c.link_diameter = 0.03175;
    const double twists[] = {geometry::kPi / 2, 0.0, -geometry::kPi / 2, 0.7};
    for (int k = 0; k < n; ++k)
        c.rows.push_back({k == 0 ? 0.0 : 0.15 + 0.05 * k, twists[k % 4], k % 2 ? 0.0 : 0.2});
    s.dh_robot = c;
    for (int i = 0; i <= 200; ++i) {
        control::Sample x;
        x.t = 0.01 * i;
        for (int k = 0; k < n; ++k) {
            const double w = 1.0 + 0.3 * k;
            x.q.push_back(0.2 * k + 0.5 * std::sin(w * x.t));
            x.qd.push_back(0.5 * w * std::cos(w * x.t));
            x.qdd.push_back(-0.5 * w * w * std::sin(w * x.t));
        }
        s.samples.push_back(x);
    }
    s.certificate.ok = true;
    s.certificate.max_deviation = 1e-5;
    s.certificate.max_joint_step = 0.005;
    return s;
}

}  // namespace modsynth::testing
