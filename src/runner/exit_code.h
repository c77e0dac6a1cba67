#pragma once
// What a modsynth process's exit code says (README, "Exit codes"): the
// commands return them, and the runners that start commands in child
// processes read them back.
namespace modsynth::app {

/// kNotCertified: `certify` found the solution's motion not certified.
enum Exit {
    kOk = 0,
    kInternal = 1,
    kInvalid = 2,
    kInfeasible = 3,
    kUnknown = 4,
    kNotCertified = 5
};

}  // namespace modsynth::app
