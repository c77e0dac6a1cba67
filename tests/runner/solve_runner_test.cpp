// What a finished solve run answered, read back through the io stage's
// readers: the exit code and the solution file must agree.
#include "solve_runner.h"

#include <catch2/catch.hpp>

#include <fstream>

#include <nlohmann/json.hpp>

#include <modsynth/io/solution_io.h>
#include <modsynth/io/task_io.h>

#include "../output/output_fixtures.h"
#include "command.h"
#include "temp_dir.h"

using namespace modsynth;
using app::RunStatus;
using Catch::Matchers::Contains;

namespace {

struct Run {
    app::TempDir dir{"modsynth-solve-runner-test"};
    app::SolveJob job{dir.path() + "/x.task.json", dir.path() + "/x.solution.json",
                      dir.path() + "/x.log"};

    /// The hand-made two-joint task and, written as `solve` would, a solution.
    template <typename MakeSolution>
    synth::Solution wrote(MakeSolution make) const {
        const task::Task task = testing::two_joint_task();
        std::ofstream(job.task_path) << io::to_json(task).dump();
        const synth::Solution s = make(task);
        io::write_solution(s, job.solution_path);
        return s;
    }

    app::SolveOutcome ended(int exit_code, bool timed_out = false) const {
        app::ProcessResult r;
        r.exit_code = exit_code;
        r.timed_out = timed_out;
        return app::read_outcome(job, r, {});
    }
};

void write_text(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

}  // namespace

TEST_CASE("a solved run's figures come from its solution file", "[app]") {
    Run run;
    run.wrote(testing::two_joint_solution);
    const app::SolveOutcome o = run.ended(app::kOk);
    CHECK(o.status == synth::Status::Solved);
    CHECK(o.name == "line");
    CHECK(o.dof == 2);
    REQUIRE(o.total_link_length);
    CHECK(*o.total_link_length == Approx(0.65));
    CHECK(o.clearance_margin == 0.0123);
    CHECK(o.message.empty());
}

TEST_CASE("an infeasible run carries its explanation and core", "[app]") {
    Run run;
    const synth::Solution s = run.wrote(testing::infeasible_solution);
    const app::SolveOutcome o = run.ended(app::kInfeasible);
    CHECK(o.status == synth::Status::Infeasible);
    CHECK(o.message == s.explanation.message);
    CHECK(o.core == task::to_strings(s.explanation.core));
    CHECK_FALSE(o.dof);
}

TEST_CASE("a solution file that contradicts the exit code, or is unreadable, is an error",
          "[app]") {
    Run run;
    run.wrote(testing::two_joint_solution);
    const app::SolveOutcome says = run.ended(app::kInfeasible);
    CHECK(says.status == RunStatus::Failure::Error);
    CHECK_THAT(says.message, Contains("exit code 3 but the solution file says 'solved'"));

    write_text(run.job.solution_path,
               "{\"format\": \"modsynth-solution/1\", \"status\": \"maybe\"}");
    const app::SolveOutcome unreadable = run.ended(app::kUnknown);
    CHECK(unreadable.status == RunStatus::Failure::Error);
    // The message names the file it is about.
    CHECK_THAT(unreadable.message,
               Contains("cannot be read: " + run.job.solution_path + ": status: expected"));
}

TEST_CASE("a run's name is its task's, or the file's stem when the task is invalid", "[app]") {
    Run run;
    write_text(run.job.task_path, "{\"format\": \"modsynth-task/1\", \"name\": \"bad\"}");
    const app::SolveOutcome o = run.ended(app::kInvalid);
    CHECK(o.status == RunStatus::Failure::Invalid);
    CHECK(o.name == "x");
    CHECK(run.ended(app::kOk, true).status == RunStatus::Failure::Timeout);
}
