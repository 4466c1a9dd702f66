// TrueType fonts for the text object: errors naming the file, POV-Ray's
// string conversion, glyph boxes and metrics against FreeType's own
// answers, the layout (ProcessNewTTF) against the same formulas applied by
// hand to FreeType's metrics, and the boxes POV-Ray 3.7 itself reports for
// text objects (min_extent / max_extent, recorded below). POV-Ray's fonts
// come from HEXANT_POV_FONT_DIR (environment or compile definition); when
// missing, those tests say so and do not run.
#include <ft2build.h>
#include FT_FREETYPE_H
#include FT_ADVANCES_H
#include FT_OUTLINE_H

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "runtime/objects/text/text_geometry.hpp"
#include "runtime/objects/text/true_type_font.hpp"

using namespace hexant::runtime::objects;
using hexant::runtime::geometry::TextGeometry;

namespace {

std::filesystem::path font_dir() {
    if (const char* env = std::getenv("HEXANT_POV_FONT_DIR")) return env;
#ifdef HEXANT_POV_FONT_DIR
    return HEXANT_POV_FONT_DIR;
#else
    return "/usr/share/povray-3.7/include";
#endif
}

// Catch2 v2 has no SKIP: warn and leave (as tests/app/full_disk_test.cpp).
#define REQUIRE_POV_FONTS(dir)                                                                \
    do {                                                                                      \
        if (!std::filesystem::exists((dir) / "timrom.ttf")) {                                 \
            WARN("not run: POV-Ray's fonts not found in "                                     \
                 << (dir).string() << " (set HEXANT_POV_FONT_DIR; Debian: povray-includes)"); \
            return;                                                                           \
        }                                                                                     \
    } while (0)

struct FreeType {
    FT_Library library = nullptr;
    FT_Face face = nullptr;
    explicit FreeType(const std::filesystem::path& path) {
        REQUIRE(FT_Init_FreeType(&library) == 0);
        REQUIRE(FT_New_Face(library, path.c_str(), 0, &face) == 0);
    }
    ~FreeType() {
        FT_Done_Face(face);
        FT_Done_FreeType(library);
    }
};

// POV-Ray's Compute_Rotation_Transform for <a, a, a> degrees (row vectors:
// about x, then y, then z).
glm::dvec3 pov_rotate(glm::dvec3 p, double degrees) {
    const double r = degrees * 3.14159265358979323846 / 180.0, c = std::cos(r), s = std::sin(r);
    p = {p.x, p.y * c - p.z * s, p.y * s + p.z * c};
    p = {p.x * c + p.z * s, p.y, -p.x * s + p.z * c};
    p = {p.x * c - p.y * s, p.x * s + p.y * c, p.z};
    return p;
}

// The box POV-Ray 3.7 reports for a text object: the union of its
// characters' boxes (each the glyph header's box, Compute_BBox in
// truetype.cpp 3142-3170, z from -1e-6 to depth + 1e-6, moved to its place;
// a space is a point), then the parser's rotation by 0.001 degrees about
// each axis (parse.cpp 6195-6198), which CSG::Rotate (csg.cpp 508-514)
// applies to the union's box as a whole: the hull of its rotated corners.
struct Extents {
    glm::dvec3 lo{1e300}, hi{-1e300};
};

Extents pov_extents(const TrueTypeFont& font, const TextGeometry& text, TextEncoding encoding) {
    Extents u;
    const double f = 1.0 / font.units_per_em();
    for (const auto& glyph : text.glyphs) {
        const FontGlyph g = font.glyph(static_cast<char16_t>(glyph.code), encoding);
        const glm::dvec3 place(glyph.translation, 0.0);
        u.lo = glm::min(u.lo, place + glm::dvec3(g.x_min * f, g.y_min * f, -1e-6));
        u.hi = glm::max(u.hi, place + glm::dvec3(g.x_max * f, g.y_max * f, text.thickness + 1e-6));
    }
    Extents e;
    for (int i = 0; i < 8; ++i) {
        const glm::dvec3 corner{(i & 1) ? u.hi.x : u.lo.x, (i & 2) ? u.hi.y : u.lo.y,
                                (i & 4) ? u.hi.z : u.lo.z};
        const glm::dvec3 r = pov_rotate(corner, 0.001);
        e.lo = glm::min(e.lo, r);
        e.hi = glm::max(e.hi, r);
    }
    return e;
}

// POV-Ray keeps boxes in single precision and prints 7 decimals here.
void check_extents(const Extents& e, glm::dvec3 pov_min, glm::dvec3 pov_max) {
    for (int k = 0; k < 3; ++k) {
        INFO("axis " << k << " ours " << e.lo[k] << " .. " << e.hi[k] << " POV-Ray " << pov_min[k]
                     << " .. " << pov_max[k]);
        CHECK(std::fabs(e.lo[k] - pov_min[k]) < 1.5e-6);
        CHECK(std::fabs(e.hi[k] - pov_max[k]) < 1.5e-6);
    }
}

}  // namespace

TEST_CASE("font: errors name the file", "[runtime][font]") {
    const std::filesystem::path missing = "/nonexistent/hexant/no_such_font.ttf";
    try {
        (void)TrueTypeFont::load(missing);
        FAIL("no error for a missing font");
    } catch (const FontError& e) {
        const std::string what = e.what();
        CHECK(what.find("no_such_font.ttf") != std::string::npos);
        CHECK(what.find("not found") != std::string::npos);
    }
    const std::filesystem::path junk =
        std::filesystem::temp_directory_path() / "hexant_font_test_not_a_font.ttf";
    {
        std::ofstream out(junk);
        out << "this is not a font\n";
    }
    try {
        (void)TrueTypeFont::load(junk);
        FAIL("no error for a text file");
    } catch (const FontError& e) {
        CHECK(std::string(e.what()).find("hexant_font_test_not_a_font.ttf") != std::string::npos);
    }
    std::filesystem::remove(junk);
}

TEST_CASE("font: POV-Ray's string conversion", "[runtime][font]") {
    // ascii (the default): every byte from 0x80 up becomes a space.
    CHECK(pov_text_to_ucs2("caf\xC3\xA9!", TextEncoding::ascii) == u"caf  !");
    // utf8: decoded; beyond U+FFFF: U+FFFD; cut-off sequence ends the text.
    CHECK(pov_text_to_ucs2("caf\xC3\xA9!", TextEncoding::utf8) == u"caf\u00E9!");
    CHECK(pov_text_to_ucs2("\xE2\x82\xAC", TextEncoding::utf8) == u"\u20AC");
    CHECK(pov_text_to_ucs2("a\xF0\x9F\x98\x80z", TextEncoding::utf8) == u"a\uFFFDz");
    CHECK(pov_text_to_ucs2("ab\xE2\x82", TextEncoding::utf8) == u"ab");
    // A C string: NUL ends it.
    CHECK(pov_text_to_ucs2(std::string("ab\0cd", 5), TextEncoding::ascii) == u"ab");
    CHECK(pov_text_to_ucs2("", TextEncoding::utf8).empty());
}

TEST_CASE("font: glyphs and metrics against FreeType", "[runtime][font]") {
    const std::filesystem::path dir = font_dir();
    REQUIRE_POV_FONTS(dir);
    for (const char* name : {"timrom.ttf", "cyrvetic.ttf", "crystal.ttf", "povlogo.ttf"}) {
        INFO(name);
        const auto font = TrueTypeFont::load(dir / name);
        FreeType ft(dir / name);
        // ascii: POV-Ray prefers the Macintosh map (platform 1), as FreeType here.
        REQUIRE(FT_Select_Charmap(ft.face, FT_ENCODING_APPLE_ROMAN) == 0);
        CHECK(font->units_per_em() == ft.face->units_per_EM);
        CHECK(font->glyph_count() == unsigned(ft.face->num_glyphs));
        const std::u16string codes = u"AVIl1Pg&o";
        for (const char16_t code : codes) {
            INFO("code " << int(code));
            const unsigned index = font->glyph_index(code, TextEncoding::ascii);
            CHECK(index == FT_Get_Char_Index(ft.face, code));
            if (index == 0) continue;
            const FontGlyph g = font->glyph(code, TextEncoding::ascii);
            REQUIRE(FT_Load_Glyph(ft.face, index, FT_LOAD_NO_SCALE | FT_LOAD_NO_HINTING) == 0);
            FT_BBox cbox;
            FT_Outline_Get_CBox(&ft.face->glyph->outline, &cbox);
            // The header box of these fonts is the points' box.
            CHECK(g.x_min == cbox.xMin);
            CHECK(g.x_max == cbox.xMax);
            CHECK(g.y_min == cbox.yMin);
            CHECK(g.y_max == cbox.yMax);
            FT_Fixed advance = 0;
            REQUIRE(FT_Get_Advance(ft.face, index, FT_LOAD_NO_SCALE, &advance) == 0);
            CHECK(g.advance_width == advance);
            // hmtx's lsb is xMin in these fonts (FreeType reports the box's xMin).
            CHECK(g.left_side_bearing == ft.face->glyph->metrics.horiBearingX);
            std::size_t points = 0;
            for (const auto& contour : g.contours) {
                points += contour.size();
                for (const auto& q : contour) {
                    CHECK(q.p.x * font->units_per_em() >= g.x_min - 1e-9);
                    CHECK(q.p.x * font->units_per_em() <= g.x_max + 1e-9);
                    CHECK(q.p.y * font->units_per_em() >= g.y_min - 1e-9);
                    CHECK(q.p.y * font->units_per_em() <= g.y_max + 1e-9);
                }
            }
            CHECK(points == std::size_t(ft.face->glyph->outline.n_points));
            CHECK(g.contours.size() == std::size_t(ft.face->glyph->outline.n_contours));
        }
    }
    // "I" in timrom: the laid-out glyph's box is its header box in em units,
    // starting at x = 0 (first character: moved by -xMin).
    const auto timrom = TrueTypeFont::load(dir / "timrom.ttf");
    const FontGlyph i_glyph = timrom->glyph(u'I', TextEncoding::ascii);
    const TextGeometry i_text = lay_out_text(*timrom, std::string("I"), 1.0, {});
    REQUIRE(i_text.glyphs.size() == 1);
    const double f = 1.0 / timrom->units_per_em();
    CHECK(i_text.glyphs[0].lo.x == 0.0);
    CHECK(i_text.glyphs[0].hi.x == Approx((i_glyph.x_max - i_glyph.x_min) * f).epsilon(1e-15));
    CHECK(i_text.glyphs[0].lo.y == Approx(i_glyph.y_min * f).margin(1e-15));
    CHECK(i_text.glyphs[0].hi.y == Approx(i_glyph.y_max * f).epsilon(1e-15));
    // The space: no outline, xMin 0, its advance.
    const FontGlyph space = timrom->glyph(u' ', TextEncoding::ascii);
    CHECK(space.contours.empty());
    CHECK(space.x_min == 0);
    CHECK(space.advance_width > 0);
}

TEST_CASE("font: layout by POV-Ray's formulas on FreeType's metrics", "[runtime][font]") {
    const std::filesystem::path dir = font_dir();
    REQUIRE_POV_FONTS(dir);
    const auto font = TrueTypeFont::load(dir / "timrom.ttf");
    FreeType ft(dir / "timrom.ttf");
    const double funit = 1.0 / ft.face->units_per_EM;
    // Kerning: POV-Ray's reading of 'kern' agrees with FreeType's here.
    const unsigned a = FT_Get_Char_Index(ft.face, 'A'), v = FT_Get_Char_Index(ft.face, 'V');
    FT_Vector kern_av;
    REQUIRE(FT_Get_Kerning(ft.face, a, v, FT_KERNING_UNSCALED, &kern_av) == 0);
    CHECK(kern_av.x < 0);  // "AV" is kerned in timrom
    CHECK(font->kerning(a, v) == glm::ivec2(kern_av.x, 0));

    for (const std::string word : {"AVATAR", "To", "Wave", "Hexant"}) {
        INFO(word);
        const glm::dvec3 offset = word == "Wave" ? glm::dvec3(0.1, 0.05, 0.3) : glm::dvec3(0.0);
        const TextGeometry text = lay_out_text(*font, word, 1.0, offset);
        REQUIRE(text.glyphs.size() == word.size());
        // ProcessNewTTF by hand: first glyph at -xMin, pen advance - lsb;
        // then glyph at pen + lsb - xMin + kern, pen += advance + kern;
        // pen += offset after every character (offset.z unused).
        glm::dvec2 pen(0.0);
        unsigned last = 0;
        for (std::size_t i = 0; i < word.size(); ++i) {
            const unsigned index = FT_Get_Char_Index(ft.face, word[i]);
            REQUIRE(FT_Load_Glyph(ft.face, index, FT_LOAD_NO_SCALE | FT_LOAD_NO_HINTING) == 0);
            FT_BBox cbox;
            FT_Outline_Get_CBox(&ft.face->glyph->outline, &cbox);
            FT_Fixed advance = 0;
            REQUIRE(FT_Get_Advance(ft.face, index, FT_LOAD_NO_SCALE, &advance) == 0);
            const long lsb = ft.face->glyph->metrics.horiBearingX, x_min = cbox.xMin;
            glm::dvec2 place;
            if (i == 0) {
                place = {-x_min * funit, 0.0};
                pen.x = (advance - lsb) * funit;
            } else {
                FT_Vector kern;
                REQUIRE(FT_Get_Kerning(ft.face, last, index, FT_KERNING_UNSCALED, &kern) == 0);
                place = {pen.x + double(lsb - x_min + kern.x) * funit, pen.y};
                pen.x += (advance + kern.x) * funit;
            }
            pen += glm::dvec2(offset);
            last = index;
            INFO("character " << i);
            CHECK(text.glyphs[i].translation.x == Approx(place.x).margin(1e-15));
            CHECK(text.glyphs[i].translation.y == Approx(place.y).margin(1e-15));
            CHECK(text.glyphs[i].glyph_index == index);
        }
    }
}

TEST_CASE("font: the boxes POV-Ray 3.7 reports", "[runtime][font]") {
    const std::filesystem::path dir = font_dir();
    REQUIRE_POV_FONTS(dir);
    // Printed by POV-Ray 3.7.0.10 (Debian) for `#declare T = text { ttf F S,
    // thickness, offset }` with #debug vstr(3, min_extent(T), " ", 0, 7) and
    // the same for max_extent: POV-Ray's own layout and glyph boxes, plus its
    // 0.001 degree rotation (reproduced in pov_extents).
    struct Case {
        const char* font;
        std::u16string codes;
        double thickness;
        glm::dvec3 offset;
        glm::dvec3 pov_min, pov_max;
    };
    const Case cases[] = {
        {"timrom.ttf",
         u"AVATAR",
         1.0,
         {},
         {-0.0000121, -0.0160175, -0.0000671},
         {3.7740176, 0.6960658, 1.0000132}},
        {"timrom.ttf",
         u"To",
         0.5,
         {},
         {-0.0000119, -0.0100087, -0.0000188},
         {1.0120088, 0.6800177, 0.5000129}},
        {"timrom.ttf",
         u"I",
         1.0,
         {},
         {-0.0000119, -0.0000175, -0.0000062},
         {0.2960175, 0.6800051, 1.0000129}},
        {"timrom.ttf",
         u"l",
         1.0,
         {},
         {-0.0000121, -0.0000175, -0.0000051},
         {0.2330174, 0.6960040, 1.0000131}},
        {"cyrvetic.ttf",
         u"Hexant 3.7",
         0.25,
         {0.1, 0.05, 0.3},
         {-0.0000198, -0.0000044, -0.0000981},
         {5.5610046, 1.1350970, 0.2500208}},
        {"crystal.ttf",
         u"Wave",
         2.0,
         {},
         {-0.0000120, -0.0078474, -0.0000354},
         {1.9639022, 0.6889991, 2.0000129}},
        {"povlogo.ttf",
         u"P",
         1.0,
         {},
         {-0.0000175, 0.0019357, -0.0000127},
         {0.6699393, 1.0019648, 1.0000185}},
        {"timrom.ttf",
         u"AV",
         -1.0,
         {},
         {-0.0000296, -0.0160000, -1.0000216},
         {1.2780004, 0.6960397, 0.0000111}},
        {"timrom.ttf",
         u"A V",
         0.0,
         {},
         {-0.0000121, -0.0160000, -0.0000313},
         {1.7190002, 0.6960300, 0.0000131}},
        // "caf\u00e9 \u00c5" under the default charset (ascii): POV-Ray looks
        // the codes up in the Macintosh map first (0xE9 is 'E' grave there).
        {"timrom.ttf",
         u"caf\u00E9 \u00C5",
         1.0,
         {},
         {-0.0000121, -0.0100175, -0.0000441},
         {2.4610176, 0.6960429, 1.0000132}},
        {"timrom.ttf",
         u"y\u00E9",
         1.0,
         {},
         {-0.0000108, -0.2120174, -0.0000225},
         {1.0200212, 0.6180178, 1.0000118}},
    };
    for (const Case& c : cases) {
        INFO(c.font << " case of " << c.codes.size() << " characters, thickness " << c.thickness);
        const auto font = TrueTypeFont::load(dir / c.font);
        const TextGeometry text =
            lay_out_text(*font, std::u16string_view(c.codes), c.thickness, c.offset);
        check_extents(pov_extents(*font, text, TextEncoding::ascii), c.pov_min, c.pov_max);
    }
}

TEST_CASE("font: empty and blank strings", "[runtime][font]") {
    const std::filesystem::path dir = font_dir();
    REQUIRE_POV_FONTS(dir);
    const auto font = TrueTypeFont::load(dir / "timrom.ttf");
    const TextGeometry empty = lay_out_text(*font, std::string(), 1.0, {});
    CHECK(empty.glyphs.empty());
    const TextGeometry blank = lay_out_text(*font, std::string("   "), 1.0, {});
    CHECK(blank.glyphs.size() == 3);
    for (const auto& g : blank.glyphs) CHECK(g.segments.empty());
    CHECK(object_bounds(blank).is_nowhere());
    // Non-ASCII bytes under ascii: spaces (and the layout advances by them).
    const TextGeometry replaced = lay_out_text(*font, std::string("a\xC3\xA9"), 1.0, {});
    REQUIRE(replaced.glyphs.size() == 3);
    CHECK(replaced.glyphs[1].segments.empty());
    CHECK(replaced.glyphs[2].segments.empty());
}

namespace {

std::uint32_t read_u32(const std::string& d, std::size_t at) {
    return std::uint32_t(std::uint8_t(d[at])) << 24 | std::uint32_t(std::uint8_t(d[at + 1])) << 16 |
           std::uint32_t(std::uint8_t(d[at + 2])) << 8 | std::uint32_t(std::uint8_t(d[at + 3]));
}
unsigned read_u16(const std::string& d, std::size_t at) {
    return unsigned(std::uint8_t(d[at])) << 8 | unsigned(std::uint8_t(d[at + 1]));
}
void write_u16(std::string& d, std::size_t at, unsigned v) {
    d[at] = char((v >> 8) & 0xFF);
    d[at + 1] = char(v & 0xFF);
}

// A copy of `font` whose outlined glyphs (outlined[k]) are rewritten in
// place as composites of one component each, glyph target(k, outlined)
// (flags: word arguments, x and y offsets 0), as a hostile font file would
// be (issue 45). Returns its path.
template <class Target>
std::filesystem::path composite_font(const std::filesystem::path& font, const std::string& name,
                                     Target target) {
    std::ifstream in(font, std::ios::binary);
    std::string d((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::size_t head = 0, maxp = 0, loca = 0, glyf = 0;
    for (unsigned i = 0; i < read_u16(d, 4); ++i) {
        const std::size_t at = 12 + 16 * i;
        const std::string tag = d.substr(at, 4);
        const std::size_t offset = read_u32(d, at + 8);
        if (tag == "head") head = offset;
        if (tag == "maxp") maxp = offset;
        if (tag == "loca") loca = offset;
        if (tag == "glyf") glyf = offset;
    }
    REQUIRE((head && maxp && loca && glyf));
    const bool long_offsets = read_u16(d, head + 50) != 0;
    const unsigned glyphs = read_u16(d, maxp + 4);
    const auto offset_of = [&](unsigned g) -> std::size_t {
        return long_offsets ? read_u32(d, loca + 4 * g)
                            : 2 * std::size_t(read_u16(d, loca + 2 * g));
    };
    std::vector<unsigned> outlined;  // glyphs with contours and room for a component
    for (unsigned g = 0; g < glyphs; ++g) {
        const std::size_t at = glyf + offset_of(g), end = glyf + offset_of(g + 1);
        if (end >= at + 18 && std::int16_t(read_u16(d, at)) > 0) outlined.push_back(g);
    }
    REQUIRE(outlined.size() > 20);
    for (std::size_t k = 0; k < outlined.size(); ++k) {
        const std::size_t at = glyf + offset_of(outlined[k]);
        write_u16(d, at, 0xFFFF);                // numberOfContours -1: a composite
        write_u16(d, at + 10, 0x0001 | 0x0002);  // word arguments, x and y values
        write_u16(d, at + 12, target(k, outlined));
        write_u16(d, at + 14, 0);
        write_u16(d, at + 16, 0);
    }
    const std::filesystem::path out = std::filesystem::temp_directory_path() / name;
    std::ofstream(out, std::ios::binary) << d;
    return out;
}

}  // namespace

TEST_CASE("font: a composite glyph that contains itself, or nests too deep, is an error",
          "[runtime][font]") {
    const std::filesystem::path dir = font_dir();
    REQUIRE_POV_FONTS(dir);
    // Each glyph its own only component; then each the next one's (a chain
    // through the whole font). Before, the first took 4 GB in a minute
    // (each level copying the one below); POV-Ray recurses until its stack
    // runs out.
    const auto self =
        composite_font(dir / "timrom.ttf", "hexant_font_test_self.ttf",
                       [](std::size_t k, const std::vector<unsigned>& g) { return g[k]; });
    const auto chain = composite_font(
        dir / "timrom.ttf", "hexant_font_test_chain.ttf",
        [](std::size_t k, const std::vector<unsigned>& g) { return g[(k + 1) % g.size()]; });
    for (const auto& [path, expected] :
         {std::pair{self, std::string("a cycle")}, std::pair{chain, std::string("16 deep")}}) {
        const auto font = TrueTypeFont::load(path);
        try {
            (void)lay_out_text(*font, std::string("Hexant"), 1.0, {});
            FAIL("no error for " << path);
        } catch (const FontError& e) {
            const std::string what = e.what();
            INFO(what);
            CHECK(what.find(path.filename().string()) != std::string::npos);
            CHECK(what.find(expected) != std::string::npos);
        }
        std::filesystem::remove(path);
    }
}
