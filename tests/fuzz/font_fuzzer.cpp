// libFuzzer over the TrueType fonts a scene's text { ttf "FILE" ... } may
// name (README, "Fuzzing"): the bytes are a font file, read by hexant's own
// reading of its tables (runtime/objects/text/true_type_font.cpp: character
// maps, glyph headers, composite glyphs, hmtx, kern) and laid out as
// POV-Ray lays out a string; the outlines are then hit by a few rays. A
// damaged font must end in a FontError: a crash, a sanitizer report, a leak
// or a hang is a bug. Seeds: POV-Ray's fonts (Debian's fonts-povray, named
// at run time: their licence asks for attribution) and the files in
// tests/fuzz/font_corpus/.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <iterator>
#include <string>

#include <unistd.h>

#include "runtime/objects/text/true_type_font.hpp"
#include "tests/fuzz/input_file.hpp"

namespace obj = hexant::runtime::objects;
namespace geo = hexant::runtime::geometry;

namespace {

// FreeType opens a font by its path: the input is written to one file per
// process, anew for each input.
const std::filesystem::path& font_file() {
    static const std::filesystem::path path = hexant::fuzz::input_file_path("font_fuzz", ".ttf");
    return path;
}

// Strings through both encodings: letters and digits (what the fonts map),
// a composite-prone accented run, pairs that kern, and codes past the
// character maps' ends.
const char* const kStrings[] = {"Hexant 0123", "AVAWToTy", "\xc3\xa9\xc3\xa8\xc3\xbc\xc3\x85",
                                "\xef\xbf\xbd\xe2\x82\xac~ \x7f"};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::filesystem::path& path = font_file();
    if (!hexant::fuzz::write_input_file(path, data, size)) return 0;
    try {
        const auto font = obj::TrueTypeFont::load(path);
        (void)font->units_per_em();
        // A few glyphs whatever the character map says, and kerning
        // between them; then one string, its charset and text picked by
        // the input's length (one layout an input keeps thousands a second).
        for (unsigned code = size % 5; code < 128; code += 23) {
            const obj::FontGlyph glyph = font->glyph(char16_t(code), obj::TextEncoding::utf8);
            (void)font->kerning(glyph.glyph_index, glyph.metrics_index);
        }
        const auto encoding = size % 2 ? obj::TextEncoding::ascii : obj::TextEncoding::utf8;
        const char* text = kStrings[(size / 2) % std::size(kStrings)];
        const geo::TextGeometry laid =
            obj::lay_out_text(*font, std::string(text), 0.5, {0.1, 0.0, 0.0}, encoding);
        const geo::Box3 box = geo::object_bounds(laid);
        // Rays through the text's box and across it, as a render would
        // send them.
        const glm::dvec3 mid = std::isfinite(box.lo.x) && std::isfinite(box.hi.x)
                                   ? (box.lo + box.hi) * 0.5
                                   : glm::dvec3(0.5);
        (void)geo::intersect(laid, geo::Ray3{{mid.x, mid.y, -5.0}, {0.0, 0.0, 1.0}}, 0.0, 1e30);
        (void)geo::intersect(laid, geo::Ray3{{-5.0, mid.y, 0.25}, {1.0, 0.01, 0.0}}, 0.0, 1e30);
        (void)geo::inside(laid, {mid.x, mid.y, 0.25});
    } catch (const obj::FontError&) {
        // A refused font: what the fuzzer wants to see.
    }
    return 0;
}
