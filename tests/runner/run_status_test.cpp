#include "run_status.h"

#include <catch2/catch.hpp>

#include <modsynth/task/input_error.h>

using modsynth::app::run_status_from_string;
using modsynth::app::RunStatus;
using modsynth::synth::Status;
using Failure = modsynth::app::RunStatus::Failure;

TEST_CASE("a run's status round-trips through its text", "[status]") {
    std::vector<RunStatus> all;
    for (const auto kind : {Status::Solved, Status::Infeasible, Status::Unknown})
        all.push_back(RunStatus::answered(kind));
    for (const auto f :
         {Failure::Invalid, Failure::Error, Failure::Timeout, Failure::Crashed, Failure::Cancelled})
        all.push_back(RunStatus::failed(f));
    for (const RunStatus& s : all) {
        const std::string text = to_string(s);
        const RunStatus back = run_status_from_string(text, "status");
        CHECK(back == s);
        CHECK(to_string(back) == text);
    }
    CHECK(to_string(RunStatus::answered(Status::Infeasible)) == "infeasible");
    CHECK(to_string(RunStatus::failed(Failure::Timeout)) == "timeout");
}

TEST_CASE("a run's status compares with answer kinds and failures", "[status]") {
    const RunStatus solved = RunStatus::answered(Status::Solved);
    const RunStatus timeout = RunStatus::failed(Failure::Timeout);
    CHECK(solved.is_answer());
    CHECK(solved == Status::Solved);
    CHECK(solved != Status::Unknown);
    CHECK_FALSE(timeout.is_answer());
    CHECK(timeout == Failure::Timeout);
    // A failed run answered nothing, whatever its answer field holds.
    CHECK(timeout != Status::Unknown);
    CHECK(timeout != RunStatus::failed(Failure::Crashed));
    CHECK(RunStatus::answered(Status(Status::Unknown, "a stage", "a reason")) ==
          RunStatus::answered(Status::Unknown));
}

TEST_CASE("text that is no run status is rejected naming the part", "[status]") {
    for (const char* text : {"", "killed", "Timeout", "solved\n"}) {
        try {
            run_status_from_string(text, "solve.status");
            FAIL("accepted \"" << text << "\"");
        } catch (const modsynth::task::InputError& e) {
            CHECK(e.part() == "solve.status");
            CHECK_THAT(e.what(), Catch::Matchers::Contains("\"timeout\""));
        }
    }
}
