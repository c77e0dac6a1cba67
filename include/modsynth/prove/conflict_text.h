#pragma once
// Conflicts and task parts in words, in the task's terms and units: what a
// proof's core says to a person ("trajectory[0] is out of reach from every
// allowed base position by an arm of 2 or 3 links of at most 1.00 m.").
#include <string>
#include <vector>

#include <modsynth/task/part.h>
#include <modsynth/task/task.h>

namespace modsynth::prove {

/// One sentence naming what conflicts.
std::string describe_conflict(const task::Task& task, const std::vector<task::TaskPart>& core);

/// What one task part is, in words and numbers: "trajectory[2]: a line from
/// (0.400, 0.100) to (0.550, 0.100)".
std::string describe_part(const task::Task& task, const task::TaskPart& part);

/// "a, b and c" (or "a, b or c" with last = " or ").
std::string listing(const std::vector<std::string>& items, const char* last = " and ");

/// The joint counts the task allows, in words: "2 or 3".
std::string joint_counts(const task::Task& task);

}  // namespace modsynth::prove
