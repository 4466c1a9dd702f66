// Reading photon mapping as POV-Ray 3.7's parser reads it: the global
// photons { } block (its defaults, every setting, its limits and messages),
// an object's and a light's photons { }, CheckPassThru's rule, a group's
// flags reaching its members, and a block's items given by a macro
// (glass.inc's `interior { I_Glass_Exp(2) }`).
#include <string>

#include <catch2/catch.hpp>

#include "language/interpreter.hpp"
#include "runtime/objects/object_factory.hpp"
#include "scene_text.hpp"

using hexant::test::check_error_at;
using hexant::test::scene_of;
namespace rt = hexant::runtime;

TEST_CASE("photons' defaults are POV-Ray 3.7's", "[language][photons]") {
    CHECK_FALSE(scene_of("sphere { 0, 1 }").global.photons.enabled);
    const auto scene = scene_of("global_settings { photons { spacing 0.02 } }");
    const rt::PhotonSettings& p = scene.global.photons;
    CHECK(p.enabled);
    CHECK(p.spacing == 0.02);
    CHECK(p.count == 0);
    CHECK(p.gather_min == 20);
    CHECK(p.gather_max == 100);
    CHECK(p.jitter == 0.4);
    CHECK(p.autostop == 0.5);
    CHECK(p.expand_tolerance == 0.2);
    CHECK(p.expand_min == 35);
    CHECK(p.max_trace_level == -1);
    CHECK(p.adc_bailout == -1.0);
    CHECK(p.radius == -1.0);
    CHECK(p.radius_factor == 1.0);
    CHECK(scene.warnings.empty());
}

TEST_CASE("photons' settings are read, a macro's too", "[language][photons]") {
    const auto scene = scene_of(R"(
#macro Gather() gather 10, 50 #end
global_settings { photons {
  count 20000 jitter 0.2 autostop 0.3 max_trace_level 7 adc_bailout 0.02
  expand_thresholds 0.4, 20 radius 0.5, 2 Gather()
} }
)");
    const rt::PhotonSettings& p = scene.global.photons;
    CHECK(p.count == 20000);
    CHECK(p.jitter == 0.2);
    CHECK(p.autostop == 0.3);
    CHECK(p.max_trace_level == 7);
    CHECK(p.adc_bailout == 0.02);
    CHECK(p.expand_tolerance == 0.4);
    CHECK(p.expand_min == 20);
    CHECK(p.radius == 0.5);
    CHECK(p.radius_factor == 2.0);
    CHECK(p.gather_min == 10);
    CHECK(p.gather_max == 50);
    // gather's maximum 0: no photon maps (POV-Ray's rule).
    CHECK_FALSE(scene_of("global_settings { photons { gather 0, 0 } }").global.photons.enabled);
}

TEST_CASE("photons' settings are checked as POV-Ray checks them", "[language][photons]") {
    check_error_at("global_settings {\nphotons { gather 50, 10 } }", "min_gather_count", 2);
    check_error_at("global_settings {\nphotons { gather -1, 10 } }", "cannot be negative", 2);
    check_error_at("global_settings {\nphotons { spacing 0 } }", "spacing", 2);
    check_error_at("global_settings {\nphotons { gather 10 } }", "MIN, MAX", 2);
    check_error_at("global_settings {\nphotons { media -1 } }", "non-negative", 2);
    check_error_at("global_settings {\nphotons { media 10, 0 } }", "greater than zero", 2);
    check_error_at("global_settings {\nphotons { jitter 1, 2 } }", "at most 1 value", 2);
    check_error_at("sphere { 0, 1\nphotons { refraction } }", "on or off", 2);
    // (Negative thresholds are set to 0 with POV-Ray's warning.)
    const auto zeroed = scene_of("global_settings { photons { expand_thresholds -1, 5 } }");
    CHECK(zeroed.global.photons.expand_tolerance == 0.0);
    REQUIRE(zeroed.warnings.size() == 1);
    CHECK(zeroed.warnings[0].find("expand_thresholds") != std::string::npos);
}

TEST_CASE("what photons hexant does not make is warned at its place", "[language][photons]") {
    // Photon files, a light's area_light photons, split_union (media
    // photons are made: no warning).
    const auto scene = scene_of(
        "global_settings { photons { spacing 0.1 media 100, 2 save_file \"a.ph\" } }\n"
        "light_source { 0, 1 photons { area_light } }\n"
        "union { sphere { 0, 1 } sphere { x, 1 } photons { split_union on } }");
    REQUIRE(scene.warnings.size() == 3);
    CHECK(scene.warnings[0].find("save_file is ignored") != std::string::npos);
    CHECK(scene.warnings[1].find("area_light") != std::string::npos);
    CHECK(scene.warnings[2].find("split_union") != std::string::npos);
    CHECK(scene.global.photons.media_max_steps == 100);
    CHECK(scene.global.photons.media_spacing_factor == 2.0);
}

TEST_CASE("an object's and a light's photons are read", "[language][photons]") {
    const auto scene = scene_of(
        "sphere { 0, 1 photons { target 0.5 refraction on reflection off collect off } }\n"
        "sphere { 0, 1 photons { pass_through } }\n"
        "sphere { 0, 1 photons { target } }\n"
        "light_source { 0, 1 photons { refraction off reflection on } }");
    REQUIRE(scene.objects.size() == 3);
    const rt::ObjectPhotons& a = scene.objects[0]->photons;
    CHECK(a.target == 0.5);
    CHECK(a.refraction == 1);
    CHECK(a.reflection == -1);
    CHECK_FALSE(a.collect);
    CHECK_FALSE(a.pass_through);
    CHECK(scene.objects[1]->photons.pass_through);
    CHECK(scene.objects[1]->photons.target == 0.0);
    CHECK(scene.objects[2]->photons.target == 1.0);  // Allow_Float's 1
    CHECK(scene.objects[2]->photons.refraction == 0);
    REQUIRE(scene.lights.size() == 1);
    CHECK(scene.lights[0].photons.refraction == -1);
    CHECK(scene.lights[0].photons.reflection == 1);
    CHECK(scene.warnings.empty());
}

TEST_CASE("a refracting target cannot pass photons through (CheckPassThru)",
          "[language][photons]") {
    // The word written last decides, with POV-Ray's warnings.
    const auto a = scene_of("sphere { 0, 1 photons { target pass_through } }");
    CHECK(a.objects[0]->photons.refraction == -1);
    CHECK(a.objects[0]->photons.pass_through);
    REQUIRE(a.warnings.size() == 1);
    CHECK(a.warnings[0].find("refraction turned off") != std::string::npos);
    const auto b = scene_of("sphere { 0, 1 photons { refraction on pass_through target } }");
    CHECK(b.objects[0]->photons.refraction == 1);
    CHECK_FALSE(b.objects[0]->photons.pass_through);
    REQUIRE(b.warnings.size() == 1);
    CHECK(b.warnings[0].find("pass_through turned off") != std::string::npos);
    // refraction off first: no conflict.
    CHECK(scene_of("sphere { 0, 1 photons { refraction off target pass_through } }")
              .warnings.empty());
}

TEST_CASE("a group's photons reach its members, which share its target", "[language][photons]") {
    // POV-Ray's Post_Process promotes a CSG's flags to its children; a
    // photon shot at the union may meet any member first.
    const auto scene = scene_of(
        "union { sphere { 0, 1 photons { reflection off } } sphere { x, 1 }\n"
        "  photons { target 2 refraction on reflection on } }\n"
        "sphere { 0, 1 photons { target } }");
    std::vector<rt::IntelligentObjectPtr> objects;
    for (const auto& record : scene.objects)
        rt::make_intelligent_objects(*record, scene.default_texture, objects);
    REQUIRE(objects.size() == 3);
    const rt::ObjectFlags& a = objects[0]->flags();
    const rt::ObjectFlags& b = objects[1]->flags();
    const rt::ObjectFlags& c = objects[2]->flags();
    CHECK(a.photon_target == 2.0f);
    CHECK(b.photon_target == 2.0f);
    CHECK(a.photon_group == b.photon_group);
    CHECK(a.photon_reflection == 1);  // the group's on over the member's off
    CHECK(b.photon_refraction == 1);
    CHECK(c.photon_target == 1.0f);
    CHECK(c.photon_group != a.photon_group);
}

TEST_CASE("a block's items may come from a macro, as glass.inc gives them", "[language][photons]") {
    // interior { I_Glass_Exp(2) }: the macro's body is `ior 1.5
    // fade_distance 2 fade_power 1001`, items of the interior (not its base).
    const auto scene = scene_of(R"(
#macro I_Exp(Distance) ior 1.5 fade_distance Distance fade_power 1001 #end
#macro Shine() phong 0.5 #end
#declare Glass = interior { ior 1.3 }
#macro Named() Glass #end
sphere { 0, 1 interior { I_Exp(2) fade_color rgb 0.5 } finish { Shine() } }
sphere { 0, 1 interior { Named() caustics 1 } }
)");
    REQUIRE(scene.objects.size() == 2);
    REQUIRE(scene.objects[0]->interior);
    CHECK(scene.objects[0]->interior->ior.constant() == 1.5);
    CHECK(scene.objects[0]->interior->fade_distance.constant() == 2.0);
    REQUIRE(scene.objects[0]->texture);
    // (A macro that gives a declared interior is still the base.)
    REQUIRE(scene.objects[1]->interior);
    CHECK(scene.objects[1]->interior->ior.constant() == 1.3);
}
