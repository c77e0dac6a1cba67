#pragma once
// The parts an arm is built from, as data (catalog/*.json at the top of the
// source tree, installed with the program): actuator modules with their
// mass and ratings, tubes by mass per metre, adapters by mass. formats.md
// ("Module catalog") describes the files.
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <modsynth/hardware/mounting.h>

namespace modsynth::hardware {

struct Dimensions {
    double length = 0.0;  ///< m, along the link
    double width = 0.0;   ///< m, across it
    double height = 0.0;  ///< m, along the joint axis
};

struct Actuator {
    std::string name;                ///< "X8-9"
    std::string family;              ///< the file's family, e.g. "hebi-x", "dynamixel-x"
    double mass = 0.0;               ///< kg
    double continuous_torque = 0.0;  ///< N m, what it gives indefinitely (compared with RMS)
    double peak_torque = 0.0;        ///< N m, what it gives for moments
    double max_speed = 0.0;          ///< rad/s at the output
    Dimensions dimensions;
    /// Optional figures (formats.md "Module catalog"): the maker's stall
    /// torque (N m) and no-load speed (rad/s) the ratings above are derived
    /// from, the supply voltage they hold at (V), the list price (USD).
    std::optional<double> stall_torque;
    std::optional<double> no_load_speed;
    std::optional<double> voltage;
    std::optional<double> cost;
    std::optional<Mounting> mounting;
    /// From a file marked "default": a task that names no modules chooses
    /// among these (among every actuator when no file is marked).
    bool default_choice = false;
};

struct Tube {
    std::string name;
    double mass_per_metre = 0.0;  ///< kg/m
    double diameter = 0.0;        ///< m
};

struct Adapter {
    std::string name;
    double mass = 0.0;  ///< kg
};

struct Catalog {
    std::vector<Actuator> actuators;
    std::vector<Tube> tubes;
    std::vector<Adapter> adapters;

    /// nullptr when no actuator has that name (names compare exactly).
    const Actuator* actuator(const std::string& name) const;
    /// The actuators of a family, in catalog order (empty when there is no
    /// such family).
    std::vector<const Actuator*> family(const std::string& name) const;
    /// The actuator families, in name order.
    std::vector<std::string> families() const;
    /// The tube whose diameter is closest to `diameter`; throws
    /// std::runtime_error when the catalog has none.
    const Tube& tube_closest_to(double diameter) const;
    /// The first adapter; throws std::runtime_error when there is none.
    const Adapter& adapter() const;
    /// nullptr when no adapter has that name.
    const Adapter* adapter(const std::string& name) const;
};

/// A catalog file that cannot be used: the message names the file and,
/// when one is to blame, the entry ("hebi-x-series.json: entries[2] (X5-9):
/// peak_torque: ...").
class CatalogError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// Adds the entries of one catalog document (JSON text) to `catalog`; `file`
/// names it in errors. Throws CatalogError.
void parse_catalog_file(const std::string& text, const std::string& file, Catalog& catalog);

/// Reads every *.json file of a folder, in name order. Throws CatalogError
/// when the folder cannot be read, a file is invalid, a name appears twice
/// (a family's name counts: it must not be a part's), or the folder holds
/// no actuator.
Catalog load_catalog(const std::string& folder);

/// Where the catalog shipped with the program is: the folder given to
/// set_default_catalog_folder when there is one (a library whose data
/// lies beside it, such as the Python module's), else
/// share/modsynth/catalog beside the executable's bin/ when that exists
/// (an installed program), else the source tree's catalog/ (a program run
/// from its build folder).
std::string default_catalog_folder();

/// Makes `folder` the default catalog's for the whole process; an empty
/// string goes back to the executable's. Safe from any thread.
void set_default_catalog_folder(const std::string& folder);

/// load_catalog(default_catalog_folder()).
Catalog load_default_catalog();

}  // namespace modsynth::hardware
