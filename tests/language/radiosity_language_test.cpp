// Reading global_settings { radiosity { } } as POV-Ray 3.7's
// Parse_Global_Settings reads it: its defaults, every setting, the second
// values of count and nearest_count, its limits and messages, settings
// written by a macro (rad_def.inc's way), and the object's no_radiosity
// and radiosity { importance }.
#include <string>

#include <catch2/catch.hpp>

#include "language/interpreter.hpp"
#include "scene_text.hpp"

using hexant::test::check_error_at;
using hexant::test::scene_of;
namespace rt = hexant::runtime;

TEST_CASE("radiosity's defaults are POV-Ray 3.7's", "[language][radiosity]") {
    const rt::RadiositySettings none = scene_of("sphere { 0, 1 }").global.radiosity;
    CHECK_FALSE(none.enabled);
    const rt::RadiositySettings r = scene_of("global_settings { radiosity { } }").global.radiosity;
    CHECK(r.enabled);
    CHECK(r.count == 35);
    CHECK(r.direction_pool == 1600);
    CHECK(r.nearest_count == 5);
    CHECK(r.error_bound == 1.8);
    CHECK(r.recursion_limit == 2);
    CHECK(r.low_error_factor == 0.5);
    CHECK(r.minimum_reuse == 0.015);
    CHECK(r.maximum_reuse == 0.2);
    CHECK(r.pretrace_start == 0.08);
    CHECK(r.pretrace_end == 0.04);
    CHECK(r.brightness == 1.0);
    CHECK(r.adc_bailout == 0.01);
    CHECK_FALSE(r.always_sample);
    CHECK_FALSE(r.normal);
    CHECK_FALSE(r.media);
}

TEST_CASE("radiosity's settings are read, a macro's too", "[language][radiosity]") {
    const auto scene = scene_of(R"(
#macro More() recursion_limit 3 normal on #end
global_settings { radiosity {
  count 200, 3000 nearest_count 10, 4 error_bound 0.5 low_error_factor 0.7
  pretrace_start 0.1 pretrace_end 0.01 minimum_reuse 0.01 maximum_reuse 0.1
  gray_threshold 0.25 brightness 1.5 adc_bailout 0.005 max_sample 2
  always_sample on media on brilliance on subsurface off
  #if (1) More() #end
} }
)");
    const rt::RadiositySettings& r = scene.global.radiosity;
    CHECK(r.count == 200);
    CHECK(r.direction_pool == 3000);
    CHECK(r.nearest_count == 10);
    CHECK(r.nearest_count_pretrace == 4);
    CHECK(r.error_bound == 0.5);
    CHECK(r.low_error_factor == 0.7);
    CHECK(r.pretrace_start == 0.1);
    CHECK(r.pretrace_end == 0.01);
    CHECK(r.minimum_reuse == 0.01);
    CHECK(r.maximum_reuse == 0.1);
    CHECK(r.gray_threshold == 0.25);
    CHECK(r.brightness == 1.5);
    CHECK(r.adc_bailout == 0.005);
    CHECK(r.max_sample == 2.0);
    CHECK(r.always_sample);
    CHECK(r.media);
    CHECK(r.brilliance);
    CHECK_FALSE(r.subsurface);
    CHECK(r.recursion_limit == 3);
    CHECK(r.normal);
    // (count's pool is at least 1600, or count.)
    CHECK(
        scene_of("global_settings { radiosity { count 2000 } }").global.radiosity.direction_pool ==
        2000);
}

TEST_CASE("radiosity's limits are POV-Ray's, refused at their place", "[language][radiosity]") {
    check_error_at("global_settings {\nradiosity { count 0 } }", "count", 2);
    check_error_at("global_settings {\nradiosity { count 100, 50 } }", "direction pool", 2);
    check_error_at("global_settings {\nradiosity { nearest_count 21 } }", "nearest_count", 2);
    check_error_at("global_settings {\nradiosity { nearest_count 5, 5 } }", "smaller", 2);
    check_error_at("global_settings {\nradiosity { recursion_limit 0 } }", "recursion_limit", 2);
    check_error_at("global_settings {\nradiosity { pretrace_start 1.5 } }", "pretrace_start", 2);
    check_error_at("global_settings {\nradiosity { pretrace_end 0 } }", "pretrace_end", 2);
    check_error_at("global_settings {\nradiosity { error_bound -1 } }", "positive", 2);
    check_error_at("global_settings {\nradiosity { brightness 0 } }", "positive", 2);
    check_error_at("global_settings {\nradiosity { gray_threshold 2 } }", "gray_threshold", 2);
    check_error_at("global_settings {\nradiosity { minimum_reuse -0.1 } }", "minimum_reuse", 2);
    check_error_at("global_settings {\nradiosity { error_bound 1, 2 } }", "one value", 2);
    check_error_at("global_settings {\nradiosity { unknown_word 1 } }", "", 2);
    check_error_at("sphere { 0, 1\nradiosity { importance 0 } }", "importance", 2);
}

TEST_CASE("radiosity's files are ignored with POV-Ray 3.7's warning", "[language][radiosity]") {
    const auto scene = scene_of("global_settings { radiosity { save_file \"a.rad\" } }");
    REQUIRE(scene.warnings.size() == 1);
    CHECK(scene.warnings[0].find("save_file is ignored") != std::string::npos);
    CHECK(scene.global.radiosity.enabled);
}

TEST_CASE("no_radiosity hides an object from radiosity's rays only", "[language][radiosity]") {
    const auto scene = scene_of("sphere { 0, 1 no_radiosity }\nsphere { 0, 1 no_radiosity off }");
    CHECK(scene.objects.at(0)->no_radiosity);
    CHECK_FALSE(scene.objects.at(1)->no_radiosity);
    CHECK(scene.warnings.empty());
    // (importance 1, the default, changes nothing; below, it is warned.)
    CHECK(scene_of("sphere { 0, 1 radiosity { importance 1 } }").warnings.empty());
    const auto thinned = scene_of("sphere { 0, 1 radiosity { importance 0.25 } }");
    REQUIRE(thinned.warnings.size() == 1);
    CHECK(thinned.warnings[0].find("importance") != std::string::npos);
}

TEST_CASE("radiosity's settings are checked together, as POV-Ray does after parsing",
          "[language][radiosity]") {
    check_error_at("global_settings {\nradiosity { pretrace_start 0.01 pretrace_end 0.5 } }",
                   "pretrace_end", 2);
    check_error_at("global_settings {\nradiosity { minimum_reuse 0.5 maximum_reuse 0.1 } }",
                   "maximum_reuse must be larger", 2);
    // One of them written: the other moves, with POV-Ray's warning.
    const auto lowered = scene_of("global_settings { radiosity { maximum_reuse 0.02 } }");
    CHECK(lowered.global.radiosity.minimum_reuse == Approx(0.01));
    REQUIRE(lowered.warnings.size() == 1);
    CHECK(lowered.warnings[0].find("minimum_reuse lowered") != std::string::npos);
    const auto raised = scene_of("global_settings { radiosity { minimum_reuse 0.15 } }");
    CHECK(raised.global.radiosity.maximum_reuse == Approx(0.3));
}

TEST_CASE("radiosity's other places read as POV-Ray 3.7 reads them", "[language][radiosity]") {
    // #default { radiosity { importance } }, an importance written twice
    // (the last counts).
    const auto scene = scene_of(
        "#default { finish { ambient 0.1 } radiosity { importance 1 } }\n"
        "sphere { 0, 1 radiosity { importance 0.5 importance 1 } }\n"
        "light_source { 0, 1 }");
    REQUIRE(scene.warnings.size() == 1);
    CHECK(scene.warnings[0].find("importance") != std::string::npos);
    CHECK(scene.lights.size() == 1);
    CHECK(
        scene_of("#default { radiosity { importance 0.5 } }").global.radiosity.default_importance ==
        0.5);
}
