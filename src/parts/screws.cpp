#include <modsynth/parts/screws.h>

#include <cmath>

#include <modsynth/text/format.h>

namespace modsynth::parts {

std::string metric_size(double clearance_hole) {
    // Clearance holes are 0.2-0.5 mm over the thread.
    const double mm = clearance_hole * 1000.0;
    const double thread = std::floor((mm - 0.15) * 2.0) / 2.0;
    return thread == std::floor(thread) ? text::format("M%d", static_cast<int>(thread))
                                        : text::format("M%.1f", thread);
}

double stock_length(double length) {
    for (double mm : {4.0, 5.0, 6.0, 8.0, 10.0, 12.0, 14.0, 16.0, 20.0, 25.0, 30.0, 35.0, 40.0})
        if (mm >= length * 1000.0 - 1e-9) return mm / 1000.0;
    return std::ceil(length * 200.0) / 200.0;
}

Screw through_plate(double clearance_hole, double plate, int count, const std::string& use) {
    const std::string size = metric_size(clearance_hole);
    const double thread = std::stod(size.substr(1)) / 1000.0;
    return {size, stock_length(plate + 2.0 * thread), count, use};
}

std::vector<Screw> arm_screws(const std::vector<LinkDesign>& links, const ModuleMount& first,
                              double base_plate) {
    std::vector<Screw> out;
    const auto add = [&](const Screw& s) {
        for (auto& o : out)
            if (o.size == s.size && o.length == s.length) {
                o.count += s.count;
                o.use += ", " + s.use;
                return;
            }
        out.push_back(s);
    };
    add(through_plate(first.mounting.body_hole_diameter, base_plate,
                      static_cast<int>(first.mounting.body_holes.size()),
                      "module 1 on the base plate"));
    add({"M5", 0.0, 4, "base plate to the table (length to suit the table)"});
    for (const auto& l : links) {
        const Mounting& h = l.horn.mounting;
        add(through_plate(h.horn_hole_diameter, l.beam.plate, h.horn_holes,
                          text::format("link %d on module %d's horn", l.index, l.index)));
        if (l.body) {
            add(through_plate(l.body->mounting.body_hole_diameter, l.beam.plate,
                              static_cast<int>(l.body->mounting.body_holes.size()),
                              text::format("module %d on link %d", l.index + 1, l.index)));
        } else {
            // Through the link's plate and the holder's flange, into a nut.
            add({"M3", stock_length(2.0 * l.beam.plate + 0.003), 2,
                 text::format("tool holder under link %d (with nuts)", l.index)});
            add({"M3", 0.006, 1, "set screw clamping the end-effector rod"});
        }
    }
    return out;
}

}  // namespace modsynth::parts
