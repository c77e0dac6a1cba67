#pragma once
// The stack of modules and tubes (hardware/stack.h), under the names the
// outputs have always used.
#include <modsynth/hardware/stack.h>

namespace modsynth::output {

using hardware::distal_allowance;
using hardware::ee_allowance;
using hardware::ee_rod_length;
using hardware::output_face_height;
using hardware::proximal_allowance;
using hardware::tube_axis_height;
using hardware::tube_cuts;
using hardware::TubeCut;

}  // namespace modsynth::output
