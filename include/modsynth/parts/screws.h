#pragma once
// The screws the printed parts are assembled with: the build sheet's list.
#include <string>
#include <vector>

#include <modsynth/parts/link_design.h>

namespace modsynth::parts {

struct Screw {
    std::string size;     ///< "M3"
    double length = 0.0;  ///< m, under the head
    int count = 0;
    std::string use;  ///< what it holds
};

/// The metric size a clearance hole (m) is drilled for: M2 for 2.2 mm, M3
/// for 3.2-3.4 mm, M5 for 5.5 mm.
std::string metric_size(double clearance_hole);

/// The shortest stock length (4 to 40 mm) at least `length` (m).
double stock_length(double length);

/// Through a plate of `plate` into a module's thread: the plate and two
/// diameters of engagement (check the maker's thread depth), stock length.
Screw through_plate(double clearance_hole, double plate, int count, const std::string& use);

/// Every screw of an arm's links, its base plate (module 1 and the table's
/// M5 bolts) and its tool holder; like sizes and lengths added up.
std::vector<Screw> arm_screws(const std::vector<LinkDesign>& links, const ModuleMount& first,
                              double base_plate);

}  // namespace modsynth::parts
