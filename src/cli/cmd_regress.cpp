// `modsynth regress encodings`: the committed front-stage encodings and
// solve figures of every task in tasks/, planar and spatial, re-run and
// compared. A change for
// the worse (a status lost, a claim of infeasibility appearing or vanishing,
// another core, a longer robot) exits 1; a change for the better is reported
// and passes, since the figures are expected to improve with the solver.
#include <modsynth/io/atomic_file.h>
#include <modsynth/io/input.h>
#include <modsynth/io/task_document.h>
#include <modsynth/io/task_io.h>
#include <modsynth/run/stopwatch.h>
#include <modsynth/smt/front_stage.h>
#include <modsynth/smt/spatial_front_stage.h>
#include <modsynth/text/format.h>
#include <modsynth/text/printable.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <variant>
#include <vector>

#include "command.h"
#include "number_checks.h"
#include "solve_runner.h"
#include "task_files.h"
#include "temp_dir.h"

namespace modsynth::app {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

constexpr const char* kFormat = "modsynth-encodings/1";

struct RegressArgs {
    std::string dir = "encodings", tasks = "tasks";
    double tolerance = 0.05;
    bool regenerate = false;
    SolveRunOptions run;
};

struct FrontFigures {
    int dof = 0;
    smt::FrontStage::Result result = smt::FrontStage::Result::Unknown;
    std::vector<std::string> core;
    double seconds = 0.0;
    std::string encoding;  ///< SMT-LIB2 text (fresh runs only)
};

struct SolveFigures {
    RunStatus status;
    std::optional<int> dof;
    std::optional<double> total_link_length;
    std::vector<std::string> core;
    double seconds = 0.0;
};

struct Figures {
    std::string name;
    std::vector<FrontFigures> front;
    SolveFigures solve;
};

/// One task of the suite and where its expectation lives.
struct Entry {
    std::string task_path;
    std::string key;    ///< path under tasks/ without ".task.json"/".json"
    std::string error;  ///< why the task cannot be run, if it cannot
    Figures now;
};

// ---------------------------------------------------------------- file names

std::string key_of(const std::string& task_path, const std::string& tasks_dir) {
    // By the path's text when it cannot be resolved (a link to itself).
    std::error_code ec;
    fs::path rel = fs::relative(task_path, tasks_dir, ec);
    if (ec) rel = fs::path(task_path).lexically_relative(tasks_dir);
    return (rel.parent_path() / task_stem(task_path)).generic_string();
}

std::string expectation_path(const std::string& dir, const std::string& key) {
    return (fs::path(dir) / (key + ".expect.json")).string();
}

std::string encoding_name(const std::string& key, int dof) {
    return fs::path(key).filename().string() + ".dof" + std::to_string(dof) + ".smt2";
}

std::string encoding_path(const std::string& dir, const std::string& key, int dof) {
    return (fs::path(dir) / fs::path(key).parent_path() / encoding_name(key, dof)).string();
}

bool is_suite_file(const fs::path& p) {
    const std::string name = p.filename().string();
    const auto has_suffix = [&](const std::string& s) {
        return name.size() > s.size() && name.compare(name.size() - s.size(), s.size(), s) == 0;
    };
    return has_suffix(".expect.json") || has_suffix(".smt2");
}

// Far more than the suite writes (a 5,000-primitive task's encoding is a
// few megabytes): a file past it is not one of the suite's.
constexpr std::size_t kLargestSuiteFile = 64u << 20;

/// A suite file's text, or nothing when there is no such file. One that
/// cannot be read, is not a regular file or is too large is refused as any
/// input is (task::InputError naming it).
std::optional<std::string> read_text(const std::string& path) {
    std::error_code ec;
    if (!fs::exists(fs::symlink_status(path, ec))) return std::nullopt;
    return io::read_input_file(path, "suite", kLargestSuiteFile);
}

void write_text(const std::string& path, const std::string& text) {
    fs::create_directories(fs::path(path).parent_path());
    io::write_file_atomically(path, text);
}

// ------------------------------------------------------------- fresh figures

const char* result_name(smt::FrontStage::Result r) {
    switch (r) {
        case smt::FrontStage::Result::Sat:
            return "sat";
        case smt::FrontStage::Result::Unsat:
            return "unsat";
        case smt::FrontStage::Result::Unknown:
            return "unknown";
    }
    return "unknown";
}

smt::FrontStage::Result result_from_name(const std::string& name, const std::string& part) {
    using R = smt::FrontStage::Result;
    for (const R r : {R::Sat, R::Unsat, R::Unknown})
        if (name == result_name(r)) return r;
    throw task::InputError(part,
                           "expected sat, unsat or unknown, got \"" + text::printable(name) + "\"");
}

// In-process: the front stage is Z3's nlsat, which honours its timeout, and
// Ipopt is not involved.
FrontFigures run_front(const task::Task& task, int dof) {
    const run::Stopwatch t0;
    smt::FrontStage front(task, dof);
    FrontFigures f;
    f.dof = dof;
    f.encoding = front.smtlib();
    const auto result = front.check();
    f.result = result;
    if (result == smt::FrontStage::Result::Unsat) f.core = task::to_strings(front.minimal_core());
    f.seconds = t0.seconds();
    return f;
}

// The spatial front stage's relaxation, as the suite records the plane's:
// its encoding, its answer and, when unsat, its minimal core.
FrontFigures run_front(const task::SpatialTask& task, int dof) {
    const run::Stopwatch t0;
    smt::SpatialFrontStage front(task, dof);
    FrontFigures f;
    f.dof = dof;
    f.encoding = front.smtlib();
    switch (front.check()) {
        case smt::SpatialFrontStage::Result::Sat:
            f.result = smt::FrontStage::Result::Sat;
            break;
        case smt::SpatialFrontStage::Result::Unsat:
            f.result = smt::FrontStage::Result::Unsat;
            f.core = task::to_strings(front.minimal_core());
            break;
        case smt::SpatialFrontStage::Result::Unknown:
            f.result = smt::FrontStage::Result::Unknown;
            break;
    }
    f.seconds = t0.seconds();
    return f;
}

std::vector<Entry> discover(const RegressArgs& a) {
    std::vector<Entry> out;
    for (const auto& path : find_task_files(a.tasks)) {
        Entry e;
        e.task_path = path;
        e.key = key_of(path, a.tasks);
        try {
            // Either kind: its own front stage per joint count, the same
            // figures, and the same `modsynth solve` in a child process.
            std::visit(
                [&](const auto& t) {
                    e.now.name = t.name;
                    for (int dof : t.robot.dof) e.now.front.push_back(run_front(t, dof));
                },
                io::load_task_document(path));
        } catch (const task::InputError& err) {
            e.error = err.what();
        }
        out.push_back(std::move(e));
    }
    return out;
}

// Solves go through child processes, as in `batch`: a hard time limit, and
// the figures are those a user of `solve` gets.
void run_full_solves(std::vector<Entry>& entries, const SolveRunOptions& options) {
    TempDir scratch("modsynth-regress");
    std::vector<SolveJob> jobs;
    std::vector<Entry*> of_job;
    for (auto& e : entries) {
        if (!e.error.empty()) continue;
        const std::string base = scratch.path() + "/" + std::to_string(jobs.size());
        jobs.push_back({e.task_path, base + ".solution.json", base + ".log"});
        of_job.push_back(&e);
    }
    run_solves(jobs, options, [&](std::size_t i, const SolveOutcome& o) {
        SolveFigures& s = of_job[i]->now.solve;
        s.status = o.status;
        s.dof = o.dof;
        s.total_link_length = o.total_link_length;
        s.core = o.core;
        s.seconds = o.seconds;
    });
}

// ---------------------------------------------------------- expectation files

Json optional_json(const std::optional<double>& v) { return v ? Json(*v) : Json(nullptr); }

// Dividing by the power of ten gives the double nearest the decimal, which
// JSON then prints without a tail of noise.
double rounded(double v, int decimals) {
    const double scale = std::pow(10.0, decimals);
    return std::round(v * scale) / scale;
}

Json to_json(const Entry& e, const std::string& task, double time_limit) {
    Json front = Json::array();
    for (const auto& f : e.now.front)
        front.push_back({{"dof", f.dof},
                         {"encoding", encoding_name(e.key, f.dof)},
                         {"result", result_name(f.result)},
                         {"core", f.core},
                         {"seconds", rounded(f.seconds, 3)}});
    const SolveFigures& s = e.now.solve;
    Json solve = {
        {"status", to_string(s.status)},
        {"dof", s.dof ? Json(*s.dof) : Json(nullptr)},
        {"total_link_length",
         optional_json(s.total_link_length ? std::optional<double>(rounded(*s.total_link_length, 6))
                                           : std::nullopt)},
        {"core", s.core},
        {"seconds", rounded(s.seconds, 3)},
        {"time_limit", time_limit}};
    return {{"format", kFormat},
            {"task", task},
            {"name", e.now.name},
            {"front_stage", front},
            {"solve", solve}};
}

std::vector<std::string> strings_of(const nlohmann::json& j) {
    std::vector<std::string> out;
    if (j.is_array())
        for (const auto& s : j)
            if (s.is_string()) out.push_back(s.get<std::string>());
    return out;
}

/// Throws std::runtime_error naming what is missing.
Figures parse_expectation(const nlohmann::json& doc) {
    if (!doc.is_object() || doc.value("format", "") != kFormat)
        throw std::runtime_error(std::string("not a ") + kFormat + " document");
    Figures f;
    f.name = doc.value("name", "");
    for (const auto& x : doc.at("front_stage")) {
        FrontFigures ff;
        ff.dof = x.at("dof").get<int>();
        ff.result = result_from_name(x.at("result").get<std::string>(), "front_stage.result");
        ff.core = strings_of(x.value("core", nlohmann::json::array()));
        ff.seconds = x.value("seconds", 0.0);
        f.front.push_back(ff);
    }
    const auto& s = doc.at("solve");
    f.solve.status = run_status_from_string(s.at("status").get<std::string>(), "solve.status");
    if (s.contains("dof") && s["dof"].is_number_integer()) f.solve.dof = s["dof"].get<int>();
    if (s.contains("total_link_length") && s["total_link_length"].is_number())
        f.solve.total_link_length = s["total_link_length"].get<double>();
    f.solve.core = strings_of(s.value("core", nlohmann::json::array()));
    f.solve.seconds = s.value("seconds", 0.0);
    return f;
}

std::optional<Figures> load_expectation(const std::string& path, std::string& why) {
    try {
        const auto text = read_text(path);
        if (!text) {
            why = "no expectation " + path + " (scripts/regen-encodings writes it)";
            return std::nullopt;
        }
        return parse_expectation(nlohmann::json::parse(*text));
    } catch (const std::exception& e) {
        why = path + ": unreadable expectation: " + e.what();
        return std::nullopt;
    }
}

// ------------------------------------------------------------------ judging

enum class Verdict { Same, Improved, Regressed };

struct Judgement {
    Verdict verdict = Verdict::Same;
    std::string why;
};

struct Row {
    std::string task, check, encoding = "-", expected, now, seconds;
    Judgement judgement;
};

bool same_set(std::vector<std::string> a, std::vector<std::string> b) {
    std::sort(a.begin(), a.end());
    std::sort(b.begin(), b.end());
    return a == b;
}

std::string braces(const std::vector<std::string>& parts) {
    std::string s = "{";
    for (std::size_t i = 0; i < parts.size(); ++i) s += (i ? ", " : "") + parts[i];
    return s + "}";
}

Judgement judge_front(const FrontFigures& e, const FrontFigures& n) {
    if (e.result == n.result) {
        if (n.result == smt::FrontStage::Result::Unsat && !same_set(e.core, n.core))
            return {Verdict::Regressed, "core " + braces(n.core) + ", expected " + braces(e.core)};
        return {};
    }
    if (e.result == smt::FrontStage::Result::Unknown && n.result == smt::FrontStage::Result::Sat)
        return {Verdict::Improved, "now decided"};
    return {Verdict::Regressed,
            std::string("was ") + result_name(e.result) + ", now " + result_name(n.result)};
}

// Failed runs (timeout, error, ...) rank below unknown: both are non-answers,
// but unknown is an orderly one.
int rank(const RunStatus& status) {
    if (status == synth::Status::Solved) return 2;
    return status == synth::Status::Unknown ? 1 : 0;
}

std::string was_now(const SolveFigures& e, const SolveFigures& n) {
    return "was " + to_string(e.status) + ", now " + to_string(n.status);
}

Judgement judge_solved(const SolveFigures& e, const SolveFigures& n, double tolerance) {
    if (!e.dof || !e.total_link_length) return {Verdict::Improved, "expectation had no robot"};
    if (!n.dof || !n.total_link_length) return {Verdict::Regressed, "solution has no robot"};
    if (*n.dof != *e.dof) {
        const std::string why = std::to_string(*n.dof) + " joints, was " + std::to_string(*e.dof);
        return {*n.dof < *e.dof ? Verdict::Improved : Verdict::Regressed, why};
    }
    const double was = *e.total_link_length, now = *n.total_link_length;
    const double change = now / was - 1.0;
    const std::string why =
        text::format("total link length %.4f m, was %.4f m (%+.1f%%)", now, was, 100 * change);
    if (change > tolerance)
        return {Verdict::Regressed, why + text::format(", tolerance %.0f%%", 100 * tolerance)};
    if (change < -tolerance) return {Verdict::Improved, why};
    return {};
}

Judgement judge_solve(const SolveFigures& e, const SolveFigures& n, double tolerance) {
    if (e.status == synth::Status::Infeasible || n.status == synth::Status::Infeasible) {
        if (e.status != n.status) return {Verdict::Regressed, was_now(e, n)};
        if (!same_set(e.core, n.core))
            return {Verdict::Regressed, "core " + braces(n.core) + ", expected " + braces(e.core)};
        return {};
    }
    if (rank(n.status) < rank(e.status)) return {Verdict::Regressed, was_now(e, n)};
    if (rank(n.status) > rank(e.status)) return {Verdict::Improved, was_now(e, n)};
    return n.status == synth::Status::Solved ? judge_solved(e, n, tolerance) : Judgement{};
}

// ------------------------------------------------------------------ display

std::string show_front(const FrontFigures& f) {
    return f.result == smt::FrontStage::Result::Unsat
               ? "unsat, core of " + std::to_string(f.core.size())
               : result_name(f.result);
}

std::string show_solve(const SolveFigures& s) {
    if (s.status == synth::Status::Solved && s.dof && s.total_link_length)
        return text::format("solved, %d joints, %.4f m", *s.dof, *s.total_link_length);
    if (s.status == synth::Status::Infeasible)
        return to_string(s.status) + ", core of " + std::to_string(s.core.size());
    return to_string(s.status);
}

std::string show_seconds(double was, double now) { return text::format("%.2f -> %.2f", was, now); }

// Timings vary from machine to machine: only a large slowdown is worth a
// note, and never a failure.
void note_slowdown(Row& row, double was, double now) {
    if (now > 2.0 * was + 0.5 && row.judgement.why.empty()) row.judgement.why = "slower";
}

Row row_for(const std::string& task, const std::string& check) {
    Row r;
    r.task = task;
    r.check = check;
    r.expected = r.now = r.seconds = "-";
    return r;
}

Row problem(const std::string& task, const std::string& check, const std::string& why) {
    Row r = row_for(task, check);
    r.judgement = {Verdict::Regressed, why};
    return r;
}

const FrontFigures* find_dof(const std::vector<FrontFigures>& v, int dof) {
    for (const auto& f : v)
        if (f.dof == dof) return &f;
    return nullptr;
}

std::string encoding_state(const std::string& path, const std::string& fresh) {
    std::optional<std::string> stored;
    try {
        stored = read_text(path);
    } catch (const task::InputError&) {
        return "unreadable";
    }
    if (!stored) return "missing";
    return *stored == fresh ? "same" : "changed";
}

Row front_row(const Entry& e, const FrontFigures& n, const Figures& expected,
              const std::string& dir) {
    Row row = row_for(e.key, "front stage, " + std::to_string(n.dof) + " joints");
    row.encoding = encoding_state(encoding_path(dir, e.key, n.dof), n.encoding);
    row.now = show_front(n);
    const FrontFigures* x = find_dof(expected.front, n.dof);
    if (!x) {
        row.expected = "-";
        row.seconds = text::format("- -> %.2f", n.seconds);
        row.judgement = {Verdict::Regressed, "no expectation for this joint count"};
        return row;
    }
    row.expected = show_front(*x);
    row.seconds = show_seconds(x->seconds, n.seconds);
    row.judgement = judge_front(*x, n);
    if (row.encoding == "missing" || row.encoding == "unreadable")
        row.judgement = {Verdict::Regressed,
                         "encoding file " + encoding_name(e.key, n.dof) + " " + row.encoding};
    note_slowdown(row, x->seconds, n.seconds);
    return row;
}

std::vector<Row> rows_of(const Entry& e, const RegressArgs& a) {
    if (!e.error.empty()) return {problem(e.key, "task", e.error)};
    std::string why;
    const auto expected = load_expectation(expectation_path(a.dir, e.key), why);
    if (!expected) return {problem(e.key, "expectation", why)};
    std::vector<Row> rows;
    for (const auto& n : e.now.front) rows.push_back(front_row(e, n, *expected, a.dir));
    for (const auto& x : expected->front)
        if (!find_dof(e.now.front, x.dof)) {
            Row gone = problem(e.key, "front stage, " + std::to_string(x.dof) + " joints",
                               "the task no longer allows this joint count");
            gone.expected = show_front(x);
            rows.push_back(gone);
        }
    Row solve = row_for(e.key, "solve");
    solve.expected = show_solve(expected->solve);
    solve.now = show_solve(e.now.solve);
    solve.seconds = show_seconds(expected->solve.seconds, e.now.solve.seconds);
    solve.judgement = judge_solve(expected->solve, e.now.solve, a.tolerance);
    note_slowdown(solve, expected->solve.seconds, e.now.solve.seconds);
    rows.push_back(solve);
    return rows;
}

/// Expectations whose task is gone: the suite would silently shrink.
std::vector<Row> stale_rows(const std::vector<Entry>& entries, const std::string& dir) {
    std::set<std::string> known;
    for (const auto& e : entries)
        known.insert(fs::path(expectation_path(dir, e.key)).lexically_normal().string());
    std::vector<Row> rows;
    if (!fs::is_directory(dir)) return rows;
    for (const auto& f : fs::recursive_directory_iterator(dir)) {
        const std::string p = f.path().lexically_normal().string();
        const std::string name = f.path().filename().string();
        if (name.size() > 12 && name.ends_with(".expect.json") && !known.count(p))
            rows.push_back(problem(fs::relative(f.path(), dir).generic_string(), "expectation",
                                   "its task is gone from the task folder"));
    }
    return rows;
}

const char* verdict_name(Verdict v) {
    switch (v) {
        case Verdict::Same:
            return "ok";
        case Verdict::Improved:
            return "improved";
        case Verdict::Regressed:
            return "REGRESSED";
    }
    return "?";
}

void print_table(const std::vector<Row>& rows) {
    const auto cells = [](const Row& r) {
        return std::vector<std::string>{r.task,
                                        r.check,
                                        r.encoding,
                                        r.expected,
                                        r.now,
                                        r.seconds,
                                        verdict_name(r.judgement.verdict)};
    };
    std::vector<std::string> head = {"task", "check",   "encoding", "expected",
                                     "now",  "seconds", "verdict"};
    std::vector<std::size_t> width(head.size());
    for (std::size_t c = 0; c < head.size(); ++c) width[c] = head[c].size();
    for (const auto& r : rows) {
        const auto cs = cells(r);
        for (std::size_t c = 0; c < cs.size(); ++c) width[c] = std::max(width[c], cs[c].size());
    }
    const auto print = [&](const std::vector<std::string>& cs, const std::string& tail) {
        std::string line;
        for (std::size_t c = 0; c < cs.size(); ++c)
            line += cs[c] + std::string(width[c] - cs[c].size() + 2, ' ');
        line += tail;
        std::printf("%s\n", line.substr(0, line.find_last_not_of(' ') + 1).c_str());
    };
    print(head, "");
    for (const auto& r : rows) print(cells(r), r.judgement.why);
}

int report(const std::vector<Row>& rows) {
    print_table(rows);
    int regressed = 0, improved = 0, changed = 0;
    for (const auto& r : rows) {
        regressed += r.judgement.verdict == Verdict::Regressed;
        improved += r.judgement.verdict == Verdict::Improved;
        changed += r.encoding == "changed";
    }
    std::printf("\n%zu checks: %d regressed, %d improved, %zu unchanged\n", rows.size(), regressed,
                improved, rows.size() - regressed - improved);
    for (const auto& r : rows)
        if (r.judgement.verdict == Verdict::Regressed)
            std::printf("REGRESSED %s: %s: %s\n", r.task.c_str(), r.check.c_str(),
                        r.judgement.why.c_str());
    if (changed > 0)
        std::printf(
            "%d encoding(s) differ from the committed dumps: not a regression by itself; "
            "scripts/regen-encodings refreshes them\n",
            changed);
    if (improved > 0 && regressed == 0)
        std::printf("improvements: scripts/regen-encodings records them as the new expectation\n");
    return regressed == 0 ? kOk : kInternal;
}

// ------------------------------------------------------------- regeneration

void remove_stale_files(const std::string& dir, const std::set<std::string>& written) {
    std::vector<fs::path> stale;
    for (const auto& f : fs::recursive_directory_iterator(dir))
        if (f.is_regular_file() && is_suite_file(f.path()) &&
            !written.count(f.path().lexically_normal().string()))
            stale.push_back(f.path());
    for (const auto& p : stale) {
        std::printf("removed %s\n", p.string().c_str());
        fs::remove(p);
    }
}

int regenerate(const std::vector<Entry>& entries, const RegressArgs& a) {
    std::set<std::string> written;
    const auto keep = [&](const std::string& path, const std::string& text) {
        write_text(path, text);
        written.insert(fs::path(path).lexically_normal().string());
    };
    for (const auto& e : entries) {
        if (!e.error.empty()) throw task::InputError(e.task_path, e.error);
        for (const auto& f : e.now.front) keep(encoding_path(a.dir, e.key, f.dof), f.encoding);
        const Json doc =
            to_json(e, fs::relative(e.task_path, a.tasks).generic_string(), a.run.time_limit);
        keep(expectation_path(a.dir, e.key), doc.dump(1) + "\n");
        std::printf("%-28s solve %-28s front stage", e.key.c_str(),
                    show_solve(e.now.solve).c_str());
        for (const auto& f : e.now.front) std::printf(" [%d: %s]", f.dof, show_front(f).c_str());
        std::printf("\n");
        if (!e.now.solve.status.is_answer())
            std::printf("  warning: the solve failed (%s); recorded as such\n",
                        to_string(e.now.solve.status).c_str());
    }
    if (fs::is_directory(a.dir)) remove_stale_files(a.dir, written);
    std::printf("wrote %zu expectations to %s\n", entries.size(), a.dir.c_str());
    return kOk;
}

int run_encodings(const RegressArgs& a) {
    if (!a.regenerate && !fs::is_directory(a.dir))
        throw task::InputError(a.dir, "no such folder (scripts/regen-encodings creates it)");
    std::vector<Entry> entries = discover(a);
    run_full_solves(entries, a.run);
    if (a.regenerate) return regenerate(entries, a);
    std::vector<Row> rows;
    for (const auto& e : entries) {
        const auto r = rows_of(e, a);
        rows.insert(rows.end(), r.begin(), r.end());
    }
    const auto stale = stale_rows(entries, a.dir);
    rows.insert(rows.end(), stale.begin(), stale.end());
    return report(rows);
}

}  // namespace

Command add_regress(CLI::App& parent) {
    auto a = std::make_shared<RegressArgs>();
    CLI::App* sub = parent.add_subcommand(
        "regress", "Regression suites (exit 0: nothing regressed, 1: something did)");
    sub->require_subcommand(1);
    CLI::App* enc = sub->add_subcommand(
        "encodings",
        "Re-run the front-stage encodings and full solves of every task against encodings/");
    enc->add_option("--dir", a->dir,
                    "the committed encodings and expectations (default encodings)");
    enc->add_option("--tasks", a->tasks, "the task folder, searched recursively (default tasks)");
    enc->add_option("--tolerance", a->tolerance,
                    "relative change of total link length that counts (default 0.05)")
        ->check(within(0.0, 10.0));
    enc->add_option("--time-limit", a->run.time_limit, "seconds per solve (default 60)")
        ->check(seconds());
    enc->add_option("-j,--jobs", a->run.jobs, "solves at once (default 1)")
        ->check(CLI::Range(1, 4096));
    enc->add_flag("--regenerate", a->regenerate,
                  "rewrite the encodings and expectations from this build instead of comparing");
    return {sub, [a] { return run_encodings(*a); }};
}

}  // namespace modsynth::app
