#include <catch2/catch.hpp>

#include <string>

#include <modsynth/synth/status.h>
#include <modsynth/task/input_error.h>

using modsynth::synth::Status;
using modsynth::synth::status_from_string;
using modsynth::synth::to_string;
using modsynth::task::InputError;

TEST_CASE("a status kind round-trips through its text", "[status]") {
    for (const Status::Kind kind : {Status::Solved, Status::Infeasible, Status::Unknown}) {
        CHECK(status_from_string(to_string(kind), "status") == kind);
    }
    CHECK(std::string(to_string(Status::Solved)) == "solved");
    CHECK(std::string(to_string(Status::Infeasible)) == "infeasible");
    CHECK(std::string(to_string(Status::Unknown)) == "unknown");
}

TEST_CASE("status text that is no status is rejected naming the part", "[status]") {
    for (const char* text : {"", "Solved", "solved ", "timeout", "sat"}) {
        try {
            status_from_string(text, "solve.status");
            FAIL("accepted \"" << text << "\"");
        } catch (const InputError& e) {
            CHECK(e.part() == "solve.status");
            CHECK_THAT(e.what(),
                       Catch::Matchers::Contains("\"solved\", \"infeasible\" or \"unknown\""));
        }
    }
}

TEST_CASE("an unknown status carries the stage it reached and why it stopped", "[status]") {
    const Status s(Status::Unknown, "3 joints: front stage", "time limit");
    CHECK(s == Status::Unknown);
    CHECK(s != Status::Solved);
    CHECK(s.stage == "3 joints: front stage");
    CHECK(s.reason == "time limit");
    const Status solved = Status::Solved;
    CHECK(solved.kind == Status::Solved);
    CHECK(solved.stage.empty());
    CHECK(Status{}.kind == Status::Unknown);
}
