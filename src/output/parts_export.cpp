#include <modsynth/output/parts_export.h>

#include <filesystem>
#include <functional>

#include <modsynth/hardware/select_dh_modules.h>
#include <modsynth/hardware/select_modules.h>
#include <modsynth/text/format.h>

namespace modsynth::output {

namespace {

using text::format;

/// The catalog's actuators the selection names, joint 1 first; empty when
/// one is missing.
std::vector<const hardware::Actuator*> chosen(const hardware::ModuleSelection& selection,
                                              const hardware::Catalog& catalog) {
    std::vector<const hardware::Actuator*> out;
    for (const auto& j : selection.joints) {
        const hardware::Actuator* a = catalog.actuator(j.module);
        if (!a) return {};
        out.push_back(a);
    }
    return out;
}

std::vector<std::string> names(const std::vector<const hardware::Actuator*>& modules) {
    std::vector<std::string> out;
    for (const auto* m : modules) out.push_back(m->name);
    return out;
}

/// The modules to print for; empty, and the line in `notes`, when there is
/// nothing to print.
std::vector<const hardware::Actuator*> modules_to_print(
    const std::optional<hardware::Catalog>& catalog, const synth::Solution& solution,
    const std::string& folder, std::vector<std::string>& notes) {
    const std::string what = "--parts " + folder + ": not written; ";
    if (solution.status != synth::Status::Solved) {
        notes.push_back(what + "the solution is " + synth::to_string(solution.status) +
                        ", so there is no robot");
        return {};
    }
    if (!catalog) {
        notes.push_back(what + "there is no module catalog to size the links for");
        return {};
    }
    std::vector<const hardware::Actuator*> modules;
    if (solution.modules && solution.modules->checked)
        modules = chosen(*solution.modules, *catalog);
    if (modules.empty())
        notes.push_back(what + "no modules were chosen for the motion" +
                        (solution.modules ? " (" + solution.modules->message + ")" : ""));
    return modules;
}

/// Prints the parts for `modules`, chooses the modules again with the
/// printed links in the dynamics and prints again for the new choice, until
/// it holds or kPartsRounds have run: a link sized for a stronger module is
/// heavier, which may call for a stronger module inwards. Without rendered
/// links (no masses) the tubes' choice stands.
std::optional<parts::PrintedParts> print_and_choose(
    std::vector<const hardware::Actuator*> modules, const hardware::Catalog& catalog,
    synth::Solution& solution, const std::string& folder, std::vector<std::string>& notes,
    const std::function<parts::PrintedParts(const std::vector<const hardware::Actuator*>&)>& print,
    const std::function<hardware::ModuleSelection(const parts::PrintedParts&)>& choose) {
    std::optional<parts::PrintedParts> printed;
    for (int round = 0; round < kPartsRounds; ++round) {
        printed = print(modules);
        if (printed->bodies.empty()) break;
        solution.modules = choose(*printed);
        const std::vector<const hardware::Actuator*> again = chosen(*solution.modules, catalog);
        if (again.empty() || names(again) == names(modules)) break;
        if (round + 1 == kPartsRounds) {
            notes.push_back(
                format("--parts %s: the modules the printed links call for changed in "
                       "each of %d rounds; the parts are for %s",
                       folder.c_str(), kPartsRounds, names(modules).front().c_str()));
            break;
        }
        modules = again;
    }
    for (const auto& n : printed->notes) notes.push_back("--parts: " + n);
    return printed;
}

}  // namespace

std::optional<parts::PrintedParts> export_parts(const task::SpatialTask& task,
                                                const std::optional<hardware::Catalog>& catalog,
                                                synth::Solution& solution,
                                                const std::string& folder,
                                                std::vector<std::string>& notes) {
    const std::vector<const hardware::Actuator*> modules =
        modules_to_print(catalog, solution, folder, notes);
    if (modules.empty()) return std::nullopt;
    const parts::PrintSettings settings;
    const auto print = [&](const std::vector<const hardware::Actuator*>& m) {
        std::vector<std::string> layout;
        const std::vector<parts::LinkDesign> links =
            parts::dh_links(task.robot, *solution.dh_robot, m, settings, layout);
        parts::PrintedParts printed = parts::write_printed_parts(
            links,
            parts::module_mount(*m.front(), {task.robot.module_length, task.robot.module_width,
                                             task.robot.module_height}),
            task.robot.ee_rod_diameter, folder, "modsynth: " + task.name, settings);
        printed.notes.insert(printed.notes.begin(), layout.begin(), layout.end());
        return printed;
    };
    const auto choose = [&](const parts::PrintedParts& printed) {
        std::vector<hardware::PrintedDhLink> bodies;
        for (std::size_t i = 0; i < printed.solids.size(); ++i)
            bodies.push_back({printed.links[i].index - 1, printed.solids[i]});
        return hardware::select_modules(task, *solution.dh_robot, solution.samples, *catalog,
                                        bodies);
    };
    return print_and_choose(modules, *catalog, solution, folder, notes, print, choose);
}

std::optional<parts::PrintedParts> export_parts(const task::Task& task,
                                                const std::optional<hardware::Catalog>& catalog,
                                                synth::Solution& solution,
                                                const std::string& folder,
                                                std::vector<std::string>& notes) {
    const std::vector<const hardware::Actuator*> modules =
        modules_to_print(catalog, solution, folder, notes);
    if (modules.empty()) return std::nullopt;
    const parts::PrintSettings settings;
    const hardware::Dimensions housing{task.robot.module_length, task.robot.module_width,
                                       task.robot.module_height};
    const auto print = [&](const std::vector<const hardware::Actuator*>& m) {
        return parts::write_printed_parts(
            parts::planar_links(task.robot, solution.robot, m, settings),
            parts::module_mount(*m.front(), housing), task.robot.ee_rod_diameter, folder,
            "modsynth: " + task.name, settings);
    };
    const auto choose = [&](const parts::PrintedParts& printed) {
        return hardware::select_modules(task, solution.robot, solution.samples, *catalog,
                                        printed.bodies);
    };
    return print_and_choose(modules, *catalog, solution, folder, notes, print, choose);
}

std::string printed_parts_section(const parts::PrintedParts& p) {
    std::string s = "## Printed parts\n\n";
    s += format("In `%s`: an OpenSCAD source of each part, its parameters at the top in mm",
                p.folder.c_str());
    s += p.rendered ? ", and its STL.\n\n" : "; not rendered to STL (see the notes).\n\n";
    s += "| Part | Source | Mesh | Checks |\n|---|---|---|---|\n";
    for (const auto& f : p.files) {
        const auto base = [](const std::string& path) {
            return path.empty() ? std::string("-")
                                : "`" + std::filesystem::path(path).filename().string() + "`";
        };
        s += format("| %s | %s | %s | %s |\n", f.name.c_str(), base(f.scad).c_str(),
                    base(f.stl).c_str(), f.checks.empty() ? "not checked" : f.checks.c_str());
    }
    const parts::PrintSettings& ps = p.settings;
    s += format(
        "\nPrint settings: %s, %.0f %% gyroid infill, %d perimeters, %.2f mm layers; each part "
        "flat on its end plates (the tool holder on its flange), no supports. The beams are sized "
        "for the driving module's peak torque at %.0f MPa allowable stress (%.0f MPa over a "
        "safety factor of %.0f).\n",
        ps.material.name.c_str(), ps.infill * 100.0, ps.perimeters, ps.layer_height * 1000.0,
        ps.allowable_stress() / 1e6, ps.material.strength / 1e6, ps.safety_factor);
    if (!p.bodies.empty()) {
        s += format(
            "\nPrinted link masses (mesh volume x %.0f kg/m^3 x %.2f solid fraction), "
            "which the module choice above carries in place of the tubes':",
            ps.material.density, ps.solid_fraction);
        for (std::size_t k = 0; k < p.bodies.size(); ++k)
            s += format(" link %d %.0f g%s", p.links[k].index, p.bodies[k].mass * 1000.0,
                        k + 1 < p.bodies.size() ? "," : ".\n");
    }
    bool provisional = false;
    for (const auto& l : p.links) provisional = provisional || l.horn.provisional;
    if (provisional)
        s += "\nThe bolt patterns are generic ones for each housing's size (the catalog gives "
             "none): check them against the modules before printing.\n";
    s += "\nScrews:\n\n| Count | Size | Length | Holds |\n|---|---|---|---|\n";
    for (const auto& sc : p.screws)
        s += format("| %d | %s | %s | %s |\n", sc.count, sc.size.c_str(),
                    sc.length > 0.0 ? format("%.0f mm", sc.length * 1000.0).c_str() : "to suit",
                    sc.use.c_str());
    if (!p.notes.empty()) {
        s += "\nNotes:\n\n";
        for (const auto& n : p.notes) s += "- " + n + "\n";
    }
    return s;
}

}  // namespace modsynth::output
