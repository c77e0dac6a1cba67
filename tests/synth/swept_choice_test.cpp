#include <catch2/catch.hpp>

#include <modsynth/io/task_io.h>
#include <modsynth/synth/swept_choice.h>
#include <modsynth/synth/synthesizer.h>
#include <modsynth/verify/verifier.h>

#include "../support/fixtures.h"

// The selectable swept-volume model: the order of attempts, and that every
// model's answer is the certified verifier's, falling back when it fails.
using namespace modsynth;

namespace {

task::Task load(const char* name) { return io::load_task(testing::source_path(name)); }

std::vector<std::string> names(const std::vector<synth::SweptAttempt>& attempts) {
    std::vector<std::string> out;
    for (const auto& a : attempts) out.push_back(synth::name_of(a));
    return out;
}

// The certificate is the verifier's own, recomputed here from the motion.
void check_certified(const task::Task& t, const synth::Solution& s) {
    REQUIRE(s.status == synth::Status::Solved);
    CHECK(s.certificate.ok);
    const auto again = verify::certify(t, s.robot, s.samples,
                                       synth::verify_options_for(t, synth::SynthesisOptions{}));
    CHECK(again.ok);
    CHECK(again.violations.empty());
}

}  // namespace

TEST_CASE("swept models are named as the command line spells them", "[synth]") {
    for (auto c : {synth::SweptChoice::Auto, synth::SweptChoice::App, synth::SweptChoice::Over,
                   synth::SweptChoice::Lines})
        CHECK(synth::swept_choice_from(synth::to_string(c)) == c);
    CHECK_FALSE(synth::swept_choice_from("SV-app").has_value());
    CHECK_FALSE(synth::swept_choice_from("").has_value());
}

TEST_CASE("each swept model is tried first, then lines", "[synth]") {
    const task::Task rose = load("tasks/rose.json");
    smt::Skeleton two;
    two.dof = 2;
    kinematics::Robot far;  // a robot whose SV-over is obstacle-free: links short, base far
    far.base = {0.0, 0.0};
    far.link_lengths = {0.05, 0.5};
    smt::Skeleton three = two;
    three.dof = 3;
    using V = std::vector<std::string>;
    CHECK(names(synth::swept_attempts(synth::SweptChoice::App, rose, two, far)) ==
          V{"SV-app", "sampled"});
    CHECK(names(synth::swept_attempts(synth::SweptChoice::Over, rose, three, far)) ==
          V{"SV-over", "sampled"});
    CHECK(names(synth::swept_attempts(synth::SweptChoice::Lines, rose, two, far)) == V{"sampled"});
    // The default keeps its SV-over attempt for two joints where it can hold.
    REQUIRE(synth::swept_over_plausible(rose, far));
    CHECK(names(synth::swept_attempts(synth::SweptChoice::Auto, rose, two, far)) ==
          V{"SV-over+lines", "sampled"});
    CHECK(names(synth::swept_attempts(synth::SweptChoice::Auto, rose, three, far)) == V{"sampled"});
    kinematics::Robot near = far;
    near.link_lengths = {0.5, 0.3};  // its disc holds obstacles[0]'s centre
    CHECK_FALSE(synth::swept_over_plausible(rose, near));
    CHECK(names(synth::swept_attempts(synth::SweptChoice::Auto, rose, two, near)) == V{"sampled"});
}

TEST_CASE("SV-app certifies the rose itself", "[synth]") {
    const task::Task rose = load("tasks/rose.json");
    synth::SynthesisOptions o;
    o.swept = synth::SweptChoice::App;
    synth::SynthesisStats stats;
    const synth::Solution s = synth::synthesize(rose, o, &stats);
    check_certified(rose, s);
    CHECK(s.robot.dof() == 2);
    CHECK(stats.first_certified_by == "SV-app");
}

TEST_CASE("SV-over cannot hold on the rose: the answer falls back to lines, certified", "[synth]") {
    // obstacles[0] lies between the base region and the top circle, inside
    // conv(disc(base, r_1), circle) for every base the region allows.
    const task::Task rose = load("tasks/rose.json");
    synth::SynthesisOptions o;
    o.swept = synth::SweptChoice::Over;
    synth::SynthesisStats stats;
    const synth::Solution s = synth::synthesize(rose, o, &stats);
    check_certified(rose, s);
    CHECK(stats.fallbacks >= 1);
    CHECK(stats.first_certified_by == "sampled");
}

TEST_CASE("SV-over certifies wipe-table with three joints", "[synth][slow]") {
    const task::Task wipe = load("tasks/wipe-table.json");
    synth::SynthesisOptions o;
    o.swept = synth::SweptChoice::Over;
    synth::SynthesisStats stats;
    const synth::Solution s = synth::synthesize(wipe, o, &stats);
    check_certified(wipe, s);
    CHECK(s.robot.dof() == 3);
    CHECK(stats.first_certified_by == "SV-over");
}
