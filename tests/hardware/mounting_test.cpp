#include <catch2/catch.hpp>

#include <string>

#include <nlohmann/json.hpp>

#include <modsynth/hardware/catalog.h>
#include <modsynth/hardware/mounting.h>

using modsynth::hardware::CatalogError;
using modsynth::hardware::parse_mounting;
using nlohmann::json;

namespace {

/// An X430-sized pattern: 46.5 mm long, 28.5 mm wide.
json good() {
    return json::parse(R"({"horn_bolt_circle": 0.016, "horn_holes": 8,
        "horn_hole_diameter": 0.0022, "horn_diameter": 0.020,
        "body_holes": [[0.0, -0.008], [0.024, 0.008]], "body_hole_diameter": 0.0027,
        "output_offset": 0.01425})");
}

std::string error_of(const json& m) {
    try {
        parse_mounting(m, "x.json: entries[0] (S)", 0.0465, 0.0285);
    } catch (const CatalogError& e) {
        return e.what();
    }
    return "";
}

}  // namespace

TEST_CASE("a mounting pattern is read in metres", "[hardware]") {
    const auto m = parse_mounting(good(), "x", 0.0465, 0.0285);
    CHECK(m.horn_bolt_circle == Approx(0.016));
    CHECK(m.horn_holes == 8);
    CHECK(m.horn_hole_diameter == Approx(0.0022));
    CHECK(m.horn_diameter == Approx(0.020));
    REQUIRE(m.body_holes.size() == 2);
    CHECK(m.body_holes[1][0] == Approx(0.024));
    CHECK(m.body_holes[0][1] == Approx(-0.008));
    CHECK(m.body_hole_diameter == Approx(0.0027));
    CHECK(m.output_offset == Approx(0.01425));
}

TEST_CASE("a bad mounting pattern is refused naming the file, entry and key", "[hardware]") {
    auto m = good();
    m.erase("horn_diameter");
    CHECK(error_of(m) == "x.json: entries[0] (S): mounting.horn_diameter: missing");
    m = good();
    m["horn_holes"] = 0;
    CHECK(error_of(m).find(
              "x.json: entries[0] (S): mounting.horn_holes: expected a whole number") == 0);
    m["horn_holes"] = 2.5;
    CHECK(error_of(m).find("mounting.horn_holes: expected a whole number") != std::string::npos);
    m = good();
    m["body_hole_diameter"] = -0.003;
    CHECK(
        error_of(m) ==
        "x.json: entries[0] (S): mounting.body_hole_diameter: must be greater than 0, got -0.003");
    m = good();
    m["horn_bolt_circle"] = 16;  // millimetres for metres
    CHECK(error_of(m).find("mounting.horn_bolt_circle: 16 m is 1 m or more") != std::string::npos);
    m = good();
    m["horn_bolt_circle"] = 0.019;  // the holes would cut the horn's rim
    CHECK(error_of(m).find("mounting.horn_bolt_circle: 0.019 m with holes of 0.0022 m does not "
                           "fit inside the horn's 0.02 m") != std::string::npos);
    m = good();
    m["output_offset"] = 0.05;
    CHECK(
        error_of(m).find("mounting.output_offset: 0.05 m puts the output axis outside the body") !=
        std::string::npos);
    m = good();
    m["body_holes"][1] = {0.024, 0.02};  // past the 14.25 mm half-width
    CHECK(error_of(m).find("mounting.body_holes[1]: [0.024,0.02] lies off the body's face") !=
          std::string::npos);
    m["body_holes"][1] = {0.024};
    CHECK(error_of(m).find("mounting.body_holes[1]: expected [x, y]") != std::string::npos);
    m["body_holes"] = json::array();
    CHECK(error_of(m).find("mounting.body_holes: expected a list") != std::string::npos);
    CHECK(error_of(json(3)) == "x.json: entries[0] (S): mounting: expected an object, got 3");
}
