#include <catch2/catch.hpp>

#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <modsynth/io/output_check.h>
#include <modsynth/task/input_error.h>

namespace fs = std::filesystem;
using Catch::Matchers::Contains;
using modsynth::io::check_outputs;
using modsynth::task::InputError;

namespace {

struct Folder {
    fs::path path;
    Folder() {
        std::string pattern = (fs::temp_directory_path() / "modsynth-outputs-XXXXXX").string();
        path = mkdtemp(pattern.data());
    }
    ~Folder() { fs::remove_all(path); }
    std::string file(const std::string& name, const std::string& text = "x") const {
        std::ofstream(path / name) << text;
        return (path / name).string();
    }
};

std::string refusal(const std::vector<modsynth::io::OutputFile>& outputs,
                    const std::vector<std::string>& inputs) {
    try {
        check_outputs(outputs, inputs);
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

}  // namespace

TEST_CASE("outputs are regular files or new names, checked before any work", "[io][outputs]") {
    Folder dir;
    const std::string task = dir.file("task.json");
    const std::string old = dir.file("old.json");
    // A regular file is replaced, a new name made, an empty path not asked.
    CHECK(refusal({{"-o", old}, {"--report", (dir.path / "new.html").string()}, {"--csv", ""}},
                  {task})
              .empty());
    const std::string fifo = (dir.path / "fifo").string();
    REQUIRE(mkfifo(fifo.c_str(), 0600) == 0);
    CHECK_THAT(refusal({{"--report", fifo}}, {task}),
               Contains("--report " + fifo) && Contains("is not a regular file"));
    CHECK_THAT(refusal({{"--events", "/dev/full"}}, {task}), Contains("is not a regular file"));
    CHECK_THAT(refusal({{"-o", dir.path.string()}}, {task}), Contains("is a folder"));
    const std::string missing = (dir.path / "missing" / "dir" / "x.json").string();
    CHECK_THAT(refusal({{"-o", missing}}, {task}), Contains("does not exist"));
}

TEST_CASE("an output is never an input, by any path, nor another output", "[io][outputs]") {
    Folder dir;
    const std::string task = dir.file("task.json", "the task");
    CHECK_THAT(refusal({{"-o", task}}, {task}), Contains("is the input"));
    // Another spelling of the same file, and a link to it.
    const std::string spelled = (dir.path / "." / "task.json").string();
    CHECK_THAT(refusal({{"--report", spelled}}, {task}), Contains("is the input"));
    const std::string link = (dir.path / "link.json").string();
    fs::create_symlink(task, link);
    CHECK_THAT(refusal({{"--events", link}}, {task}), Contains("is the input"));
    // Two outputs of one new name.
    const std::string fresh = (dir.path / "out.json").string();
    CHECK_THAT(refusal({{"-o", fresh}, {"--csv", (dir.path / "." / "out.json").string()}}, {task}),
               Contains("also the output of -o"));
    std::ifstream in(task);
    std::string text;
    std::getline(in, text);
    CHECK(text == "the task");
}
