#pragma once
// What a modsynth process's exit code says (README, "Exit codes"): the
// commands return them, and the runners that start commands in child
// processes read them back.
namespace modsynth::app {

enum Exit { kOk = 0, kInternal = 1, kInvalid = 2, kInfeasible = 3, kUnknown = 4 };

}  // namespace modsynth::app
