// A program that embeds modsynth through its public API alone: the build
// gives it only the public headers (tests/CMakeLists.txt copies them apart),
// so a public header that needs an internal one breaks this build.
//
//   modsynth_embed_example TASK.json
//
//   modsynth_embed_example TASK.json SOLUTION.json
//
// Designs a robot for the task (with the modules that carry it), certifies
// the answer again as a reader of the solution document would, or explains
// why there is none; with SOLUTION.json, writes the answer there too (the
// same bytes as `modsynth solve TASK.json -o SOLUTION.json`). Exit 0 when
// solved and re-certified, 1 when proved infeasible and explained, 2 on bad
// input, 3 otherwise.
#include <cstdio>
#include <exception>
#include <fstream>
#include <iterator>
#include <string>

#include <modsynth/modsynth.h>

namespace {

bool write(const char* path, const modsynth::Solution& solution) {
    std::ofstream out(path, std::ios::binary);
    out << modsynth::write_solution_json(solution);
    if (!out) std::fprintf(stderr, "error: %s cannot be written\n", path);
    return static_cast<bool>(out);
}

// A spatial task: its DH chain, re-certified from the document, or why
// there is none.
int answer_spatial(const char* path, const char* solution_path) {
    const modsynth::SpatialTask task = modsynth::load_spatial_task(path);
    modsynth::SolveOptions options;
    options.time_limit = 30.0;
    const modsynth::Solution solution = modsynth::solve(task, options);
    if (solution_path && !write(solution_path, solution)) return 3;
    if (solution.status == modsynth::Status::Solved) {
        const modsynth::Solution read =
            modsynth::read_solution(modsynth::write_solution_json(solution));
        const modsynth::Certificate again = modsynth::certify(task, read);
        std::printf("%s: solved with %d joints, chain %.4f m; re-certified: %s\n",
                    task.name.c_str(), read.dh_robot->dof(), read.dh_robot->total_length(),
                    again.ok ? "yes" : "no");
        if (solution.modules) std::printf("  %s\n", solution.modules->message.c_str());
        return again.ok ? 0 : 3;
    }
    std::printf("%s: %s\n", task.name.c_str(), solution.explanation.message.c_str());
    for (const auto& part : solution.explanation.core)
        std::printf("  conflicting: %s\n", to_string(part).c_str());
    return solution.status == modsynth::Status::Infeasible ? 1 : 3;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 2 && argc != 3) {
        std::fprintf(stderr, "usage: %s TASK.json [SOLUTION.json]\n", argv[0]);
        return 2;
    }
    try {
        std::ifstream in(argv[1], std::ios::binary);
        const std::string text((std::istreambuf_iterator<char>(in)), {});
        if (in && modsynth::is_spatial_task(text))
            return answer_spatial(argv[1], argc == 3 ? argv[2] : nullptr);
        const modsynth::Task task = modsynth::load_task(argv[1]);
        modsynth::SolveOptions options;
        options.time_limit = 30.0;
        const modsynth::Solution solution = modsynth::solve(task, options);
        if (argc == 3 && !write(argv[2], solution)) return 3;

        if (solution.status == modsynth::Status::Solved) {
            // The document round trip loses nothing the certificate rests on.
            const modsynth::Solution read =
                modsynth::read_solution(modsynth::write_solution_json(solution));
            const modsynth::Certificate again = modsynth::certify(task, read);
            std::printf(
                "%s: solved with %d joints, links %.4f m in all; re-certified: %s "
                "(clearance margin %.4f m)\n",
                task.name.c_str(), read.robot.dof(), read.robot.total_length(),
                again.ok ? "yes" : "no", again.min_clearance);
            if (solution.modules) std::printf("  %s\n", solution.modules->message.c_str());
            return again.ok ? 0 : 3;
        }
        const modsynth::Explanation why = modsynth::explain(task, 30.0, 1.0);
        std::printf("%s: %s\n", task.name.c_str(), why.message.c_str());
        for (const auto& part : why.core)
            std::printf("  conflicting: %s\n", to_string(part).c_str());
        for (const auto& s : why.suggestions) std::printf("  change: %s\n", s.change.c_str());
        return why.status == modsynth::Status::Infeasible && !why.core.empty() ? 1 : 3;
    } catch (const modsynth::InputError& e) {
        std::fprintf(stderr, "error: %s\n", e.what());
        return 2;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "internal error: %s\n", e.what());
        return 3;
    }
}
