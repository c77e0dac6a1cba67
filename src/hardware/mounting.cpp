#include <modsynth/hardware/mounting.h>

#include <cmath>

#include <nlohmann/json.hpp>

#include <modsynth/hardware/catalog.h>

namespace modsynth::hardware {
namespace {

using nlohmann::json;

[[noreturn]] void fail(const std::string& place, const std::string& key,
                       const std::string& message) {
    throw CatalogError(place + ": mounting." + key + ": " + message);
}

double finite_number(const json& v, const std::string& place, const std::string& key) {
    if (!v.is_number() || !std::isfinite(v.get<double>()))
        fail(place, key, "expected a finite number (m), got " + v.dump());
    return v.get<double>();
}

/// A length in m: positive, finite and below 1 m, which catches millimetres
/// written for metres.
double length(const json& obj, const std::string& place, const char* key) {
    const auto it = obj.find(key);
    if (it == obj.end()) fail(place, key, "missing");
    const double v = finite_number(*it, place, key);
    if (v <= 0.0) fail(place, key, "must be greater than 0, got " + it->dump());
    if (v >= 1.0) fail(place, key, it->dump() + " m is 1 m or more (check the unit)");
    return v;
}

}  // namespace

Mounting parse_mounting(const json& value, const std::string& place, double body_length,
                        double body_width) {
    if (!value.is_object())
        throw CatalogError(place + ": mounting: expected an object, got " + value.dump());
    Mounting m;
    m.horn_bolt_circle = length(value, place, "horn_bolt_circle");
    m.horn_hole_diameter = length(value, place, "horn_hole_diameter");
    m.horn_diameter = length(value, place, "horn_diameter");
    m.body_hole_diameter = length(value, place, "body_hole_diameter");
    m.output_offset = length(value, place, "output_offset");

    const auto holes = value.find("horn_holes");
    if (holes == value.end()) fail(place, "horn_holes", "missing");
    if (!holes->is_number_integer() || holes->get<long long>() < 1 || holes->get<long long>() > 64)
        fail(place, "horn_holes", "expected a whole number from 1 to 64, got " + holes->dump());
    m.horn_holes = holes->get<int>();

    // A screw must go through the horn: its hole lies inside the horn's
    // outline and clear of the axis.
    if (m.horn_bolt_circle + m.horn_hole_diameter > m.horn_diameter) {
        fail(place, "horn_bolt_circle",
             json(m.horn_bolt_circle).dump() + " m with holes of " +
                 json(m.horn_hole_diameter).dump() + " m does not fit inside the horn's " +
                 json(m.horn_diameter).dump() + " m");
    }
    if (m.horn_hole_diameter >= m.horn_bolt_circle) {
        fail(place, "horn_hole_diameter",
             json(m.horn_hole_diameter).dump() + " m is not less than the bolt circle's " +
                 json(m.horn_bolt_circle).dump() + " m");
    }
    if (m.output_offset >= body_length) {
        fail(place, "output_offset",
             json(m.output_offset).dump() + " m puts the output axis outside the body (" +
                 json(body_length).dump() + " m long)");
    }

    const auto body = value.find("body_holes");
    if (body == value.end()) fail(place, "body_holes", "missing");
    if (!body->is_array() || body->empty() || body->size() > 64)
        fail(place, "body_holes", "expected a list of 1 to 64 [x, y] pairs (m)");
    for (std::size_t i = 0; i < body->size(); ++i) {
        const json& h = (*body)[i];
        const std::string key = "body_holes[" + std::to_string(i) + "]";
        if (!h.is_array() || h.size() != 2)
            fail(place, key, "expected [x, y] (m), got " + h.dump());
        const double x = finite_number(h[0], place, key);
        const double y = finite_number(h[1], place, key);
        // The face opposite the horn spans the body's outline in the body
        // frame: x from -output_offset to length - output_offset.
        if (x < -m.output_offset || x > body_length - m.output_offset ||
            std::fabs(y) > body_width / 2.0) {
            fail(place, key,
                 h.dump() + " lies off the body's face (x from " + json(-m.output_offset).dump() +
                     " to " + json(body_length - m.output_offset).dump() + " m, |y| up to " +
                     json(body_width / 2.0).dump() + " m)");
        }
        m.body_holes.push_back({x, y});
    }
    return m;
}

}  // namespace modsynth::hardware
