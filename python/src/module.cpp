// modsynth._core: the public C++ API (modsynth.h) for the Python package,
// whose pure-Python layer (python/modsynth/) gives it its final shape:
// tasks from dicts and files, NumPy samples, Dask batches.
#include <cstddef>
#include <iterator>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include <pybind11/functional.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <nlohmann/json.hpp>

#include <modsynth/io/task_checks.h>
#include <modsynth/io/task_document.h>
#include <modsynth/modsynth.h>

#include "solver_call.h"
#include "values.h"

namespace modsynth::python {

bool& inside_callback() {
    thread_local bool inside = false;
    return inside;
}

namespace {

using TaskVariant = std::variant<Task, SpatialTask>;

/// A validated task of either kind.
struct TaskDocument {
    TaskVariant task;
};

TaskDocument parse_task(const std::string& json_text) {
    if (is_spatial_task(json_text)) return {read_spatial_task(json_text)};
    return {read_task(json_text)};
}

/// As `modsynth` reads a task file: a task without a name takes the file's
/// name without its extension; an unreadable or invalid file is an
/// InputError said of the file.
TaskDocument load_task_file(const std::string& path) { return {io::load_task_document(path)}; }

/// What the command line warns of in a task document it reads (keys the
/// format does not define, lengths that look like millimetres), each as
/// it prints it, said of `file` when one is given. A document that is not
/// JSON has none: reading it says what is wrong.
std::vector<std::string> task_warnings(const std::string& json_text, const std::string& file) {
    const nlohmann::json doc = nlohmann::json::parse(json_text, nullptr, false);
    std::vector<std::string> out;
    if (doc.is_discarded()) return out;
    const auto said = [&](const InputError& w) -> std::string {
        return file.empty() ? w.what() : w.in_file(file).what();
    };
    for (const InputError& w : io::unknown_keys(doc))
        out.push_back(said(w) + " (the task is read without it)");
    for (const InputError& w : io::unit_warnings(doc)) out.push_back(said(w));
    return out;
}

const std::string& task_name(const TaskDocument& t) {
    return std::visit([](const auto& x) -> const std::string& { return x.name; }, t.task);
}

std::string status_text(const synth::Status& s) { return synth::to_string(s.kind); }

py::object robot_of(const Solution& s) {
    if (s.status != Status::Solved || s.dh_robot) return py::none();
    return py::cast(s.robot);
}

py::object dh_robot_of(const Solution& s) {
    if (s.status != Status::Solved || !s.dh_robot) return py::none();
    return py::cast(*s.dh_robot);
}

/// Raises the package's own exceptions (modsynth/_errors.py) for the
/// library's: TaskError for bad input, naming the part.
void translate_errors(std::exception_ptr p) {
    static py::handle task_error, import_timeout;
    if (!task_error) {
        py::module_ errors = py::module_::import("modsynth._errors");
        task_error = py::object(errors.attr("TaskError")).release();
        import_timeout = py::object(errors.attr("ImportTimeout")).release();
    }
    try {
        if (p) std::rethrow_exception(p);
    } catch (const InputError& e) {
        py::object error = task_error(e.problem(), e.part(), e.file());
        PyErr_SetObject(task_error.ptr(), error.ptr());
    } catch (const ImportTimeout& e) {
        PyErr_SetString(import_timeout.ptr(), e.what());
    }
}

Solution solve_task(const TaskDocument& t, double time_limit, unsigned seed,
                    const py::object& progress) {
    SolveOptions options;
    options.time_limit = time_limit;
    options.seed = seed;
    const run::CancelToken cancel = options.cancel;
    const TaskVariant task = t.task;
    return call_on_solver_thread<Solution>(
        [task, options](const run::ProgressSink& sink) {
            SolveOptions o = options;
            o.progress = sink;
            return std::visit([&](const auto& x) { return modsynth::solve(x, o); }, task);
        },
        cancel, progress);
}

Explanation explain_task(const TaskDocument& t, double time_limit, double solve_seconds,
                         double proof_seconds, const py::object& progress) {
    ExplainOptions options;
    options.time_limit = time_limit;
    options.solve_seconds = solve_seconds;
    options.proof_seconds = proof_seconds;
    std::string error;
    if (!options.IsValid(&error)) throw std::invalid_argument(error);
    const TaskVariant task = t.task;
    return call_on_solver_thread<Explanation>(
        [task, options](const run::ProgressSink& sink) {
            ExplainOptions o = options;
            o.progress = sink;
            return std::visit([&](const auto& x) { return modsynth::explain(x, o); }, task);
        },
        std::nullopt, progress);
}

}  // namespace

}  // namespace modsynth::python

PYBIND11_MODULE(_core, m) {
    using namespace modsynth;
    using namespace modsynth::python;
    m.doc() =
        "The compiled core of modsynth: the public C++ API (include/modsynth/modsynth.h). "
        "Use the package `modsynth`, which builds on it.";
    py::register_exception_translator(&translate_errors);
    bind_values(m);

    py::class_<TaskDocument>(m, "TaskDocument", "A validated task, planar or spatial.")
        .def_property_readonly("name", &task_name)
        .def_property_readonly(
            "spatial",
            [](const TaskDocument& t) { return std::holds_alternative<SpatialTask>(t.task); })
        .def(
            "to_json",
            [](const TaskDocument& t) {
                return std::visit([](const auto& x) { return write_task_json(x); }, t.task);
            },
            "The task as a modsynth-task/1 document (JSON text).");
    m.def("parse_task", &parse_task, py::arg("json_text"),
          "A task document (JSON text) validated; TaskError naming the offending part.");
    m.def("load_task", &load_task_file, py::arg("path"),
          "A task file validated; a task without a name takes the file's stem.");
    m.def("task_warnings", &task_warnings, py::arg("json_text"), py::arg("file") = "",
          "What `modsynth validate` warns of in a task document: unknown keys (with the "
          "nearest known one) and lengths that look like millimetres.");

    py::class_<synth::Explanation>(m, "SolutionExplanation",
                                   "Why a solution is infeasible or unknown.")
        .def_readonly("message", &synth::Explanation::message)
        .def_property_readonly(
            "core", [](const synth::Explanation& e) { return task::to_strings(e.core); },
            "The task parts that conflict, e.g. \"trajectory[3]\".");

    py::class_<Solution>(m, "Solution", "A solution as the pipeline answers it.")
        .def_readonly("task_name", &Solution::task_name)
        .def_property_readonly("status", [](const Solution& s) { return status_text(s.status); })
        .def_property_readonly("status_stage", [](const Solution& s) { return s.status.stage; })
        .def_property_readonly("status_reason", [](const Solution& s) { return s.status.reason; })
        .def_property_readonly("robot", &robot_of)
        .def_property_readonly("dh_robot", &dh_robot_of)
        .def_readonly("certificate", &Solution::certificate)
        .def_readonly("explanation", &Solution::explanation)
        .def_readwrite("modules", &Solution::modules,
                       "The modules chosen for the motion; a document read back has none (they "
                       "are chosen again from the task, as `modsynth export` does).")
        .def_property_readonly("sample_count", [](const Solution& s) { return s.samples.size(); })
        .def("sample_arrays", [](const Solution& s) { return sample_arrays(s.samples); })
        .def("to_json", &write_solution_json,
             "The modsynth-solution/1 document, the bytes `modsynth solve` writes.");
    m.def(
        "read_solution",
        [](const std::string& text) {
            py::gil_scoped_release release;
            return read_solution(text);
        },
        py::arg("json_text"));

    py::class_<explanation::Relaxation>(m, "Suggestion",
                                        "A change of one part that removes the conflict.")
        .def_property_readonly(
            "part", [](const explanation::Relaxation& r) { return task::to_string(r.part); })
        .def_readonly("change", &explanation::Relaxation::change)
        .def_property_readonly(
            "status", [](const explanation::Relaxation& r) { return status_text(r.status); })
        .def_readonly("outcome", &explanation::Relaxation::outcome)
        .def_property_readonly(
            "task", [](const explanation::Relaxation& r) { return TaskDocument{r.relaxed}; },
            "The task with the change applied.");

    py::class_<Explanation>(m, "Explanation", "Why a task cannot be done.")
        .def_readonly("proved", &Explanation::proved)
        .def_property_readonly("status", [](const Explanation& e) { return status_text(e.status); })
        .def_readonly("message", &Explanation::message)
        .def_property_readonly("core",
                               [](const Explanation& e) { return task::to_strings(e.core); })
        .def_readonly("suggestions", &Explanation::suggestions)
        .def(
            "to_json",
            [](const Explanation& e, const std::string& task_name) {
                return write_explanation_json(task_name, e);
            },
            py::arg("task_name"), "As `modsynth explain --json` prints it.");

    m.def("solve", &solve_task, py::arg("task"), py::arg("time_limit"), py::arg("seed"),
          py::arg("progress"));
    m.def("explain", &explain_task, py::arg("task"), py::arg("time_limit"),
          py::arg("solve_seconds"), py::arg("proof_seconds"), py::arg("progress"));
    m.def(
        "certify",
        [](const TaskDocument& t, const Solution& s) {
            py::gil_scoped_release release;
            return std::visit([&](const auto& x) { return modsynth::certify(x, s); }, t.task);
        },
        py::arg("task"), py::arg("solution"));

    m.def(
        "write_exports",
        [](const TaskDocument& t, const Solution& s, const std::string& report,
           const std::string& urdf, const std::string& csv, const std::string& joint_trajectory,
           const std::string& build_sheet, bool write_uncertified, bool had_certificate) {
            ExportFiles files;
            files.report = report;
            files.urdf = urdf;
            files.csv = csv;
            files.joint_trajectory = joint_trajectory;
            files.build_sheet = build_sheet;
            files.write_uncertified = write_uncertified;
            files.had_certificate = had_certificate;
            py::gil_scoped_release release;
            return std::visit([&](const auto& x) { return modsynth::write_exports(x, s, files); },
                              t.task);
        },
        py::arg("task"), py::arg("solution"), py::arg("report"), py::arg("urdf"), py::arg("csv"),
        py::arg("joint_trajectory"), py::arg("build_sheet"), py::arg("write_uncertified"),
        py::arg("had_certificate"));

    py::class_<DrawingImport>(m, "DrawingImport", "What to import and how (modsynth import).")
        .def(py::init<>())
        .def_readwrite("path", &DrawingImport::path)
        .def_readwrite("contents", &DrawingImport::contents)
        .def_readwrite("format", &DrawingImport::format)
        .def_readwrite("text", &DrawingImport::text)
        .def_readwrite("font", &DrawingImport::font)
        .def_readwrite("text_height", &DrawingImport::text_height)
        .def_readwrite("name", &DrawingImport::name)
        .def_readwrite("width", &DrawingImport::width)
        .def_readwrite("scale", &DrawingImport::scale)
        .def_readwrite("at", &DrawingImport::at)
        .def_readwrite("rotate_degrees", &DrawingImport::rotate_degrees)
        .def_readwrite("tolerance", &DrawingImport::tolerance)
        .def_readwrite("time_limit", &DrawingImport::time_limit)
        .def_readwrite("base_regions", &DrawingImport::base_regions)
        .def_readwrite("obstacle_layer", &DrawingImport::obstacle_layer)
        .def_readwrite("layers", &DrawingImport::layers)
        .def_readwrite("strict", &DrawingImport::strict)
        .def_readwrite("hatch_boundaries", &DrawingImport::hatch_boundaries)
        .def_readwrite("keep_order", &DrawingImport::keep_order)
        .def_readwrite("dof", &DrawingImport::dof)
        .def_readwrite("link_diameter", &DrawingImport::link_diameter)
        .def_readwrite("plane", &DrawingImport::plane)
        .def_readwrite("cylinder", &DrawingImport::cylinder)
        .def_readwrite("tool_length", &DrawingImport::tool_length)
        .def_readwrite("tool", &DrawingImport::tool)
        .def_readwrite("tool_tolerance_degrees", &DrawingImport::tool_tolerance_degrees);
    py::class_<ImportedDrawing>(m, "ImportedDrawing", "A task made from a drawing.")
        .def_readonly("task_json", &ImportedDrawing::task_json)
        .def_readonly("primitives_per_stroke", &ImportedDrawing::primitives_per_stroke)
        .def_readonly("obstacles", &ImportedDrawing::obstacles)
        .def_readonly("deviation", &ImportedDrawing::deviation)
        .def_readonly("travel", &ImportedDrawing::travel)
        .def_readonly("surface", &ImportedDrawing::surface)
        .def_readonly("warnings", &ImportedDrawing::warnings)
        .def_readonly("filled_outlines", &ImportedDrawing::filled_outlines)
        .def_readonly("layers", &ImportedDrawing::layers);
    m.def(
        "import_drawing",
        [](const DrawingImport& request) {
            py::gil_scoped_release release;
            return import_drawing(request);
        },
        py::arg("request"));

    m.def("set_catalog_folder", &set_catalog_folder, py::arg("folder"));
    m.def("catalog_folder", &catalog_folder);
    m.def(
        "shut_down",
        [] {
            py::gil_scoped_release release;
            SolverThread::shut_down();
        },
        "Cancels what the solver thread runs, waits for it and stops it (at exit).");
}
