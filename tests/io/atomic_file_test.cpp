#include <catch2/catch.hpp>

#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include <modsynth/io/atomic_file.h>

namespace fs = std::filesystem;
using modsynth::io::write_file_atomically;

namespace {

std::string read(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

std::vector<std::string> names_in(const fs::path& dir) {
    std::vector<std::string> out;
    for (const auto& e : fs::directory_iterator(dir)) out.push_back(e.path().filename().string());
    std::sort(out.begin(), out.end());
    return out;
}

struct Folder {
    fs::path path;
    Folder() {
        std::string pattern = (fs::temp_directory_path() / "modsynth-atomic-XXXXXX").string();
        path = mkdtemp(pattern.data());
    }
    ~Folder() { fs::remove_all(path); }
};

}  // namespace

TEST_CASE("an atomic write replaces the file and leaves nothing else", "[output][atomic]") {
    Folder dir;
    const fs::path file = dir.path / "out.json";
    write_file_atomically(file.string(), "first\n");
    CHECK(read(file) == "first\n");
    write_file_atomically(file.string(), "second, longer\n");
    CHECK(read(file) == "second, longer\n");
    CHECK(names_in(dir.path) == std::vector<std::string>{"out.json"});
}

TEST_CASE("a failed atomic write names the path and removes its temporary file",
          "[output][atomic]") {
    Folder dir;
    // A folder in the target's place: the rename fails after the write.
    const fs::path target = dir.path / "taken";
    fs::create_directory(target);
    fs::create_directory(target / "inside");
    try {
        write_file_atomically(target.string(), "text");
        FAIL("no error");
    } catch (const std::runtime_error& e) {
        CHECK(std::string(e.what()).find(target.string()) != std::string::npos);
    }
    CHECK(fs::is_directory(target / "inside"));
    CHECK(names_in(dir.path) == std::vector<std::string>{"taken"});
    CHECK_THROWS_AS(write_file_atomically((dir.path / "no" / "x").string(), "text"),
                    std::runtime_error);
}

TEST_CASE("a write that fails midway leaves the previous file intact", "[output][atomic]") {
    Folder dir;
    const fs::path file = dir.path / "out.csv";
    const std::string old(1000, 'o');
    write_file_atomically(file.string(), old);
    const pid_t pid = fork();
    if (pid == 0) {
        // A file size limit makes the write fail after its first 4 KiB.
        signal(SIGXFSZ, SIG_IGN);
        const rlimit limit{4096, 4096};
        setrlimit(RLIMIT_FSIZE, &limit);
        try {
            write_file_atomically(file.string(), std::string(100000, 'n'));
        } catch (const std::runtime_error&) {
            _exit(0);
        }
        _exit(1);
    }
    int status = 0;
    waitpid(pid, &status, 0);
    CHECK(WIFEXITED(status));
    CHECK(WEXITSTATUS(status) == 0);
    CHECK(read(file) == old);
    CHECK(names_in(dir.path) == std::vector<std::string>{"out.csv"});
}

TEST_CASE("SIGTERM during a write leaves the old or the new file whole, and no temporary file",
          "[output][atomic]") {
    Folder dir;
    const fs::path file = dir.path / "report.html";
    const std::string old = "old report\n";
    write_file_atomically(file.string(), old);
    const std::string fresh(64 << 20, 'n');
    const pid_t pid = fork();
    if (pid == 0) {
        signal(SIGTERM, SIG_DFL);  // the test runner's handler stays behind
        write_file_atomically(file.string(), fresh);
        _exit(0);
    }
    // Strike as soon as the write is visibly under way.
    const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(10);
    while (std::chrono::steady_clock::now() < until && names_in(dir.path).size() == 1 &&
           fs::file_size(file) == old.size())
        std::this_thread::sleep_for(std::chrono::microseconds(200));
    kill(pid, SIGTERM);
    int status = 0;
    waitpid(pid, &status, 0);
    const std::string now = read(file);
    CHECK((now == old || now == fresh));
    CHECK(names_in(dir.path) == std::vector<std::string>{"report.html"});
}

TEST_CASE("an atomic write keeps a symbolic link and writes through a device", "[output][atomic]") {
    Folder dir;
    const fs::path file = dir.path / "real.json", link = dir.path / "link.json";
    write_file_atomically(file.string(), "old");
    fs::create_symlink(file, link);
    write_file_atomically(link.string(), "new");
    CHECK(fs::is_symlink(link));
    CHECK(read(file) == "new");
    CHECK(names_in(dir.path) == std::vector<std::string>{"link.json", "real.json"});
    write_file_atomically("/dev/null", "discarded");
    CHECK(fs::is_character_file("/dev/null"));
}

TEST_CASE("a file written piece by piece appears whole at commit, or not at all",
          "[output][atomic]") {
    using modsynth::io::AtomicFile;
    Folder dir;
    const fs::path file = dir.path / "motion.json";
    write_file_atomically(file.string(), "old");
    {
        AtomicFile out(file.string());
        out.write("new ");
        out.write("text");
        CHECK(out.bytes() == 8);
        // Until the commit the old file stays, beside the temporary one.
        CHECK(read(file) == "old");
        out.commit();
    }
    CHECK(read(file) == "new text");
    CHECK(names_in(dir.path) == std::vector<std::string>{"motion.json"});
    {
        AtomicFile out(file.string());
        out.write("abandoned");
    }
    CHECK(read(file) == "new text");
    CHECK(names_in(dir.path) == std::vector<std::string>{"motion.json"});
    const pid_t pid = fork();
    if (pid == 0) {
        // The first write over the size limit fails; commit says so and
        // the previous file stays.
        signal(SIGXFSZ, SIG_IGN);
        const rlimit limit{4096, 4096};
        setrlimit(RLIMIT_FSIZE, &limit);
        try {
            AtomicFile out(file.string());
            for (int i = 0; i < 100; ++i) out.write(std::string(1000, 'x'));
            out.commit();
        } catch (const modsynth::io::WriteError& e) {
            _exit(std::string(e.what()).find("write failed") != std::string::npos ? 0 : 2);
        }
        _exit(1);
    }
    int status = 0;
    waitpid(pid, &status, 0);
    CHECK(WIFEXITED(status));
    CHECK(WEXITSTATUS(status) == 0);
    CHECK(read(file) == "new text");
    CHECK(names_in(dir.path) == std::vector<std::string>{"motion.json"});
}
