#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <string>

#include <modsynth/control/joint_limits.h>
#include <modsynth/hardware/catalog.h>

#include "../output/output_fixtures.h"

using namespace modsynth::hardware;

namespace {

std::string actuator_file(const std::string& entry) {
    return R"({"format": "modsynth-catalog/1", "family": "test", "kind": "actuator", "entries": [)" +
           entry + "]}";
}

const char* kGood =
    R"({"name": "T-1", "mass": 0.3, "continuous_torque": 1, "peak_torque": 2, "max_speed": 3,
        "dimensions": {"length": 0.1, "width": 0.07, "height": 0.03},
        "sources": {"mass": "a", "continuous_torque": "b", "peak_torque": "c",
                    "max_speed": "d", "dimensions": "e"}})";

std::string error_of(const std::string& text, const std::string& file) {
    Catalog c;
    try {
        parse_catalog_file(text, file, c);
    } catch (const CatalogError& e) {
        return e.what();
    }
    return "";
}

}  // namespace

TEST_CASE("the shipped catalog has the paper's HEBI X-series modules", "[hardware]") {
    const Catalog c = load_catalog(std::string(MODSYNTH_SOURCE_DIR) + "/catalog");
    for (const char* name : {"X5-1", "X5-4", "X5-9", "X8-3", "X8-9", "X8-16"}) {
        const Actuator* a = c.actuator(name);
        REQUIRE(a != nullptr);
        CHECK(a->mass > 0.2);
        CHECK(a->mass < 0.6);
        CHECK(a->continuous_torque <= a->peak_torque);
        CHECK(a->max_speed > 0.0);
        CHECK(a->dimensions.length == Approx(0.110));
    }
    // The X8-16 is the strongest and slowest; the X5-1 the lightest.
    CHECK(c.actuator("X8-16")->peak_torque == Approx(38.0));
    CHECK(c.actuator("X8-16")->max_speed < c.actuator("X8-9")->max_speed);
    CHECK(c.actuator("X5-1")->mass < c.actuator("X5-4")->mass);
    CHECK(c.tube_closest_to(0.03175).mass_per_metre == Approx(0.4));
    CHECK(c.tube_closest_to(0.009).diameter == Approx(0.0095));
    CHECK(c.adapter().mass > 0.0);
    // A task without joint limits is timed with the X8-9's (joint_limits.h).
    CHECK(c.actuator("X8-9")->max_speed == Approx(modsynth::control::kDefaultJointSpeed));
}

TEST_CASE("the program finds its catalog", "[hardware]") {
    CHECK(std::filesystem::is_directory(default_catalog_folder()));
    CHECK(load_default_catalog().actuators.size() >= 6);
}

TEST_CASE("catalog errors name the file and the entry", "[hardware]") {
    Catalog c;
    parse_catalog_file(actuator_file(kGood), "good.json", c);
    CHECK(c.actuators.size() == 1);
    std::string bad = kGood;
    bad.replace(bad.find("\"peak_torque\": 2"), 16, "\"peak_torque\": -2");
    CHECK(error_of(actuator_file(bad), "bad.json") ==
          "bad.json: entries[0] (T-1): peak_torque: must be greater than 0, got -2");
    std::string no_source = kGood;
    no_source.replace(no_source.find("\"max_speed\": \"d\", "), 18, "");
    CHECK(error_of(actuator_file(std::string(kGood) + "," + no_source), "s.json")
              .find("s.json: entries[1] (T-1): sources.max_speed: missing") == 0);
    std::string weak = kGood;
    weak.replace(weak.find("\"continuous_torque\": 1"), 22, "\"continuous_torque\": 5");
    CHECK(error_of(actuator_file(weak), "w.json")
              .find("w.json: entries[0] (T-1): continuous_torque 5") == 0);
    CHECK(error_of("{", "broken.json").find("broken.json: not valid JSON") == 0);
    CHECK(error_of(R"({"format": "modsynth-catalog/1", "kind": "gear", "entries": [{}]})", "k.json")
              .find("k.json: kind:") == 0);
    CHECK(error_of(actuator_file("3"), "n.json") == "n.json: entries[0]: expected an object");
}

TEST_CASE("a catalog folder with a name twice or no actuator is refused", "[hardware]") {
    const auto dir = modsynth::testing::scratch_dir("catalog_twice");
    std::ofstream(dir / "a.json") << actuator_file(kGood);
    std::ofstream(dir / "b.json") << actuator_file(kGood);
    CHECK_THROWS_WITH(load_catalog(dir.string()), Catch::Contains("\"T-1\" appears twice"));
    std::filesystem::remove(dir / "a.json");
    std::filesystem::remove(dir / "b.json");
    CHECK_THROWS_WITH(load_catalog(dir.string()), Catch::Contains("has no actuator"));
    CHECK_THROWS_AS(load_catalog((dir / "missing").string()), CatalogError);
}
