// text { ttf "FONT" "STRING", THICKNESS, OFFSET } as the language reads it:
// the font found as includes are (then in Debian's fonts-povray), strings
// that change with clock made one text per piece of time, refusals named.
#include <filesystem>
#include <fstream>
#include <string>

#include <catch2/catch.hpp>

#include "language/interpreter.hpp"
#include "runtime/objects/shapes.hpp"
#include "tests/language/scene_text.hpp"

namespace rt = hexant::runtime;
using hexant::test::error_of;

namespace {

bool fonts_installed() {
    if (std::filesystem::exists(std::filesystem::path(HEXANT_POV_FONT_DIR) / "timrom.ttf"))
        return true;
    WARN("not run: POV-Ray's fonts are not installed (Debian: fonts-povray)");
    return false;
}

std::string message(const std::string& scene) {
    return error_of(scene).what();
}

}  // namespace

TEST_CASE("a text's glyphs are laid out when it is read", "[language][text]") {
    if (!fonts_installed()) return;
    const auto scene = hexant::language::parse_scene_text(
        "text { ttf \"timrom.ttf\" \"Hi there\", 0.25, <0.1, 0, 0> }", "t.pov", {});
    REQUIRE(scene.objects.size() == 1);
    const auto& text = std::get<rt::Text>(scene.objects[0]->shape);
    CHECK(text.string == "Hi there");
    CHECK(text.glyphs.size() == 8);  // the space is a glyph without outline
    CHECK(text.thickness.constant() == 0.25);
    // Each later glyph starts further right: the offset adds 0.1 a character.
    CHECK(text.glyphs[1].lo.x > text.glyphs[0].hi.x);
    // POV-Ray's turn of 0.001 degrees about each axis comes first.
    CHECK(scene.objects[0]->transform.steps().size() == 1);
}

TEST_CASE("a text whose string changes with clock is one text per string", "[language][text]") {
    if (!fonts_installed()) return;
    auto options = hexant::test::animation();  // frames 1 to 8, clock 0 to 1
    const auto scene = hexant::language::parse_scene_text(
        "text { ttf \"timrom.ttf\" str(frame_number, 0, 0), 0.1, 0 pigment { rgb 1 } }", "t.pov",
        options);
    REQUIRE(scene.objects.size() == 1);
    const auto* group = std::get_if<rt::Csg>(&scene.objects[0]->shape);
    REQUIRE(group != nullptr);
    REQUIRE(group->children.size() == 8);
    for (int frame = 1; frame <= 8; ++frame) {
        const double t = options.animation.clock_of_frame(frame);
        int living = 0;
        for (const auto& child : group->children)
            if (child->lifetime.contains(t)) {
                ++living;
                CHECK(std::get<rt::Text>(child->shape).string == std::to_string(frame));
            }
        CHECK(living == 1);
    }
}

TEST_CASE("a text's characters follow the scene's charset and fonts by POV-Ray's names",
          "[language][text]") {
    if (!fonts_installed()) return;
    const auto glyphs = [](const std::string& scene) {
        const auto s = hexant::language::parse_scene_text(scene, "t.pov", {});
        return std::get<rt::Text>(s.objects.back()->shape).glyphs.size();
    };
    // "\xc3\xa9" is é in UTF-8: two bytes, two spaces in ascii (POV-Ray's
    // default), one character with charset utf8.
    CHECK(glyphs("text { ttf \"timrom.ttf\" \"a\xc3\xa9\", 1, 0 }") == 3);
    CHECK(glyphs(
              "global_settings { charset utf8 } text { ttf \"timrom.ttf\" \"a\xc3\xa9\", 1, 0 }") ==
          2);
    CHECK(message("global_settings { charset sys }").find("charset 'sys' is not supported") !=
          std::string::npos);
    // A name without its extension gets ".ttf"; internal 1 is timrom.ttf.
    const auto plain =
        hexant::language::parse_scene_text("text { ttf \"timrom.ttf\" \"Ab\", 1, 0 }", "t.pov", {});
    const auto bare =
        hexant::language::parse_scene_text("text { ttf \"timrom\" \"Ab\", 1, 0 }", "t.pov", {});
    const auto internal =
        hexant::language::parse_scene_text("text { internal 1 \"Ab\", 1, 0 }", "t.pov", {});
    const auto& a = std::get<rt::Text>(plain.objects[0]->shape).glyphs;
    for (const auto* other : {&bare, &internal}) {
        const auto& b = std::get<rt::Text>((*other).objects[0]->shape).glyphs;
        REQUIRE(b.size() == a.size());
        for (std::size_t i = 0; i < a.size(); ++i) {
            CHECK(b[i].lo == a[i].lo);
            CHECK(b[i].hi == a[i].hi);
        }
    }
}

TEST_CASE("a text's refusals name what is wrong", "[language][text]") {
    CHECK(message("text { ttf \"no_such_font.ttf\" \"a\", 1, 0 }")
              .find("font file 'no_such_font.ttf' not found") != std::string::npos);
    CHECK(
        message("text { internal 7 \"a\", 1, 0 }").find("internal font 7 is out of range 0 to 3") !=
        std::string::npos);
    CHECK(message("text { \"timrom.ttf\" \"a\", 1, 0 }").find("needs its font as ttf") !=
          std::string::npos);
    CHECK(message("text { ttf \"timrom.ttf\" \"a\", 1 }")
              .find("text needs a font file, a string, a thickness and an offset") !=
          std::string::npos);
    if (!fonts_installed()) return;
    CHECK(std::string(error_of("text { ttf \"timrom.ttf\" \"a\", 1, <clock, 0, 0> }",
                               hexant::test::animation())
                          .what())
              .find("offset depends on clock") != std::string::npos);
    // A file that is not a font: FreeType's refusal, naming the file.
    const auto folder = std::filesystem::temp_directory_path() / "hexant_text_test";
    std::filesystem::create_directories(folder);
    { std::ofstream(folder / "fake.ttf") << "not a font at all"; }
    hexant::language::ParseOptions options;
    options.include_paths.push_back(folder.string());
    const auto e = error_of("text { ttf \"fake.ttf\" \"a\", 1, 0 }", options);
    CHECK(std::string(e.what()).find("fake.ttf") != std::string::npos);
}
