// Reading textures as POV-Ray does (issue 19, and a new user's probe of it):
// a second pigment { } or normal { } on an object modifies the one it has,
// colour maps may be written by directives and macros, a layered texture
// that shows what is under it is refused where it is written, a pattern
// hexant lacks in a normal is an error when the scene is checked, and
// global_settings { noise_generator } reaches the patterns after it.
#include <catch2/catch.hpp>

#include <string>

#include "language/interpreter.hpp"
#include "scene_text.hpp"

using hexant::test::error_of;
namespace rt = hexant::runtime;

namespace {

rt::SceneDescription read(const std::string& text) {
    hexant::language::ParseOptions options;
    std::ostringstream messages;
    options.messages = &messages;
    return hexant::language::parse_scene_text(text, "test.pov", options);
}

const rt::Texture& texture_of(const rt::SceneDescription& scene, std::size_t i) {
    REQUIRE(scene.objects.at(i)->texture);
    return *scene.objects[i]->texture;
}

}  // namespace

TEST_CASE("a second pigment or normal on an object modifies the first", "[language][pattern]") {
    const auto scene = read(R"(
#declare S = sphere { 0, 1 pigment { bozo color_map { [0 rgb 0] [1 rgb <1, 0, 0>] } } }
object { S pigment { scale 0.2 } }
sphere { 0, 1 normal { bumps 1 scale 0.2 } normal { bump_size 2 } }
)");
    const rt::Pigment& p = texture_of(scene, 0).pigment;
    CHECK(p.pattern == rt::Pigment::Pattern::Patterned);
    CHECK(p.patterned.kind->name == "bozo");
    CHECK(p.colour_map.entries.size() == 2);
    CHECK(!p.transform.empty());
    const auto& n = texture_of(scene, 1).normal;
    REQUIRE(n);
    CHECK(n->patterned.kind->name == "bumps");
    CHECK(n->amount.constant() == 2.0);
    CHECK(!n->transform.empty());
}

TEST_CASE("directives and macros write a colour map's entries", "[language][pattern]") {
    const auto scene = read(R"(
#macro E(T, C) [T rgb C] #end
sphere { 0, 1 pigment { gradient x color_map { #for (I, 0, 4) [I / 4 rgb I / 4] #end } } }
sphere { 0, 1 pigment { gradient y color_map { E(0, <1, 0, 0>) #if (1) E(1, <0, 0, 1>) #end } } }
)");
    CHECK(texture_of(scene, 0).pigment.colour_map.entries.size() == 5);
    CHECK(texture_of(scene, 0).pigment.colour_map.entries[3].value.constant() == 0.75);
    REQUIRE(texture_of(scene, 1).pigment.colour_map.entries.size() == 2);
    CHECK(texture_of(scene, 1).pigment.colour_map.entries[1].colour.c[2].constant() == 1.0);
}

TEST_CASE("what hexant cannot show yet is an error where it is written", "[language][pattern]") {
    // A second texture is a layer on top in POV-Ray: refused when the lower
    // one would show through; an opaque one is the same image as a
    // replacement.
    const auto layered = error_of("sphere { 0, 1 texture { pigment { bozo } } texture { pigment { rgbt <1, 1, 1, 0.5> } } }\n");
    CHECK(layered.formatted().find("test.pov:1:") != std::string::npos);
    CHECK(layered.formatted().find("layered") != std::string::npos);
    hexant::test::reads("sphere { 0, 1 texture { pigment { bozo } } texture { pigment { rgb 1 } } }\n");
    // A normal pattern hexant lacks: at check, not only at render.
    const auto facets = error_of("sphere { 0, 1 normal { facets } }\n");
    CHECK(facets.formatted().find("facets") != std::string::npos);
}

TEST_CASE("global_settings { noise_generator } reaches the patterns after it", "[language][pattern]") {
    const auto scene = read("global_settings { noise_generator 3 }\nsphere { 0, 1 pigment { bozo } }\n"
                            "sphere { 0, 1 pigment { bozo noise_generator 1 } }\n");
    CHECK(texture_of(scene, 0).pigment.patterned.noise_generator == 3);
    CHECK(texture_of(scene, 1).pigment.patterned.noise_generator == 1);
}
