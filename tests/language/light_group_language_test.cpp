// light_group as POV-Ray 3.7 reads it (Parse_Light_Group,
// Promote_Local_Lights): its own lights belong to it, each placed copy of
// a declared group is a group of its own, a group inside another knows the
// one around it, and media in a group are said to be lit by the scene's
// lights. (What the groups light is tested against POV-Ray's images:
// tests/tracer/pov_reference/lights/light_group.pov.)
#include <string>

#include <catch2/catch.hpp>

#include "language/interpreter.hpp"
#include "scene_text.hpp"

using hexant::test::scene_of;

TEST_CASE("each light_group and each copy of one is a group of the scene's", "[language]") {
    const auto scene = scene_of(R"(
light_source { <0, 9, 0> rgb 1 }
#declare G = light_group {
  light_source { <1, 2, 3> rgb 1 }
  sphere { 0, 1 }
  union { light_source { <0, 5, 0> rgb 1 } sphere { x, 1 } }
}
object { G }
object { G translate 4 * x }
light_group {
  light_source { <0, 8, 0> rgb 1 }
  object { G }
  global_lights on
}
)");
    // Three groups placed (G twice and the outer one) and the copy of G
    // inside the outer one.
    REQUIRE(scene.light_groups.size() == 4);
    REQUIRE(scene.lights.size() == 8);
    // The scene's light, and the lights in unions within a group, light
    // the whole scene (POV-Ray takes a group's direct children only).
    int global = 0;
    std::vector<int> per_group(scene.light_groups.size(), 0);
    for (const auto& light : scene.lights) {
        if (light.light_group < 0)
            ++global;
        else
            ++per_group[std::size_t(light.light_group)];
    }
    CHECK(global == 4);
    for (int n : per_group) CHECK(n == 1);
    // The copy of G inside the outer group has it as its parent; the
    // others stand alone.
    int nested = 0;
    for (const auto& g : scene.light_groups)
        if (g.parent >= 0) {
            ++nested;
            CHECK(scene.light_groups[std::size_t(g.parent)].parent == -1);
        }
    CHECK(nested == 1);
    // The declared group's record is shared, not numbered itself: each
    // object added has its own numbers.
    REQUIRE(scene.objects.size() == 3);
    CHECK(scene.objects[0]->light_group->id != scene.objects[1]->light_group->id);
    CHECK(scene.objects[2]->light_group->global_lights);
    CHECK_FALSE(scene.objects[0]->light_group->global_lights);
}

TEST_CASE("media in a light_group are said to be lit by the scene's lights", "[language]") {
    const auto scene = scene_of(R"(
light_group {
  light_source { <0, 8, 0> rgb 1 }
  sphere { 0, 1 hollow pigment { rgbt 1 } interior { media { emission 0.1 } } }
}
)");
    REQUIRE(scene.warnings.size() == 1);
    CHECK(scene.warnings[0].find("lit by the scene's lights, not by the group's") !=
          std::string::npos);
    // Without a group, no word.
    CHECK(scene_of("sphere { 0, 1 hollow pigment { rgbt 1 } interior { media { emission 0.1 } } }")
              .warnings.empty());
}
