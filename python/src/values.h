#pragma once
// Python classes of the value types the pipeline answers with.
#include <vector>

#include <pybind11/pybind11.h>

#include <modsynth/control/motion.h>

namespace modsynth::python {

namespace py = pybind11;

void bind_values(py::module_& m);

/// The samples as NumPy arrays: t, s, primitive, stroke (one value per
/// sample), q, qd, qdd (a row per sample; qd and qdd None when the motion
/// carries none) and phase (a list of "trace", "transition", "travel").
py::dict sample_arrays(const std::vector<control::Sample>& samples);

}  // namespace modsynth::python
