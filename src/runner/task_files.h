#pragma once
// Finding the task files of a suite, naming them, and splitting a suite into
// shards so that a cluster can share it out.
#include <string>
#include <vector>

namespace modsynth::app {

/// Task files under `dir`, recursively, sorted by path. In a folder that
/// holds *.task.json files (plant.py's layout) only those are tasks;
/// elsewhere every *.json is, except plant.py's companions (*.expect.json,
/// *.planted.json) and solutions (*.solution.json). Links to folders are
/// followed, each folder searched once however many links reach it; an
/// entry named as a task that cannot be read (a link to itself) is listed,
/// for its run to say why. Throws task::InputError when `dir` is not a
/// folder.
std::vector<std::string> find_task_files(const std::string& dir);

/// The paths listed in a text file, one per line (blank lines and lines
/// starting with '#' skipped), sorted. Throws task::InputError when the file
/// cannot be read (or is not a regular file, or larger than a task file).
std::vector<std::string> read_task_list(const std::string& list_file);

/// The file name without ".task.json" or ".json": "tasks/rose.json" -> "rose".
std::string task_stem(const std::string& path);

/// A name per task path for the files made from it, unique and the same
/// on every run: the path below `root` (the suite folder; when empty, the
/// deepest folder holding every path) without ".task.json" or ".json", so
/// "suite/a/x.task.json" -> "a/x". Where two tasks of one folder shorten to
/// the same name both keep their whole file name ("a/x.json",
/// "a/x.task.json"); a path given twice gets "~2", "~3", ... in order.
std::vector<std::string> output_names(const std::vector<std::string>& paths,
                                      const std::string& root = "");

struct Shard {
    int index = 1;  ///< K, 1-based
    int count = 1;  ///< N
};

/// Parses "K/N" with 1 <= K <= N; throws task::InputError naming --shard.
Shard parse_shard(const std::string& text);

/// The positions of shard K of N in a list of `size` items: every N-th,
/// starting at K-1. The shards of one N partition the list.
std::vector<std::size_t> shard_positions(std::size_t size, const Shard& shard);

}  // namespace modsynth::app
