#include <modsynth/hardware/select_modules.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>

#include <modsynth/hardware/dynamics.h>
#include <modsynth/task/input_error.h>
#include <modsynth/text/format.h>
#include <modsynth/text/printable.h>

namespace modsynth::hardware {
namespace {

bool timed(const std::vector<control::Sample>& samples, std::size_t dof) {
    if (samples.empty()) return false;
    for (const auto& s : samples)
        if (s.qd.size() != dof || s.qdd.size() != dof) return false;
    return true;
}

JointChoice assess(const Actuator& a, const JointLoad& load) {
    JointChoice c;
    c.module = a.name;
    c.family = a.family;
    c.cost = a.cost;
    c.mass = a.mass;
    c.load = load;
    c.peak_torque_limit = a.peak_torque;
    c.continuous_torque_limit = a.continuous_torque;
    c.speed_limit = a.max_speed;
    c.peak_margin = a.peak_torque - load.peak_torque;
    c.continuous_margin = a.continuous_torque - load.rms_torque;
    c.speed_margin = a.max_speed - load.max_speed;
    const struct {
        const char* name;
        double share;
        double time;
    } limits[] = {{"peak torque", c.peak_margin / a.peak_torque, load.peak_time},
                  {"continuous torque", c.continuous_margin / a.continuous_torque, load.peak_time},
                  {"speed", c.speed_margin / a.max_speed, load.max_speed_time}};
    const auto* worst =
        std::min_element(std::begin(limits), std::end(limits),
                         [](const auto& x, const auto& y) { return x.share < y.share; });
    c.worst_limit = worst->name;
    c.worst_share = worst->share;
    c.worst_time = worst->time;
    c.carries = c.peak_margin >= 0.0 && c.continuous_margin >= 0.0 && c.speed_margin >= 0.0;
    return c;
}

std::string overload_text(int joint, const JointChoice& c) {
    std::string what;
    if (c.worst_limit == "peak torque") {
        what = text::format(
            "%.2f N m at t = %.3f s against its %.3g N m peak torque (margin %.2f N m)",
            c.load.peak_torque, c.load.peak_time, c.peak_torque_limit, c.peak_margin);
    } else if (c.worst_limit == "continuous torque") {
        what = text::format(
            "an RMS torque of %.2f N m against its %.3g N m continuous torque (margin %.2f N m; "
            "peak %.2f N m at t = %.3f s)",
            c.load.rms_torque, c.continuous_torque_limit, c.continuous_margin, c.load.peak_torque,
            c.load.peak_time);
    } else {
        what = text::format("%.3f rad/s at t = %.3f s against its %.3g rad/s (margin %.3f rad/s)",
                            c.load.max_speed, c.load.max_speed_time, c.speed_limit, c.speed_margin);
    }
    return text::format(
               "joint %d is overloaded: no allowed module carries it; the one with the "
               "most room, %s, sees ",
               joint, c.module.c_str()) +
           what;
}

/// The modules' count, price and total (ModuleSelection::cost).
std::string cost_line(const std::vector<JointChoice>& joints, std::optional<double>& total) {
    std::vector<std::pair<const JointChoice*, int>> groups;  // first of each model, in joint order
    for (const auto& j : joints) {
        const auto g = std::find_if(groups.begin(), groups.end(),
                                    [&](const auto& x) { return x.first->module == j.module; });
        if (g == groups.end()) {
            groups.emplace_back(&j, 1);
        } else {
            ++g->second;
        }
    }
    std::string s = "cost: ";
    double known = 0.0;
    bool any_known = false, any_unknown = false;
    for (std::size_t i = 0; i < groups.size(); ++i) {
        const auto& [j, count] = groups[i];
        s += (i ? ", " : "") + std::to_string(count) + " x " + j->module;
        if (j->cost) {
            s += text::format(" = $%.2f", count * *j->cost);
            known += count * *j->cost;
            any_known = true;
        } else {
            s += ": cost unknown";
            any_unknown = true;
        }
    }
    total.reset();
    if (!any_unknown) {
        total = known;
        return s + text::format("; total $%.2f", known);
    }
    if (!any_known) return s + "; total cost unknown";
    return s + text::format("; total $%.2f plus the modules of unknown cost", known);
}

}  // namespace

std::vector<JointLoad> joint_loads(const ArmModel& model,
                                   const std::vector<control::Sample>& samples) {
    return joint_loads(
        static_cast<int>(model.link_lengths.size()), samples,
        [&](const control::Sample& s) { return inverse_dynamics(model, s.q, s.qd, s.qdd); });
}

std::vector<JointLoad> joint_loads(
    int dof, const std::vector<control::Sample>& samples,
    const std::function<std::vector<double>(const control::Sample&)>& torques) {
    const auto n = static_cast<std::size_t>(dof);
    if (!timed(samples, n))
        throw std::invalid_argument("joint_loads: every sample needs q, qd and qdd per joint");
    std::vector<JointLoad> loads(n);
    std::vector<double> square_integral(n, 0.0), square_sum(n, 0.0), previous;
    for (std::size_t i = 0; i < samples.size(); ++i) {
        const auto& s = samples[i];
        const std::vector<double> tau = torques(s);
        const double dt = i > 0 ? s.t - samples[i - 1].t : 0.0;
        for (std::size_t k = 0; k < n; ++k) {
            JointLoad& l = loads[k];
            if (std::fabs(tau[k]) > l.peak_torque) {
                l.peak_torque = std::fabs(tau[k]);
                l.peak_time = s.t;
            }
            if (std::fabs(s.qd[k]) > l.max_speed) {
                l.max_speed = std::fabs(s.qd[k]);
                l.max_speed_time = s.t;
            }
            square_sum[k] += tau[k] * tau[k];
            if (i > 0)
                square_integral[k] += dt * (tau[k] * tau[k] + previous[k] * previous[k]) / 2.0;
        }
        previous = tau;
    }
    const double duration = samples.back().t - samples.front().t;
    for (std::size_t k = 0; k < n; ++k) {
        loads[k].rms_torque = duration > 0.0 ? std::sqrt(square_integral[k] / duration)
                                             : std::sqrt(square_sum[k] / samples.size());
    }
    return loads;
}

std::vector<const Actuator*> allowed_actuators(const task::RobotSpec& spec,
                                               const Catalog& catalog) {
    return allowed_actuators(spec.modules, catalog);
}

std::vector<const Actuator*> allowed_actuators(const std::vector<std::string>& names,
                                               const Catalog& catalog) {
    std::vector<const Actuator*> out;
    const auto add = [&](const Actuator* a) {
        if (std::find(out.begin(), out.end(), a) == out.end()) out.push_back(a);
    };
    if (names.empty()) {
        for (const auto& a : catalog.actuators)
            if (a.default_choice) add(&a);
        if (out.empty())
            for (const auto& a : catalog.actuators) add(&a);
    } else {
        for (std::size_t i = 0; i < names.size(); ++i) {
            if (const Actuator* a = catalog.actuator(names[i])) {
                add(a);
                continue;
            }
            const std::vector<const Actuator*> family = catalog.family(names[i]);
            if (family.empty()) {
                std::string families, models;
                // Names echoed to a terminal: the user's and the catalog's
                // as printable text, never its control characters.
                for (const auto& f : catalog.families())
                    families += (families.empty() ? "" : ", ") + text::printable(f);
                for (const auto& c : catalog.actuators)
                    models += (models.empty() ? "" : ", ") + text::printable(c.name);
                throw task::InputError("robot.modules[" + std::to_string(i) + "]",
                                       "the module catalog has no \"" + text::printable(names[i]) +
                                           "\"; its families are " + families + ", its models " +
                                           models);
            }
            for (const Actuator* a : family) add(a);
        }
    }
    std::stable_sort(out.begin(), out.end(),
                     [](const Actuator* a, const Actuator* b) { return a->mass < b->mass; });
    return out;
}

ModuleSelection select_modules(const task::Task& task, const kinematics::Robot& robot,
                               const std::vector<control::Sample>& samples, const Catalog& catalog,
                               const std::vector<PrintedLink>& printed) {
    const std::vector<const Actuator*> allowed = allowed_actuators(task.robot, catalog);
    const int n = robot.dof();
    if (!timed(samples, static_cast<std::size_t>(n))) {
        ModuleSelection out;
        out.message =
            "modules not chosen: the motion carries no joint rates and accelerations (qd, qdd)";
        return out;
    }
    return choose_modules(n, allowed, [&](const std::vector<const Actuator*>& modules) {
        return joint_loads(arm_model(task.robot, robot, catalog, modules, printed), samples);
    });
}

ModuleSelection choose_modules(int dof, const std::vector<const Actuator*>& allowed,
                               const LoadsWithModules& loads) {
    ModuleSelection out;
    const int n = dof;
    out.checked = true;
    out.joints.resize(n);
    // Joints not yet chosen hold the lightest module: they are proximal to
    // the joint being chosen, so they do not load it.
    std::vector<const Actuator*> modules(n, allowed.front());
    for (int k = n - 1; k >= 0; --k) {
        const JointLoad load = loads(modules)[k];
        std::optional<JointChoice> best;
        for (const Actuator* a : allowed) {
            const JointChoice c = assess(*a, load);
            if (c.carries) {
                best = c;
                modules[k] = a;
                break;
            }
            if (!best || c.worst_share > best->worst_share) {
                best = c;
                modules[k] = a;
            }
        }
        out.joints[k] = *best;
        if (!best->carries) out.overloaded_joint = k + 1;
    }
    for (const auto& j : out.joints) out.total_mass += j.mass;
    out.cost = cost_line(out.joints, out.total_cost);
    if (out.overloaded_joint > 0) {
        out.message = overload_text(out.overloaded_joint, out.joints[out.overloaded_joint - 1]);
    } else {
        std::string names, families;
        std::vector<std::string> seen;
        double worst = 1.0;
        for (int k = 0; k < n; ++k) {
            const JointChoice& j = out.joints[k];
            names += (k ? ", " : "") + j.module;
            if (!j.family.empty() && std::find(seen.begin(), seen.end(), j.family) == seen.end()) {
                seen.push_back(j.family);
                families += (families.empty() ? "" : ", ") + j.family;
            }
            worst = std::min(worst, j.worst_share);
        }
        out.message = text::format(
            "modules %s (%s%s%.3f kg), every joint carried with at least "
            "%.0f%% of a rating to spare; %s",
            names.c_str(), families.c_str(), families.empty() ? "" : "; ", out.total_mass,
            100.0 * worst, out.cost.c_str());
    }
    return out;
}

}  // namespace modsynth::hardware
