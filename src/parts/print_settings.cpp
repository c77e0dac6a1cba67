#include <modsynth/parts/print_settings.h>

namespace modsynth::parts {

Material pla() { return {"PLA", 1240.0, 40e6}; }

Material petg() { return {"PETG", 1270.0, 30e6}; }

}  // namespace modsynth::parts
