#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

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

TEST_CASE("a library tells where its catalog lies, and can go back", "[hardware]") {
    const std::string shipped = default_catalog_folder();
    const auto folder = std::filesystem::temp_directory_path() / "modsynth-given-catalog";
    std::filesystem::create_directories(folder);
    std::ofstream(folder / "test.json") << actuator_file(kGood);
    set_default_catalog_folder(folder.string());
    CHECK(default_catalog_folder() == folder.string());
    const Catalog given = load_default_catalog();
    REQUIRE(given.actuators.size() == 1);
    CHECK(given.actuator("T-1") != nullptr);
    set_default_catalog_folder("");
    CHECK(default_catalog_folder() == shipped);
    CHECK(load_default_catalog().actuator("T-1") == nullptr);
    std::filesystem::remove_all(folder);
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

TEST_CASE("the shipped hobby-servo families derive their ratings from the stall figures",
          "[hardware]") {
    const Catalog c = load_catalog(std::string(MODSYNTH_SOURCE_DIR) + "/catalog");
    CHECK(c.families() == std::vector<std::string>{"dynamixel-x", "feetech", "hebi-x"});
    const std::vector<std::string> dynamixels = {"XL330-M288", "XL430-W250", "XC430-W150",
                                                 "XC430-W240", "XM430-W350", "XH430-W350",
                                                 "XM540-W270"};
    CHECK(c.family("dynamixel-x").size() == dynamixels.size());
    std::vector<std::string> servos = dynamixels;
    for (const char* f : {"STS3215", "STS3250", "SCS0009"}) servos.push_back(f);
    for (const auto& name : servos) {
        INFO(name);
        const Actuator* a = c.actuator(name);
        REQUIRE(a != nullptr);
        CHECK((a->family == "dynamixel-x" || a->family == "feetech"));
        CHECK_FALSE(a->default_choice);
        REQUIRE(a->stall_torque);
        REQUIRE(a->no_load_speed);
        REQUIRE(a->cost);
        CHECK(*a->cost > 1.0);
        CHECK(*a->cost < 1000.0);
        CHECK(a->mass < 0.2);
        // formats.md "Module catalog": a fifth of the stall torque runs
        // indefinitely; half of it and half the no-load speed at once stay
        // on the motor's speed-torque line.
        CHECK(a->continuous_torque == Approx(*a->stall_torque / 5.0).epsilon(1e-3));
        CHECK(a->peak_torque == Approx(*a->stall_torque / 2.0).epsilon(1e-3));
        CHECK(a->max_speed == Approx(*a->no_load_speed / 2.0).epsilon(1e-3));
        CHECK(a->peak_torque / *a->stall_torque + a->max_speed / *a->no_load_speed <= 1.0);
        if (name != "SCS0009") {
            REQUIRE(a->mounting);
            CHECK(a->mounting->horn_bolt_circle < a->mounting->horn_diameter);
            CHECK(a->mounting->output_offset < a->dimensions.length);
        }
    }
    CHECK(c.actuator("XM430-W350")->stall_torque == Approx(4.1));
    CHECK(c.actuator("XM430-W350")->mass == Approx(0.082));
    CHECK(c.actuator("XL330-M288")->mass == Approx(0.018));
    // 30 kg cm at 12 V; 0.222 s per 60 degrees.
    CHECK(*c.actuator("STS3215")->stall_torque == Approx(30 * 0.0980665).epsilon(1e-3));
    CHECK(*c.actuator("STS3215")->no_load_speed == Approx(M_PI / 3 / 0.222).epsilon(1e-3));
    for (const Actuator* a : c.family("hebi-x")) {
        CHECK(a->default_choice);
        CHECK_FALSE(a->cost);  // no public list price: "cost unknown"
    }
}

TEST_CASE("optional figures need a source and stay within the maker's limits", "[hardware]") {
    const auto with = [](const std::string& figures, const std::string& sources) {
        std::string e = kGood;
        e.replace(e.find("\"max_speed\": 3,"), 15, "\"max_speed\": 3, " + figures + ",");
        e.replace(e.find("\"dimensions\": \"e\""), 17, "\"dimensions\": \"e\"" + sources);
        return actuator_file(e);
    };
    Catalog c;
    parse_catalog_file(with(R"("cost": 23.9, "stall_torque": 4, "no_load_speed": 6)",
                            R"(, "cost": "u", "stall_torque": "v", "no_load_speed": "w")"),
                       "ok.json", c);
    REQUIRE(c.actuators.size() == 1);
    CHECK(c.actuators[0].cost == Approx(23.9));
    CHECK(c.actuators[0].family == "test");
    CHECK_FALSE(c.actuators[0].mounting);
    CHECK_FALSE(c.actuators[0].voltage);
    CHECK(error_of(with(R"("cost": 23.9)", ""), "c.json") ==
          "c.json: entries[0] (T-1): sources.cost: missing; say where the figure is from");
    CHECK(error_of(with(R"("stall_torque": -4)", R"(, "stall_torque": "v")"), "t.json") ==
          "t.json: entries[0] (T-1): stall_torque: must be greater than 0, got -4");
    CHECK(error_of(with(R"("stall_torque": 1.5)", R"(, "stall_torque": "v")"), "p.json") ==
          "p.json: entries[0] (T-1): peak_torque 2.0 is more than stall_torque 1.5");
    CHECK(error_of(with(R"("no_load_speed": 2)", R"(, "no_load_speed": "w")"), "v.json") ==
          "v.json: entries[0] (T-1): max_speed 3.0 is more than no_load_speed 2.0");
    const std::string mounting =
        R"("mounting": {"horn_bolt_circle": 0.016, "horn_holes": 8, "horn_hole_diameter": 0.0022,
           "horn_diameter": 0.020, "body_holes": [[0.0, 0.008]], "body_hole_diameter": 0.0027,
           "output_offset": 0.02})";
    parse_catalog_file(with(mounting, R"(, "mounting": "m")"), "ok.json", c);
    REQUIRE(c.actuators.back().mounting);
    CHECK(c.actuators.back().mounting->horn_holes == 8);
    CHECK(error_of(with(mounting, ""), "m.json") ==
          "m.json: entries[0] (T-1): sources.mounting: missing; say where the figure is from");
    std::string bad = mounting;
    bad.replace(bad.find("\"horn_holes\": 8"), 15, "\"horn_holes\": -1");
    CHECK(error_of(with(bad, R"(, "mounting": "m")"), "b.json")
              .find("b.json: entries[0] (T-1): mounting.horn_holes: expected a whole number") == 0);
}

TEST_CASE("an actuator file names its family", "[hardware]") {
    std::string f = actuator_file(kGood);
    const std::string no_family = std::string(f).erase(f.find("\"family\": \"test\", "), 18);
    CHECK(error_of(no_family, "f.json").find("f.json: family: expected a non-empty text") == 0);
    std::string marked = f;
    marked.replace(marked.find("\"kind\""), 6, "\"default\": 1, \"kind\"");
    CHECK(error_of(marked, "d.json") == "d.json: default: expected true or false, got 1");
    const auto dir = modsynth::testing::scratch_dir("catalog_family_name");
    std::string clash = f;
    clash.replace(clash.find("\"family\": \"test\""), 16, "\"family\": \"T-1\"");
    std::ofstream(dir / "a.json") << clash;
    CHECK_THROWS_WITH(load_catalog(dir.string()),
                      Catch::Contains("the family \"T-1\" has the name of a part"));
    std::filesystem::remove(dir / "a.json");
}
