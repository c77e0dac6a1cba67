#include <catch2/catch.hpp>

#include <modsynth/synth/proximal_plan.h>

using namespace modsynth;
