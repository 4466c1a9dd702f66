// TrueType fonts for POV-Ray's text object, read with FreeType 2, and the
// placement of a string's glyphs exactly as POV-Ray 3.7 does it
// (source/backend/shape/truetype.cpp of 3.7-stable, cited below by line).
//
// What is POV-Ray's own reading rather than FreeType's (reproduced from the
// raw tables that FreeType hands out, FT_Load_Sfnt_Table):
// - the character map (ProcessCharMap, 1455-1600): the subtables are tried by
//   platform ID only, in an order set by the string encoding (OpenFontFile,
//   940-975: charset ascii: Macintosh 1 first, then 3, 0, 3; utf8/sys: Unicode
//   0, then 3, 1, 3); the first subtable of that platform in format 0, 4 or 6
//   answers for every character; format 4 retries a missing code below 0x100
//   at 0xF000 + code (1740-1747).
// - the glyph header (ExtractGlyphOutline, 1958-2360): xMin/xMax/yMin/yMax as
//   stored, widened by the outline's points; a glyph with no data (other
//   than for the character ' ', which is never read) takes the header and
//   outline of the glyph whose data follows in 'glyf', as POV-Ray reads at
//   loca[index] without looking at the length; composite glyphs are
//   assembled by POV-Ray's rules (byte offsets read unsigned, the 2x2
//   matrix's off-diagonal terms swapped, components positioned by point
//   matching dropped, the header widened by em-unit coordinates truncated to
//   whole font units).
// - metrics from 'hmtx' (ProcessHmtxTable, 1323-1345), of the glyph or of
//   the component flagged USE_MY_METRICS;
// - kerning from format 0 subtables of 'kern' (ProcessKernTable, 1169-1270;
//   its use in ProcessNewTTF, 530-620).
// FreeType supplies the outlines' points and on/off-curve flags
// (FT_LOAD_NO_SCALE | FT_LOAD_NO_HINTING | FT_LOAD_NO_RECURSE, font units).
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

#include "runtime/objects/text/text_geometry.hpp"

namespace hexant::runtime::objects {

// A font that cannot be used: the message names the file.
class FontError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

// POV-Ray 3.7's string encodings: global_settings { charset ascii | utf8 |
// sys }. The default is ascii (scene.cpp: stringEncoding = 0); POV-Ray
// switches to utf8 by itself when the scene file starts with bytes above 127
// (a byte order mark; tokenize.cpp 120-123). sys is utf8 here (POV-Ray's
// Unix build has no system conversion and stops with an error).
enum class TextEncoding { ascii, utf8, sys };

// The conversion part of POV-Ray's String_To_UCS2 (parsestr.cpp 679-740),
// for #version 3.5 and later, without the escapes (hexant's parser resolves
// those; POV-Ray's \uXXXX gives a code directly): ascii keeps bytes below
// 0x80 and replaces every other byte by ' ' (POV-Ray warns "Non-ASCII
// character has been replaced by space character."); utf8 and sys decode
// UTF-8 as Convert_UTF8_To_UCS2 (parsestr.cpp 945-981): no validation, codes
// above 0xFFFF become U+FFFD, a sequence cut off by the end of the string
// ends it. The string ends at its first NUL (POV-Ray's are C strings).
std::u16string pov_text_to_ucs2(std::string_view text, TextEncoding encoding);

// One glyph as POV-Ray reads it for a character: contours in em units
// (font units / unitsPerEm), in file order, each point with its on-curve
// flag (the first point of a contour is used as an on-curve start whatever
// its flag, see lay_out_text).
struct FontGlyph {
    struct Point {
        glm::dvec2 p;
        bool on_curve;
    };
    unsigned glyph_index = 0;                        // the character map's answer (0: missing)
    unsigned metrics_index = 0;                      // whose hmtx entry gives the metrics
    int x_min = 0, y_min = 0, x_max = 0, y_max = 0;  // the header box, font units
    int advance_width = 0, left_side_bearing = 0;    // hmtx, font units
    std::vector<std::vector<Point>> contours;
};

class TrueTypeFont {
  public:
    // Opens and checks the font (throws FontError: file not found, not a
    // font FreeType reads, not a TrueType font with quadratic 'glyf'
    // outlines, a required table missing or damaged). A collection (.ttc):
    // its first font, as POV-Ray.
    static std::shared_ptr<const TrueTypeFont> load(const std::filesystem::path& path);
    ~TrueTypeFont();
    TrueTypeFont(const TrueTypeFont&) = delete;
    TrueTypeFont& operator=(const TrueTypeFont&) = delete;

    const std::filesystem::path& path() const;
    unsigned units_per_em() const;
    unsigned glyph_count() const;

    // POV-Ray's character map lookup (ProcessCharMap): 0 when missing.
    unsigned glyph_index(char16_t code, TextEncoding encoding) const;
    // The glyph POV-Ray uses for the character (ProcessCharacter): the
    // missing glyph 0 for an unmapped character. Thread-safe (the glyphs are
    // read on demand under a lock and cached).
    FontGlyph glyph(char16_t code, TextEncoding encoding) const;
    // POV-Ray's kerning between the previous character's glyph index and
    // this glyph's metrics index, font units: (x, y) after POV-Ray's
    // clamping from below at -unitsPerEm or a minimum table's value.
    glm::ivec2 kerning(unsigned left_glyph_index, unsigned right_metrics_index) const;

    struct Impl;

  private:
    explicit TrueTypeFont(std::unique_ptr<Impl> impl);
    std::unique_ptr<Impl> impl_;
};

// POV-Ray 3.7's ProcessNewTTF (truetype.cpp 454-640): one glyph per
// character in text space, 1 unit = 1 em. The first glyph is moved by
// -xMin (its box starts at x = 0) and the pen set to advance - lsb; every
// later glyph is placed at pen + (lsb - xMin + kern) (its box's left end at
// pen + lsb + kern) and the pen advanced by advance + kern; after each
// character the pen moves by `offset` (x and y: offset.y raises every later
// character; offset.z is ignored, as POV-Ray's placement copies only x and y).
// Kerning in y shifts a glyph up by its value. A space (U+0020) has no
// outline and xMin 0 but its hmtx metrics. Glyphs are extruded from z = 0 to
// z = thickness. The text ends at the first NUL.
//
// Not done here, for the caller: POV-Ray's parser (parse.cpp
// Parse_TrueType) then rotates the whole text by <0.001, 0.001, 0.001>
// degrees ("to fix cracks in text that lies along an axis") before the
// scene's own transformations.
geometry::TextGeometry lay_out_text(const TrueTypeFont& font, std::u16string_view codes,
                                    double thickness, glm::dvec3 offset,
                                    TextEncoding encoding = TextEncoding::ascii);
// The same for a string as the scene gives it: pov_text_to_ucs2 first.
geometry::TextGeometry lay_out_text(const TrueTypeFont& font, const std::string& text,
                                    double thickness, glm::dvec3 offset,
                                    TextEncoding encoding = TextEncoding::ascii);

// POV-Ray's outline walk (ConvertOutlineToGlyph 2367-2455 with the segment
// walk of Inside_Glyph/GlyphIntersect, 2463-2600 and 2870-2990): from the
// contour's first point (taken as on the curve), an on-curve point ends a
// line, an off-curve point is the control of a quadratic ending at the next
// point if that is on the curve, else at the midpoint of the two; the
// contour closes back to its first point. Points in em units, moved by
// translation.
std::vector<std::vector<geometry::TextSegment>> pov_glyph_segments(const FontGlyph& glyph,
                                                                   glm::dvec2 translation);

}  // namespace hexant::runtime::objects
