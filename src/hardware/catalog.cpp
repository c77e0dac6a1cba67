#include <modsynth/hardware/catalog.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <mutex>
#include <optional>
#include <set>
#include <system_error>

#include <nlohmann/json.hpp>

#include <modsynth/task/input_error.h>
#include <modsynth/task/input_file.h>
#include <modsynth/text/printable.h>

namespace modsynth::hardware {
namespace {

using nlohmann::json;

constexpr const char* kFormat = "modsynth-catalog/1";
/// A catalog file lists a family of modules or parts: tens of kilobytes.
constexpr std::size_t kMaxCatalogFileBytes = 1u << 20;
/// Files in the catalog folder: a few families and the parts.
constexpr std::size_t kMaxCatalogFiles = 100;

/// "file: entries[i] (name): key: message", each part only when known.
[[noreturn]] void fail(const std::string& where, const std::string& message) {
    throw CatalogError(where + ": " + message);
}

std::string entry_place(const std::string& file, std::size_t i, const json& entry) {
    std::string s = file + ": entries[" + std::to_string(i) + "]";
    const auto name = entry.is_object() ? entry.find("name") : entry.end();
    if (entry.is_object() && name != entry.end() && name->is_string())
        s += " (" + text::printable(name->get<std::string>()) + ")";
    return s;
}

/// A positive, finite number under `key`; `cap` catches unit slips (grams
/// for kilograms, rpm for rad/s).
double positive(const json& obj, const std::string& place, const char* key, double cap) {
    const auto it = obj.find(key);
    if (it == obj.end()) fail(place, std::string(key) + ": missing");
    if (!it->is_number() || !std::isfinite(it->get<double>()))
        fail(place, std::string(key) + ": expected a finite number, got " + it->dump());
    const double v = it->get<double>();
    if (v <= 0.0) fail(place, std::string(key) + ": must be greater than 0, got " + it->dump());
    if (v > cap) {
        fail(place, std::string(key) + ": " + it->dump() + " is more than " + json(cap).dump() +
                        " (check the unit)");
    }
    return v;
}

std::string name_of(const json& obj, const std::string& place) {
    const auto it = obj.find("name");
    if (it == obj.end()) fail(place, "name: missing");
    if (!it->is_string() || it->get<std::string>().empty())
        fail(place, "name: expected a non-empty text, got " + it->dump());
    return it->get<std::string>();
}

/// Every figure must say where it comes from: `sources` maps each key to a
/// URL or a note on how it was derived.
void require_sources(const json& obj, const std::string& place,
                     std::initializer_list<const char*> keys) {
    const auto it = obj.find("sources");
    if (it == obj.end() || !it->is_object()) fail(place, "sources: missing (an object of texts)");
    for (const char* key : keys) {
        const auto s = it->find(key);
        if (s == it->end() || !s->is_string() || s->get<std::string>().empty())
            fail(place, std::string("sources.") + key + ": missing; say where the figure is from");
    }
}

/// An optional positive figure: absent gives none; present, it must be as
/// `positive` requires and say where it comes from.
std::optional<double> optional_figure(const json& obj, const std::string& place, const char* key,
                                      double cap) {
    if (obj.find(key) == obj.end()) return std::nullopt;
    const double v = positive(obj, place, key, cap);
    require_sources(obj, place, {key});
    return v;
}

Actuator parse_actuator(const json& e, const std::string& place, const std::string& family,
                        bool default_choice) {
    Actuator a;
    a.name = name_of(e, place);
    a.family = family;
    a.default_choice = default_choice;
    a.mass = positive(e, place, "mass", 100.0);
    a.continuous_torque = positive(e, place, "continuous_torque", 1e4);
    a.peak_torque = positive(e, place, "peak_torque", 1e4);
    a.max_speed = positive(e, place, "max_speed", 1e3);
    if (a.continuous_torque > a.peak_torque) {
        fail(place, "continuous_torque " + json(a.continuous_torque).dump() +
                        " is more than peak_torque " + json(a.peak_torque).dump());
    }
    const auto d = e.find("dimensions");
    if (d == e.end() || !d->is_object())
        fail(place, "dimensions: missing (an object with length, width and height in m)");
    a.dimensions.length = positive(*d, place + ": dimensions", "length", 10.0);
    a.dimensions.width = positive(*d, place + ": dimensions", "width", 10.0);
    a.dimensions.height = positive(*d, place + ": dimensions", "height", 10.0);
    require_sources(e, place,
                    {"mass", "continuous_torque", "peak_torque", "max_speed", "dimensions"});
    a.stall_torque = optional_figure(e, place, "stall_torque", 1e4);
    a.no_load_speed = optional_figure(e, place, "no_load_speed", 1e3);
    a.voltage = optional_figure(e, place, "voltage", 1e3);
    a.cost = optional_figure(e, place, "cost", 1e7);
    // The ratings are what the module gives in use, so no more than the
    // maker's limits they are derived from.
    if (a.stall_torque && a.peak_torque > *a.stall_torque) {
        fail(place, "peak_torque " + json(a.peak_torque).dump() + " is more than stall_torque " +
                        json(*a.stall_torque).dump());
    }
    if (a.no_load_speed && a.max_speed > *a.no_load_speed) {
        fail(place, "max_speed " + json(a.max_speed).dump() + " is more than no_load_speed " +
                        json(*a.no_load_speed).dump());
    }
    if (const auto m = e.find("mounting"); m != e.end()) {
        a.mounting = parse_mounting(*m, place, a.dimensions.length, a.dimensions.width);
        require_sources(e, place, {"mounting"});
    }
    return a;
}

Tube parse_tube(const json& e, const std::string& place) {
    Tube t;
    t.name = name_of(e, place);
    t.mass_per_metre = positive(e, place, "mass_per_metre", 100.0);
    t.diameter = positive(e, place, "diameter", 1.0);
    require_sources(e, place, {"mass_per_metre", "diameter"});
    return t;
}

Adapter parse_adapter(const json& e, const std::string& place) {
    Adapter a;
    a.name = name_of(e, place);
    a.mass = positive(e, place, "mass", 100.0);
    require_sources(e, place, {"mass"});
    return a;
}

/// A catalog file is read like any other input (task/input_file.h): a FIFO
/// or device among them is refused rather than waited on or read for ever,
/// and a file past kMaxCatalogFileBytes before it is read.
std::string read_file(const std::filesystem::path& path) {
    try {
        return task::read_input_file(path.string(), "catalog", kMaxCatalogFileBytes);
    } catch (const task::InputError& e) {
        throw CatalogError(e.what());
    }
}

}  // namespace

const Actuator* Catalog::actuator(const std::string& name) const {
    for (const auto& a : actuators)
        if (a.name == name) return &a;
    return nullptr;
}

std::vector<const Actuator*> Catalog::family(const std::string& name) const {
    std::vector<const Actuator*> out;
    for (const auto& a : actuators)
        if (a.family == name) out.push_back(&a);
    return out;
}

std::vector<std::string> Catalog::families() const {
    std::set<std::string> names;
    for (const auto& a : actuators) names.insert(a.family);
    return {names.begin(), names.end()};
}

const Tube& Catalog::tube_closest_to(double diameter) const {
    if (tubes.empty()) throw std::runtime_error("the module catalog has no tube");
    return *std::min_element(tubes.begin(), tubes.end(), [&](const Tube& a, const Tube& b) {
        return std::fabs(a.diameter - diameter) < std::fabs(b.diameter - diameter);
    });
}

const Adapter& Catalog::adapter() const {
    if (adapters.empty()) throw std::runtime_error("the module catalog has no adapter");
    return adapters.front();
}

const Adapter* Catalog::adapter(const std::string& name) const {
    for (const auto& a : adapters)
        if (a.name == name) return &a;
    return nullptr;
}

void parse_catalog_file(const std::string& text, const std::string& file, Catalog& catalog) {
    json doc;
    try {
        doc = json::parse(text);
    } catch (const json::parse_error& e) {
        fail(file, std::string("not valid JSON: ") + e.what());
    }
    if (!doc.is_object())
        fail(file, "expected a JSON object {\"format\": \"" + std::string(kFormat) + "\", ...}");
    const auto format = doc.find("format");
    if (format == doc.end() || *format != kFormat)
        fail(file, std::string("format: expected \"") + kFormat + "\"");
    const auto kind_it = doc.find("kind");
    if (kind_it == doc.end() || !kind_it->is_string())
        fail(file, "kind: expected \"actuator\", \"tube\" or \"adapter\"");
    const std::string kind = kind_it->get<std::string>();
    if (kind != "actuator" && kind != "tube" && kind != "adapter")
        fail(file, "kind: expected \"actuator\", \"tube\" or \"adapter\", got \"" +
                       text::printable(kind) + "\"");
    std::string family;
    bool default_choice = false;
    if (kind == "actuator") {
        // Actuator families are names robot.modules may use.
        const auto f = doc.find("family");
        if (f == doc.end() || !f->is_string() || f->get<std::string>().empty())
            fail(file, "family: expected a non-empty text (the name robot.modules uses for it)");
        family = f->get<std::string>();
        if (const auto d = doc.find("default"); d != doc.end()) {
            if (!d->is_boolean()) fail(file, "default: expected true or false, got " + d->dump());
            default_choice = d->get<bool>();
        }
    }
    const auto entries = doc.find("entries");
    if (entries == doc.end() || !entries->is_array() || entries->empty())
        fail(file, "entries: expected a non-empty list");
    for (std::size_t i = 0; i < entries->size(); ++i) {
        const json& e = (*entries)[i];
        const std::string place = entry_place(file, i, e);
        if (!e.is_object()) fail(place, "expected an object");
        if (kind == "actuator") {
            catalog.actuators.push_back(parse_actuator(e, place, family, default_choice));
        } else if (kind == "tube") {
            catalog.tubes.push_back(parse_tube(e, place));
        } else {
            catalog.adapters.push_back(parse_adapter(e, place));
        }
    }
}

Catalog load_catalog(const std::string& folder) {
    namespace fs = std::filesystem;
    std::error_code ec;
    std::vector<fs::path> files;
    for (fs::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
        if (it->path().extension() != ".json") continue;
        files.push_back(it->path());
        if (files.size() > kMaxCatalogFiles)
            throw CatalogError(folder + ": more than " + std::to_string(kMaxCatalogFiles) +
                               " catalog files");
    }
    if (ec) throw CatalogError(folder + ": the module catalog cannot be read: " + ec.message());
    std::sort(files.begin(), files.end());
    Catalog catalog;
    for (const auto& f : files) parse_catalog_file(read_file(f), f.filename().string(), catalog);
    if (catalog.actuators.empty())
        throw CatalogError(folder +
                           ": the module catalog has no actuator (no kind \"actuator\" file)");
    std::set<std::string> names;
    const auto unique = [&](const std::string& name) {
        if (!names.insert(name).second)
            throw CatalogError(folder + ": the name \"" + text::printable(name) +
                               "\" appears twice in the catalog");
    };
    for (const auto& a : catalog.actuators) unique(a.name);
    for (const auto& t : catalog.tubes) unique(t.name);
    for (const auto& a : catalog.adapters) unique(a.name);
    for (const auto& f : catalog.families()) {
        if (names.count(f))
            throw CatalogError(
                folder + ": the family \"" + text::printable(f) +
                "\" has the name of a part; robot.modules could not tell them apart");
    }
    return catalog;
}

namespace {

// Set once by a library at load time and read by every solve: a mutex
// keeps a read from seeing a string half written.
std::mutex given_folder_mutex;
std::string given_folder;

}  // namespace

void set_default_catalog_folder(const std::string& folder) {
    const std::lock_guard<std::mutex> lock(given_folder_mutex);
    given_folder = folder;
}

std::string default_catalog_folder() {
    {
        const std::lock_guard<std::mutex> lock(given_folder_mutex);
        if (!given_folder.empty()) return given_folder;
    }
    namespace fs = std::filesystem;
    std::error_code ec;
    const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    if (!ec) {
        const fs::path installed =
            exe.parent_path().parent_path() / MODSYNTH_CATALOG_INSTALL_SUBDIR;
        if (fs::is_directory(installed, ec)) return installed.string();
    }
    return MODSYNTH_CATALOG_SOURCE_DIR;
}

Catalog load_default_catalog() { return load_catalog(default_catalog_folder()); }

}  // namespace modsynth::hardware
