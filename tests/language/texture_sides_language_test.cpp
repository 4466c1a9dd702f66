// Reading tiles { } and interior_texture { } as POV-Ray 3.7 reads them
// (Parse_Tiles, Parse_Object_Mods): tiles is a checker texture whose first
// tile sits at 1 and tile2 at 0, each tile's textures layered, only
// transforms after it; an interior texture is layered like a texture, moves
// with the object, and needs the object's own texture.
#include <string>

#include <catch2/catch.hpp>

#include "language/interpreter.hpp"
#include "scene_text.hpp"

using hexant::test::check_error_at;
using hexant::test::scene_of;
namespace rt = hexant::runtime;

namespace {

// The colour of a plain texture's solid pigment, red channel.
double red_of(const rt::Texture& t) {
    return t.pigment.colours.at(0).c[0].constant();
}

}  // namespace

TEST_CASE("tiles is a checker of two textures, the first tile at 1", "[language][pattern]") {
    const auto scene = scene_of(R"(
#declare B = texture { pigment { rgb 0.5 } }
sphere { 0, 1 texture {
  tiles { texture { pigment { rgb 0.1 } } texture { pigment { rgbt <0.2, 0, 0, 0.5> } }
          tile2 texture { B } }
  scale 2 } }
)");
    const rt::Texture& t = *scene.objects.at(0)->texture;
    REQUIRE(t.patterned->kind);
    CHECK(t.patterned->kind->name == "checker");
    REQUIRE(t.texture_map.size() == 2);
    // (POV-Ray's Parse_Tiles: "first tile is 1, 2nd tile is 0".)
    CHECK(t.texture_map[0].value.constant() == 0.0);
    CHECK(red_of(*t.texture_map[0].texture) == 0.5);
    CHECK(t.texture_map[1].value.constant() == 1.0);
    // The first tile's two textures layered, the later on top.
    const rt::Texture& first = *t.texture_map[1].texture;
    CHECK(red_of(first) == 0.2);
    REQUIRE(first.below.size() == 1);
    CHECK(red_of(first.below[0]) == 0.1);
    // The scale after the block moves the pattern.
    CHECK(!t.transform.empty());
}

TEST_CASE("tiles reads in a texture_map's entry", "[language][pattern]") {
    const auto scene = scene_of(R"(
sphere { 0, 1 texture { gradient y texture_map {
  [0 pigment { rgb 1 }]
  [1 tiles { texture { pigment { rgb 0.3 } } tile2 texture { pigment { rgb 0.7 } } } scale 0.5]
} } }
)");
    const rt::Texture& t = *scene.objects.at(0)->texture;
    REQUIRE(t.texture_map.size() == 2);
    const rt::Texture& entry = *t.texture_map[1].texture;
    REQUIRE(entry.texture_map.size() == 2);
    CHECK(red_of(*entry.texture_map[1].texture) == 0.3);
}

TEST_CASE("what POV-Ray refuses in tiles is an error where it is written", "[language][pattern]") {
    check_error_at("sphere { 0, 1\n texture { tiles { texture { pigment { rgb 1 } } } } }\n",
                   "expected tile2", 2);
    check_error_at("sphere { 0, 1\n texture { tiles { tile2 texture { pigment { rgb 1 } } } } }\n",
                   "first tile's texture", 2);
    check_error_at("sphere { 0, 1 texture {\n tiles { texture { pigment { rgb 1 } } tile2 } } }\n",
                   "second tile's texture", 2);
    // Nothing but transforms after it, and nothing before it (POV-Ray's
    // Parse_Texture: no tiles after a pigment, normal, finish or a
    // declared texture).
    check_error_at(
        "sphere { 0, 1 texture {\n tiles { texture { pigment { rgb 1 } } tile2 texture "
        "{ pigment { rgb 0 } } }\n pigment { rgb 1 } } }\n",
        "", 3);
    check_error_at(
        "#declare T = texture { pigment { rgb 1 } }\nsphere { 0, 1 texture { T\n tiles { "
        "texture { T } tile2 texture { T } } } }\n",
        "", 3);
}

TEST_CASE("an interior texture is layered, moves with its object, needs a texture",
          "[language][pattern]") {
    const auto scene = scene_of(R"(
sphere { 0, 1 pigment { rgb 1 }
  interior_texture { pigment { rgb 0.25 } }
  interior_texture { pigment { rgbt <0.75, 0, 0, 0.5> } }
  translate x }
union { sphere { 0, 1 } sphere { x, 1 } texture { pigment { rgb 1 } }
  interior_texture { pigment { checker rgb 0 rgb 1 } } }
sphere { 0, 1 }
)");
    const auto& inside = scene.objects.at(0)->interior_texture;
    REQUIRE(inside);
    CHECK(red_of(*inside) == 0.75);
    REQUIRE(inside->below.size() == 1);
    CHECK(red_of(inside->below[0]) == 0.25);
    // (The translate moves it as it moves the texture: POV-Ray's
    // Transform_Textures on both.)
    CHECK(!inside->transform.empty());
    CHECK(scene.objects.at(1)->interior_texture);
    CHECK_FALSE(scene.objects.at(2)->interior_texture);
    // POV-Ray: "Interior texture requires an exterior texture."
    check_error_at("sphere { 0, 1\n interior_texture { pigment { rgb 1 } } }\n", "own texture", 1);
}
