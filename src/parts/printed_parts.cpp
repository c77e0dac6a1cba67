#include <modsynth/parts/printed_parts.h>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <stdexcept>

#include <modsynth/parts/external_tool.h>
#include <modsynth/parts/hole_spacing.h>
#include <modsynth/parts/scad_writer.h>
#include <modsynth/task/input_error.h>
#include <modsynth/text/format.h>

namespace modsynth::parts {

namespace fs = std::filesystem;

namespace {

/// Removes a symbolic link at `path`, so that what is then written there
/// lands in the folder, not where the link points.
void unlink_if_link(const std::string& path) {
    struct stat st {};
    if (::lstat(path.c_str(), &st) == 0 && S_ISLNK(st.st_mode)) ::unlink(path.c_str());
}

/// Opens `path` for writing without following a link: one there is
/// replaced. -1 (errno set) on failure.
int open_in_folder(const std::string& path, int flags) {
    unlink_if_link(path);
    return ::open(path.c_str(), O_WRONLY | O_CREAT | O_NOFOLLOW | O_CLOEXEC | flags, 0666);
}

}  // namespace

void prepare_parts_folder(const std::string& folder) {
    const std::string part = "--parts " + folder;
    if (folder.empty()) throw task::InputError("--parts", "an empty folder name");
    std::error_code ec;
    if (fs::exists(folder, ec) && !fs::is_directory(folder, ec))
        throw task::InputError(part, "is a file, not a folder");
    fs::create_directories(folder, ec);
    if (ec || !fs::is_directory(folder))
        throw task::InputError(part, "cannot be created: " + ec.message());
    // A new file of its own, never one that is there (a link, say).
    const std::string probe = (fs::path(folder) / ".modsynth-write-probe").string();
    const int fd =
        ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0600);
    if (fd < 0 && errno != EEXIST)
        throw task::InputError(part, std::string("cannot be written to: ") + std::strerror(errno));
    if (fd >= 0) {
        ::close(fd);
        ::unlink(probe.c_str());
    }
}

std::vector<std::string> part_paths(const std::string& folder, int max_links) {
    std::vector<std::string> names;
    for (int k = 1; k <= max_links; ++k) names.push_back(text::format("link_%d", k));
    names.push_back("base_plate");
    names.push_back("tool_holder");
    std::vector<std::string> out;
    for (const std::string& n : names)
        for (const char* ext : {".scad", ".stl"})
            out.push_back((fs::path(folder) / (n + ext)).string());
    return out;
}

std::vector<LinkDesign> planar_links(const task::RobotSpec& spec, const kinematics::Robot& robot,
                                     const std::vector<const hardware::Actuator*>& modules,
                                     const PrintSettings& settings) {
    const int n = robot.dof();
    if (static_cast<int>(modules.size()) != n)
        throw std::invalid_argument("planar_links: one module per joint");
    const hardware::Dimensions fallback{spec.module_length, spec.module_width, spec.module_height};
    std::vector<LinkDesign> out;
    for (int k = 0; k < n; ++k) {
        std::optional<ModuleMount> body;
        if (k + 1 < n) body = module_mount(*modules[k + 1], fallback);
        out.push_back(link_design(k + 1, robot.link_lengths[k], module_mount(*modules[k], fallback),
                                  body, spec.ee_rod_diameter, modules[k]->peak_torque, settings));
    }
    return out;
}

std::vector<LinkDesign> dh_links(const task::SpatialRobotSpec& spec,
                                 const kinematics::DhChain& chain,
                                 const std::vector<const hardware::Actuator*>& modules,
                                 const PrintSettings& settings, std::vector<std::string>& notes) {
    const int n = chain.dof();
    if (static_cast<int>(modules.size()) != n)
        throw std::invalid_argument("dh_links: one module per joint");
    const hardware::Dimensions fallback{spec.module_length, spec.module_width, spec.module_height};
    constexpr double kShortest = 0.001;
    std::vector<LinkDesign> out;
    for (int k = 0; k < n; ++k) {
        const kinematics::DhRow& r = chain.rows[static_cast<std::size_t>(k)];
        if (std::abs(r.a) <= kShortest) {
            notes.push_back(text::format(
                "link %d has no common normal (a = 0): no printed link; "
                "the tube or bracket the sheet lists joins module %d to "
                "%s",
                k + 1, k + 1, k + 1 < n ? text::format("module %d", k + 2).c_str() : "the tool"));
            continue;
        }
        if (std::abs(r.d) > kShortest || std::abs(r.alpha) > 1e-6)
            notes.push_back(text::format(
                "link %d: the printed link spans a = %.1f mm; d = %.1f mm and the twist %.0f deg "
                "are the tube and bracket the sheet lists",
                k + 1, r.a * 1000.0, r.d * 1000.0, r.alpha * 180.0 / geometry::kPi));
        std::optional<ModuleMount> body;
        if (k + 1 < n) body = module_mount(*modules[static_cast<std::size_t>(k + 1)], fallback);
        out.push_back(link_design(k + 1, std::abs(r.a),
                                  module_mount(*modules[static_cast<std::size_t>(k)], fallback),
                                  body, spec.ee_rod_diameter,
                                  modules[static_cast<std::size_t>(k)]->peak_torque, settings));
    }
    return out;
}

hardware::PrintedLink link_body(const Mesh& mesh_mm, const PrintSettings& settings) {
    const MassProperties p = mass_properties(mesh_mm);
    const double density = settings.printed_density();
    hardware::PrintedLink body;
    body.mass = p.volume * 1e-9 * density;
    body.com = p.centroid.x() / 1000.0;
    body.inertia = p.inertia(2, 2) * 1e-15 * density;
    return body;
}

hardware::RigidBody link_solid(const Mesh& mesh_mm, const PrintSettings& settings) {
    const MassProperties p = mass_properties(mesh_mm);
    const double density = settings.printed_density();
    hardware::RigidBody body;
    body.mass = p.volume * 1e-9 * density;
    body.com = p.centroid / 1000.0;
    body.inertia = p.inertia * 1e-15 * density;
    return body;
}

namespace {

void write_source(const std::string& path, const std::string& text) {
    const int fd = open_in_folder(path, O_TRUNC);
    if (fd < 0) throw std::runtime_error(path + ": cannot be written: " + std::strerror(errno));
    const char* p = text.data();
    std::size_t left = text.size();
    int err = 0;
    while (left > 0) {
        const ssize_t n = ::write(fd, p, left);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) {
            err = n < 0 ? errno : ENOSPC;
            break;
        }
        p += n;
        left -= static_cast<std::size_t>(n);
    }
    if (::close(fd) != 0 && err == 0) err = errno;
    if (err != 0) throw std::runtime_error(path + ": cannot be written: " + std::strerror(err));
}

/// Renders one source and runs the checks every mesh gets; the spacing
/// check too for a link.
void render_and_check(PartFile& f, const LinkDesign* link, PrintedParts& parts, double time_limit,
                      bool admesh) {
    const std::string stl = (fs::path(parts.folder) / (f.name + ".stl")).string();
    // openscad writes through a link at the mesh's name; none is left there.
    unlink_if_link(stl);
    const ToolRun run = run_tool({"openscad", "-o", stl, f.scad}, time_limit);
    if (!run.ok() || !fs::exists(stl)) {
        f.checks = run.timed_out ? text::format("openscad gave up at the %.0f s limit", time_limit)
                                 : "openscad failed: " + run.output.substr(0, 300);
        parts.notes.push_back(f.name + ": " + f.checks);
        return;
    }
    f.stl = stl;
    const Mesh mesh = read_stl(stl);
    std::vector<std::string> found;
    bool ok = true;
    const int bad = bad_edges(mesh);
    found.push_back(bad == 0 ? "closed" : text::format("%d open or misoriented edges", bad));
    ok = ok && bad == 0;
    if (admesh) {
        const AdmeshReport r = parse_admesh(run_tool({"admesh", stl}, time_limit).output);
        found.push_back("admesh: " + r.summary());
        ok = ok && r.closed_manifold();
    }
    if (link) {
        const SpacingCheck s = check_spacing(mesh, *link);
        found.push_back(s.message);
        ok = ok && s.ok;
        parts.bodies.push_back(link_body(mesh, parts.settings));
        parts.solids.push_back(link_solid(mesh, parts.settings));
        found.push_back(text::format("%.0f g", parts.bodies.back().mass * 1000.0));
    }
    f.checks_ok = ok;
    for (std::size_t i = 0; i < found.size(); ++i) f.checks += (i ? "; " : "") + found[i];
    if (!ok) parts.notes.push_back(f.name + ": a check failed: " + f.checks);
}

}  // namespace

PrintedParts write_printed_parts(const std::vector<LinkDesign>& links, const ModuleMount& first,
                                 double rod_diameter, const std::string& folder,
                                 const std::string& title, const PrintSettings& settings,
                                 double time_limit) {
    PrintedParts parts;
    parts.folder = folder;
    parts.settings = settings;
    parts.links = links;
    const double plate = links.empty() ? 0.006 : links.front().beam.plate;
    parts.screws = arm_screws(links, first, plate);
    const auto source = [&](const std::string& name, const std::string& text) {
        PartFile f;
        f.name = name;
        f.scad = (fs::path(folder) / (name + ".scad")).string();
        write_source(f.scad, text);
        parts.files.push_back(f);
    };
    for (const auto& l : links)
        source(
            text::format("link_%d", l.index),
            link_scad(l, text::format("%s: link %d of %zu", title.c_str(), l.index, links.size())));
    source("base_plate", base_plate_scad(first, plate, title + ": base plate"));
    source("tool_holder", tool_holder_scad(rod_diameter, plate, title + ": tool holder"));
    if (!on_path("openscad")) {
        parts.notes.push_back(
            "openscad is not installed: the OpenSCAD sources are written, not rendered to STL "
            "(Debian: apt install openscad), so the links' masses are the tubes' estimate");
        return parts;
    }
    const bool admesh = on_path("admesh");
    for (std::size_t i = 0; i < parts.files.size(); ++i)
        render_and_check(parts.files[i], i < links.size() ? &links[i] : nullptr, parts, time_limit,
                         admesh);
    parts.rendered = true;
    parts.checks_ok = true;
    for (const auto& f : parts.files) {
        parts.rendered = parts.rendered && !f.stl.empty();
        parts.checks_ok = parts.checks_ok && f.checks_ok;
    }
    if (parts.bodies.size() != links.size()) {
        parts.bodies.clear();
        parts.solids.clear();
    }
    return parts;
}

}  // namespace modsynth::parts
