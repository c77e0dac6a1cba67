// The value types the pipeline answers with, as read-only Python objects:
// robots, samples (as NumPy arrays), certificates, modules, explanations.
#include "values.h"

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <modsynth/modsynth.h>

namespace modsynth::python {

namespace {

py::array_t<double> vector_array(const std::vector<double>& v) {
    py::array_t<double> out(static_cast<py::ssize_t>(v.size()));
    auto a = out.mutable_unchecked<1>();
    for (std::size_t i = 0; i < v.size(); ++i) a(static_cast<py::ssize_t>(i)) = v[i];
    return out;
}

py::array_t<double> point_array(const double* p, int n) {
    py::array_t<double> out(n);
    auto a = out.mutable_unchecked<1>();
    for (int i = 0; i < n; ++i) a(i) = p[i];
    return out;
}

/// One row per sample of `field` (q, qd or qdd), as wide as the first
/// sample's; None when the samples do not carry it.
py::object joint_matrix(const std::vector<control::Sample>& samples,
                        const std::vector<double> control::Sample::*field) {
    if (samples.empty() || (samples.front().*field).empty()) return py::none();
    const std::size_t n = (samples.front().*field).size();
    py::array_t<double> out(
        {static_cast<py::ssize_t>(samples.size()), static_cast<py::ssize_t>(n)});
    auto a = out.mutable_unchecked<2>();
    for (std::size_t i = 0; i < samples.size(); ++i) {
        const std::vector<double>& v = samples[i].*field;
        if (v.size() != n) throw std::runtime_error("samples of unequal width");
        for (std::size_t k = 0; k < n; ++k)
            a(static_cast<py::ssize_t>(i), static_cast<py::ssize_t>(k)) = v[k];
    }
    return out;
}

const char* phase_name(control::Phase p) {
    switch (p) {
        case control::Phase::Trace:
            return "trace";
        case control::Phase::Transition:
            return "transition";
        case control::Phase::Travel:
            return "travel";
    }
    return "trace";
}

const char* violation_kind(verify::Violation::Kind k) {
    using Kind = verify::Violation::Kind;
    switch (k) {
        case Kind::Structure:
            return "structure";
        case Kind::Deviation:
            return "deviation";
        case Kind::Clearance:
            return "clearance";
        case Kind::SelfCollision:
            return "self_collision";
        case Kind::JointStep:
            return "joint_step";
        case Kind::Order:
            return "order";
        case Kind::ToolAxis:
            return "tool_axis";
    }
    return "structure";
}

}  // namespace

py::dict sample_arrays(const std::vector<control::Sample>& samples) {
    const auto n = static_cast<py::ssize_t>(samples.size());
    py::array_t<double> t(n), s(n);
    py::array_t<int> primitive(n), stroke(n);
    py::list phase;
    auto ta = t.mutable_unchecked<1>();
    auto sa = s.mutable_unchecked<1>();
    auto pa = primitive.mutable_unchecked<1>();
    auto st = stroke.mutable_unchecked<1>();
    for (py::ssize_t i = 0; i < n; ++i) {
        const control::Sample& x = samples[static_cast<std::size_t>(i)];
        ta(i) = x.t;
        sa(i) = x.s;
        pa(i) = x.primitive;
        st(i) = x.stroke;
        phase.append(phase_name(x.phase));
    }
    py::dict out;
    out["t"] = t;
    out["q"] = samples.empty() ? py::object(py::array_t<double>(std::vector<py::ssize_t>{0, 0}))
                               : joint_matrix(samples, &control::Sample::q);
    out["qd"] = joint_matrix(samples, &control::Sample::qd);
    out["qdd"] = joint_matrix(samples, &control::Sample::qdd);
    out["phase"] = phase;
    out["primitive"] = primitive;
    out["stroke"] = stroke;
    out["s"] = s;
    return out;
}

void bind_values(py::module_& m) {
    py::class_<run::ProgressEvent>(m, "ProgressEvent",
                                   "One step of a run: its stage, a sentence, and the seconds "
                                   "since the run started.")
        .def_property_readonly(
            "stage",
            [](const run::ProgressEvent& e) { return std::string(run::to_string(e.stage)); },
            "The pipeline stage: \"proofs\", \"front stage\", \"refinement\", ...")
        .def_readonly("message", &run::ProgressEvent::message)
        .def_readonly("elapsed", &run::ProgressEvent::elapsed)
        .def("__str__", [](const run::ProgressEvent& e) { return run::console_line(e); })
        .def("__repr__", [](const run::ProgressEvent& e) {
            return "<ProgressEvent " + run::console_line(e) + ">";
        });

    py::class_<kinematics::Robot>(m, "Robot", "A planar arm: base, link lengths and elbow branch.")
        .def_property_readonly(
            "base", [](const kinematics::Robot& r) { return point_array(r.base.data(), 2); },
            "The first joint's axis, [x, y] (m).")
        .def_property_readonly(
            "link_lengths", [](const kinematics::Robot& r) { return vector_array(r.link_lengths); },
            "r_1 .. r_n (m), base first.")
        .def_readonly("link_diameter", &kinematics::Robot::link_diameter)
        .def_readonly("elbow", &kinematics::Robot::elbow)
        .def_property_readonly(
            "proximal_angles",
            [](const kinematics::Robot& r) { return vector_array(r.proximal_angles); },
            "Three joints: the first joint's angle while each primitive is traced.")
        .def_property_readonly("dof", &kinematics::Robot::dof)
        .def_property_readonly("total_length", &kinematics::Robot::total_length)
        .def("__repr__", [](const kinematics::Robot& r) {
            std::string links;
            for (double l : r.link_lengths)
                links += (links.empty() ? "" : ", ") + std::to_string(l);
            return "<Robot " + std::to_string(r.dof()) + " joints, links [" + links + "] m>";
        });

    py::class_<kinematics::DhRow>(m, "DhRow", "One row of a DH table: a, alpha, d.")
        .def_readonly("a", &kinematics::DhRow::a)
        .def_readonly("alpha", &kinematics::DhRow::alpha)
        .def_readonly("d", &kinematics::DhRow::d)
        .def("__repr__", [](const kinematics::DhRow& r) {
            return "<DhRow a=" + std::to_string(r.a) + " alpha=" + std::to_string(r.alpha) +
                   " d=" + std::to_string(r.d) + ">";
        });

    py::class_<kinematics::DhChain>(m, "DhRobot",
                                    "A spatial arm: base and classic Denavit-Hartenberg rows.")
        .def_property_readonly(
            "base", [](const kinematics::DhChain& c) { return point_array(c.base.data(), 3); },
            "The base, [x, y, z] (m).")
        .def_readonly("dh", &kinematics::DhChain::rows, "The DH rows, base first.")
        .def_readonly("link_diameter", &kinematics::DhChain::link_diameter)
        .def_property_readonly("dof", &kinematics::DhChain::dof)
        .def_property_readonly("total_length", &kinematics::DhChain::total_length,
                               "The sum of a_k and |d_k| (m).")
        .def("__repr__", [](const kinematics::DhChain& c) {
            return "<DhRobot " + std::to_string(c.dof()) + " joints, chain " +
                   std::to_string(c.total_length()) + " m>";
        });

    py::class_<verify::Violation>(m, "Violation", "A guarantee broken at a sample.")
        .def_property_readonly("kind",
                               [](const verify::Violation& v) { return violation_kind(v.kind); })
        .def_readonly("sample", &verify::Violation::sample)
        .def_readonly("primitive", &verify::Violation::primitive)
        .def_readonly("transition", &verify::Violation::transition)
        .def_readonly("travel", &verify::Violation::travel)
        .def_readonly("obstacle", &verify::Violation::obstacle)
        .def_readonly("link", &verify::Violation::link)
        .def_readonly("amount", &verify::Violation::amount)
        .def_readonly("message", &verify::Violation::message)
        .def("__repr__",
             [](const verify::Violation& v) { return "<Violation " + v.message + ">"; });

    py::class_<verify::Certificate>(
        m, "Certificate",
        "The verifier's verdict on a motion over the whole continuum (docs/verification.md).")
        .def_readonly("ok", &verify::Certificate::ok)
        .def_readonly("min_clearance", &verify::Certificate::min_clearance,
                      "Certified obstacle clearance margin (m); inf without obstacles.")
        .def_readonly("min_self_clearance", &verify::Certificate::min_self_clearance)
        .def_readonly("max_deviation", &verify::Certificate::max_deviation)
        .def_readonly("max_joint_step", &verify::Certificate::max_joint_step)
        .def_readonly("min_tool_angle_margin", &verify::Certificate::min_tool_angle_margin,
                      "Certified margin of the tool's angle to its tool_axis (rad); inf "
                      "without one.")
        .def_readonly("violations", &verify::Certificate::violations)
        .def_readonly("coarse_pairs", &verify::Certificate::coarse_pairs)
        .def_property_readonly(
            "reason", [](const verify::Certificate& c) { return uncertified_reason(c); },
            "Why it is not ok, naming the first offending sample; \"\" when it is.")
        .def("__bool__", [](const verify::Certificate& c) { return c.ok; })
        .def("__repr__", [](const verify::Certificate& c) {
            return c.ok ? std::string("<Certificate ok>")
                        : "<Certificate not ok: " + uncertified_reason(c) + ">";
        });

    // The modules are pickled field by field: a solution document carries
    // only part of them (formats.md, "Modules"), and a solution that goes
    // to another process (a Dask batch) keeps all of them.
    py::class_<hardware::JointLoad>(m, "JointLoad", "What one joint must deliver over the motion.")
        .def(py::pickle(
            [](const hardware::JointLoad& l) {
                return py::make_tuple(l.peak_torque, l.peak_time, l.rms_torque, l.max_speed,
                                      l.max_speed_time);
            },
            [](const py::tuple& t) {
                return hardware::JointLoad{t[0].cast<double>(), t[1].cast<double>(),
                                           t[2].cast<double>(), t[3].cast<double>(),
                                           t[4].cast<double>()};
            }))
        .def_readonly("peak_torque", &hardware::JointLoad::peak_torque)
        .def_readonly("peak_time", &hardware::JointLoad::peak_time)
        .def_readonly("rms_torque", &hardware::JointLoad::rms_torque)
        .def_readonly("max_speed", &hardware::JointLoad::max_speed)
        .def_readonly("max_speed_time", &hardware::JointLoad::max_speed_time);

    py::class_<hardware::JointChoice>(m, "JointModule",
                                      "The module chosen for one joint, and its margins.")
        .def(py::pickle(
            [](const hardware::JointChoice& c) {
                return py::make_tuple(c.module, c.family, c.cost, c.mass, c.load,
                                      c.peak_torque_limit, c.continuous_torque_limit, c.speed_limit,
                                      c.peak_margin, c.continuous_margin, c.speed_margin,
                                      c.worst_limit, c.worst_share, c.worst_time, c.carries);
            },
            [](const py::tuple& t) {
                hardware::JointChoice c;
                c.module = t[0].cast<std::string>();
                c.family = t[1].cast<std::string>();
                c.cost = t[2].cast<std::optional<double>>();
                c.mass = t[3].cast<double>();
                c.load = t[4].cast<hardware::JointLoad>();
                c.peak_torque_limit = t[5].cast<double>();
                c.continuous_torque_limit = t[6].cast<double>();
                c.speed_limit = t[7].cast<double>();
                c.peak_margin = t[8].cast<double>();
                c.continuous_margin = t[9].cast<double>();
                c.speed_margin = t[10].cast<double>();
                c.worst_limit = t[11].cast<std::string>();
                c.worst_share = t[12].cast<double>();
                c.worst_time = t[13].cast<double>();
                c.carries = t[14].cast<bool>();
                return c;
            }))
        .def_readonly("module", &hardware::JointChoice::module)
        .def_readonly("family", &hardware::JointChoice::family)
        .def_readonly("cost", &hardware::JointChoice::cost)
        .def_readonly("mass", &hardware::JointChoice::mass)
        .def_readonly("load", &hardware::JointChoice::load)
        .def_readonly("peak_torque_limit", &hardware::JointChoice::peak_torque_limit)
        .def_readonly("continuous_torque_limit", &hardware::JointChoice::continuous_torque_limit)
        .def_readonly("speed_limit", &hardware::JointChoice::speed_limit)
        .def_readonly("peak_margin", &hardware::JointChoice::peak_margin)
        .def_readonly("continuous_margin", &hardware::JointChoice::continuous_margin)
        .def_readonly("speed_margin", &hardware::JointChoice::speed_margin)
        .def_readonly("worst_limit", &hardware::JointChoice::worst_limit)
        .def_readonly("worst_share", &hardware::JointChoice::worst_share)
        .def_readonly("worst_time", &hardware::JointChoice::worst_time)
        .def_readonly("carries", &hardware::JointChoice::carries)
        .def("__repr__", [](const hardware::JointChoice& c) {
            return "<JointModule " + c.module + (c.carries ? "" : " (overloaded)") + ">";
        });

    py::class_<hardware::ModuleSelection>(m, "Modules",
                                          "The actuator modules that carry a solved motion.")
        .def(py::pickle(
            [](const hardware::ModuleSelection& s) {
                return py::make_tuple(s.checked, s.joints, s.overloaded_joint, s.total_mass,
                                      s.total_cost, s.cost, s.message);
            },
            [](const py::tuple& t) {
                hardware::ModuleSelection s;
                s.checked = t[0].cast<bool>();
                s.joints = t[1].cast<std::vector<hardware::JointChoice>>();
                s.overloaded_joint = t[2].cast<int>();
                s.total_mass = t[3].cast<double>();
                s.total_cost = t[4].cast<std::optional<double>>();
                s.cost = t[5].cast<std::string>();
                s.message = t[6].cast<std::string>();
                return s;
            }))
        .def_readonly("checked", &hardware::ModuleSelection::checked)
        .def_readonly("joints", &hardware::ModuleSelection::joints)
        .def_readonly("overloaded_joint", &hardware::ModuleSelection::overloaded_joint)
        .def_readonly("total_mass", &hardware::ModuleSelection::total_mass)
        .def_readonly("total_cost", &hardware::ModuleSelection::total_cost)
        .def_readonly("cost", &hardware::ModuleSelection::cost)
        .def_readonly("message", &hardware::ModuleSelection::message)
        .def_property_readonly("carried", &hardware::ModuleSelection::carried)
        .def_property_readonly("names",
                               [](const hardware::ModuleSelection& s) {
                                   std::vector<std::string> out;
                                   for (const auto& j : s.joints) out.push_back(j.module);
                                   return out;
                               })
        .def("__repr__",
             [](const hardware::ModuleSelection& s) { return "<Modules " + s.message + ">"; });
}

}  // namespace modsynth::python
