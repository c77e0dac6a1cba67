#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <variant>

#include <nlohmann/json.hpp>

#include <modsynth/io/json_numbers.h>
#include <modsynth/io/solution_io.h>
#include <modsynth/io/task_document.h>
#include <modsynth/output/recertify.h>
#include <modsynth/text/format.h>
#include <modsynth/text/printable.h>

#include "command.h"
#include "task_file.h"

namespace modsynth::app {
namespace {

struct CertifyArgs {
    std::string task, solution;
    bool json = false;
    bool strict = false;
};

std::string margin_text(const char* what, double v) {
    return std::isfinite(v) ? text::format("%s %.6f m", what, v)
                            : std::string("no ") + what + " (nothing to check)";
}

int run_certify(const CertifyArgs& a) {
    const io::TaskDocument doc = read_task_file(a.task, a.strict);
    io::ParsedSolution parsed = io::load_solution(a.solution);
    std::visit([&](const auto& t) { output::recertify(t, parsed); }, doc);
    const synth::Solution& s = parsed.solution;
    const bool solved = s.status == synth::Status::Solved;
    const verify::Certificate& c = s.certificate;
    const bool ok = solved && c.ok;
    const std::string reason =
        !solved ? std::string("the solution is \"") + synth::to_string(s.status) + "\", not solved"
                : output::uncertified_reason(c);
    const std::string name = std::visit([](const auto& t) { return t.name; }, doc);
    if (a.json) {
        nlohmann::json out = {
            {"task", name},
            {"space", std::holds_alternative<task::SpatialTask>(doc) ? "3d" : "plane"},
            {"certified", ok},
            {"reason", reason}};
        if (solved) {
            out["samples"] = s.samples.size();
            out["min_clearance_margin"] = io::finite_or_null(c.min_clearance);
            out["min_self_collision_margin"] = io::finite_or_null(c.min_self_clearance);
            out["max_ee_deviation"] = c.max_deviation;
            out["max_joint_step"] = c.max_joint_step;
            if (std::isfinite(c.min_tool_angle_margin))
                out["min_tool_angle_margin"] = c.min_tool_angle_margin;
            out["violations"] = c.violations.size();
            out["coarse_pairs"] = c.coarse_pairs.size();
        }
        std::printf("%s\n", out.dump().c_str());
    } else if (ok) {
        std::printf(
            "%s: certified: %zu samples, max EE deviation %.6f m, %s, %s, max joint step "
            "%.6f rad\n",
            text::printable(name, 80).c_str(), s.samples.size(), c.max_deviation,
            margin_text("clearance margin", c.min_clearance).c_str(),
            margin_text("self-collision margin", c.min_self_clearance).c_str(), c.max_joint_step);
    } else {
        std::printf("%s: not certified: %s\n", text::printable(name, 80).c_str(), reason.c_str());
    }
    return ok ? int{kOk} : int{kNotCertified};
}

}  // namespace

Command add_certify(CLI::App& parent) {
    auto a = std::make_shared<CertifyArgs>();
    CLI::App* sub = parent.add_subcommand(
        "certify",
        "Check a solution file against its task over the whole motion (exit 0 certified, "
        "5 not certified, 2 invalid)");
    sub->add_option("TASK", a->task, "modsynth-task/1 JSON file (planar or spatial)")->required();
    sub->add_option("SOLUTION", a->solution, "modsynth-solution/1 JSON file")->required();
    sub->add_flag("--json", a->json, "print one JSON object instead of a line");
    add_strict_option(*sub, a->strict);
    return {sub, [a] { return run_certify(*a); }};
}

}  // namespace modsynth::app
