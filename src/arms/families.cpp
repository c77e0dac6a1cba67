// The arm families of the spatial search, in the order it tries them for a
// joint count (docs/design.md "Adding an arm family"). Each family's folder
// defines its instance.
#include <modsynth/arms/family.h>

namespace modsynth::arms {

const Family& yaw_pitch_family();
const Family& scara_family();

const std::vector<const Family*>& families() {
    static const std::vector<const Family*> all{
        &yaw_pitch_family(),
        &scara_family(),
    };
    return all;
}

}  // namespace modsynth::arms
