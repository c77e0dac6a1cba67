#include "task_files.h"

#include <modsynth/io/input.h>
#include <modsynth/task/input_error.h>
#include <modsynth/task/limits.h>
#include <modsynth/text/printable.h>

#include <algorithm>
#include <deque>
#include <filesystem>
#include <map>
#include <regex>
#include <set>
#include <sstream>

namespace modsynth::app {
namespace {

namespace fs = std::filesystem;

bool ends_with(const std::string& s, const std::string& suffix) {
    return s.size() >= suffix.size() &&
           s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

bool is_companion(const std::string& name) {
    return ends_with(name, ".expect.json") || ends_with(name, ".core.json") ||
           ends_with(name, ".planted.json") || ends_with(name, ".solution.json");
}

/// Whether a folder entry that is no folder is named as a task.
bool task_named(const std::string& name) { return ends_with(name, ".json") && !is_companion(name); }

std::string trim(const std::string& s) {
    const auto b = s.find_first_not_of(" \t\r");
    if (b == std::string::npos) return "";
    return s.substr(b, s.find_last_not_of(" \t\r") - b + 1);
}

}  // namespace

std::vector<std::string> find_task_files(const std::string& dir) {
    std::error_code ec;
    if (!fs::is_directory(dir, ec)) throw task::InputError(dir, "not a folder");
    std::vector<std::string> out;
    // Folders by what they are, not by the path that reached them: a link
    // to a folder already searched (itself, an ancestor) adds nothing, so
    // every task is found once and the search ends.
    // Breadth first, each folder's subfolders in name order: of two paths to
    // one folder, the shorter (then the first by name) names its tasks, the
    // same on every run.
    std::set<fs::path> searched;
    std::deque<fs::path> folders{fs::path(dir)};
    while (!folders.empty()) {
        const fs::path folder = folders.front();
        folders.pop_front();
        const fs::path real = fs::canonical(folder, ec);
        if (ec || !searched.insert(real).second) continue;
        std::vector<std::string> json, planted;
        std::vector<fs::path> subfolders;
        for (fs::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
            const fs::path& path = it->path();
            std::error_code kind;
            if (it->is_directory(kind)) {
                subfolders.push_back(path);
                continue;
            }
            // Anything else named as a task is one, also what cannot be read
            // (a link to itself, a FIFO): the run says why, as one row.
            const std::string name = path.filename().string();
            if (ends_with(name, ".task.json")) planted.push_back(path.generic_string());
            if (task_named(name)) json.push_back(path.generic_string());
        }
        const auto& found = planted.empty() ? json : planted;
        out.insert(out.end(), found.begin(), found.end());
        std::sort(subfolders.begin(), subfolders.end());
        folders.insert(folders.end(), subfolders.begin(), subfolders.end());
    }
    std::sort(out.begin(), out.end());
    return out;
}

std::vector<std::string> read_task_list(const std::string& list_file) {
    std::istringstream in(io::read_input_file(list_file, "task list", task::kMaxTaskBytes));
    std::vector<std::string> out;
    for (std::string line; std::getline(in, line);) {
        line = trim(line);
        if (!line.empty() && line[0] != '#') out.push_back(line);
    }
    std::sort(out.begin(), out.end());
    return out;
}

std::string task_stem(const std::string& path) {
    std::string name = fs::path(path).filename().string();
    for (const std::string suffix : {".task.json", ".json"})
        if (ends_with(name, suffix)) return name.substr(0, name.size() - suffix.size());
    return name;
}

namespace {

/// The deepest folder holding every path.
fs::path common_folder(const std::vector<fs::path>& paths) {
    fs::path common = paths.front().parent_path();
    for (const auto& p : paths) {
        const fs::path folder = p.parent_path();
        fs::path shared;
        for (auto a = common.begin(), b = folder.begin();
             a != common.end() && b != folder.end() && *a == *b; ++a, ++b)
            shared /= *a;
        common = shared;
    }
    return common;
}

}  // namespace

std::vector<std::string> output_names(const std::vector<std::string>& paths,
                                      const std::string& root) {
    if (paths.empty()) return {};
    std::vector<fs::path> full;
    for (const auto& p : paths) full.push_back(fs::absolute(p).lexically_normal());
    const fs::path base =
        root.empty() ? common_folder(full) : fs::absolute(root).lexically_normal();
    std::vector<fs::path> relative;
    std::map<std::string, std::set<std::string>> uses;
    for (const auto& p : full) {
        fs::path r = p.lexically_relative(base);
        if (r.empty() || *r.begin() == "..") r = p.filename();
        relative.push_back(r);
        uses[(r.parent_path() / task_stem(r.string())).generic_string()].insert(r.generic_string());
    }
    // x.json and x.task.json in one folder both shorten to x: then both keep
    // their whole file name. The same path listed twice gets "~2", "~3", ...
    std::vector<std::string> out;
    std::map<std::string, int> taken;
    for (const auto& r : relative) {
        const std::string stem = (r.parent_path() / task_stem(r.string())).generic_string();
        const std::string name = uses[stem].size() == 1 ? stem : r.generic_string();
        std::string unique = name;
        for (int n = 2; taken.count(unique); ++n) unique = name + "~" + std::to_string(n);
        ++taken[unique];
        out.push_back(unique);
    }
    return out;
}

Shard parse_shard(const std::string& text) {
    static const std::regex form(R"(\s*([0-9]{1,6})\s*/\s*([0-9]{1,6})\s*)");
    std::smatch m;
    if (!std::regex_match(text, m, form))
        throw task::InputError(
            "--shard", "expected K/N (e.g. 2/8), got '" + modsynth::text::printable(text) + "'");
    Shard s{std::stoi(m[1]), std::stoi(m[2])};
    if (s.count < 1 || s.index < 1 || s.index > s.count)
        throw task::InputError(
            "--shard", "K/N needs 1 <= K <= N, got '" + modsynth::text::printable(text) + "'");
    return s;
}

std::vector<std::size_t> shard_positions(std::size_t size, const Shard& shard) {
    std::vector<std::size_t> out;
    for (std::size_t i = static_cast<std::size_t>(shard.index - 1); i < size;
         i += static_cast<std::size_t>(shard.count))
        out.push_back(i);
    return out;
}

}  // namespace modsynth::app
