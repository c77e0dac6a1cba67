#pragma once
// Which actuator module drives each joint, and how much room it has: what
// selection (hardware/select_modules.h) answers for a solved motion, as
// plain values for the console, the build sheet and the URDF.
#include <optional>
#include <string>
#include <vector>

namespace modsynth::hardware {

/// What one joint must deliver over the motion.
struct JointLoad {
    double peak_torque = 0.0;  ///< N m, max |tau|
    double peak_time = 0.0;    ///< s, when it occurs
    double rms_torque = 0.0;   ///< N m, over time
    double max_speed = 0.0;    ///< rad/s, max |qd|
    double max_speed_time = 0.0;
};

/// The module chosen for one joint and its margins (limit minus load:
/// negative when the module cannot carry it).
struct JointChoice {
    std::string module;
    std::string family;          ///< the module's catalog family ("dynamixel-x")
    std::optional<double> cost;  ///< USD list price; none when the catalog gives none
    double mass = 0.0;           ///< kg
    JointLoad load;
    double peak_torque_limit = 0.0;        ///< N m, the module's
    double continuous_torque_limit = 0.0;  ///< N m
    double speed_limit = 0.0;              ///< rad/s
    double peak_margin = 0.0;              ///< N m: peak_torque_limit - load.peak_torque
    double continuous_margin = 0.0;        ///< N m: continuous limit - load.rms_torque
    double speed_margin = 0.0;             ///< rad/s
    /// The limit with the least relative room ("peak torque", "continuous
    /// torque" or "speed"), and that room as a share of the limit.
    std::string worst_limit;
    double worst_share = 0.0;
    double worst_time = 0.0;  ///< s: when the worst limit is closest (the peak's time for RMS)
    bool carries = false;
};

struct ModuleSelection {
    /// False when the motion carries no joint rates and accelerations (qd,
    /// qdd): nothing was chosen, and `message` says so.
    bool checked = false;
    std::vector<JointChoice> joints;  ///< one per joint, joint 1 first
    /// 1-based number of the most proximal joint no allowed module carries
    /// (it then gets the allowed module with the most relative room); 0 when
    /// every joint is carried.
    int overloaded_joint = 0;
    double total_mass = 0.0;  ///< kg of the chosen modules
    /// USD of the chosen modules; none when a module's cost is unknown.
    std::optional<double> total_cost;
    /// The parts bill in one line: "cost: 2 x XM430-W350 = $579.80; total
    /// $579.80" ("N x MODEL: cost unknown" for a module without a cost).
    std::string cost;
    std::string message;  ///< one line: the choice, or what overloads

    bool carried() const { return checked && overloaded_joint == 0; }
};

}  // namespace modsynth::hardware
