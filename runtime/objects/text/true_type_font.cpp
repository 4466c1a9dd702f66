#include "runtime/objects/text/true_type_font.hpp"

#include <ft2build.h>
#include FT_FREETYPE_H
#include FT_TRUETYPE_TABLES_H
#include FT_TRUETYPE_TAGS_H

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <mutex>
#include <optional>
#include <system_error>
#include <utility>

namespace hexant::runtime::objects {

namespace {

// TrueType composite glyph flags (the 'glyf' table; FreeType's
// FT_SUBGLYPH_FLAG_* have the same values).
constexpr unsigned kArgsAreWords = 0x0001;
constexpr unsigned kArgsAreXyValues = 0x0002;
constexpr unsigned kUseMyMetrics = 0x0200;

// 'kern' coverage bits (truetype.cpp 86-90).
constexpr unsigned kKernHorizontal = 0x01;
constexpr unsigned kKernMinimum = 0x02;
constexpr unsigned kKernCrossStream = 0x04;
constexpr unsigned kKernOverride = 0x08;

std::string quoted(const std::filesystem::path& path) {
    return "'" + path.string() + "'";
}

// Big-endian reads from a table held in memory; out of range reads 0 (and
// set `ok` false) instead of reading past the end.
struct Table {
    std::vector<unsigned char> bytes;
    bool present = false;

    std::uint8_t u8(std::size_t at, bool* ok = nullptr) const {
        if (at >= bytes.size()) {
            if (ok) *ok = false;
            return 0;
        }
        return bytes[at];
    }
    std::uint16_t u16(std::size_t at, bool* ok = nullptr) const {
        if (at + 2 > bytes.size()) {
            if (ok) *ok = false;
            return 0;
        }
        return static_cast<std::uint16_t>(bytes[at] << 8 | bytes[at + 1]);
    }
    std::int16_t s16(std::size_t at, bool* ok = nullptr) const {
        return static_cast<std::int16_t>(u16(at, ok));
    }
    std::uint32_t u32(std::size_t at, bool* ok = nullptr) const {
        return static_cast<std::uint32_t>(u16(at, ok)) << 16 | u16(at + 2, ok);
    }
};

Table load_table(FT_Face face, FT_ULong tag) {
    Table table;
    FT_ULong length = 0;
    if (FT_Load_Sfnt_Table(face, tag, 0, nullptr, &length) != 0) return table;
    table.bytes.resize(length);
    if (length > 0 && FT_Load_Sfnt_Table(face, tag, 0, table.bytes.data(), &length) != 0) {
        table.bytes.clear();
        return table;
    }
    table.present = true;
    return table;
}

struct KernPair {
    std::uint16_t left, right;
    std::int16_t value;
};
struct KernSubtable {
    std::uint16_t coverage = 0;
    std::vector<KernPair> pairs;
};

// A format 4 character map's segments (ProcessFormat4Glyph 1647-1700).
struct Format4 {
    std::size_t base = 0;  // offset of the subtable in 'cmap'
    std::uint16_t seg_count = 0;
    std::size_t end_at = 0, start_at = 0, delta_at = 0, range_at = 0;
};

// The subtable POV-Ray's ProcessCharMap settles on for an encoding.
struct CharMapChoice {
    int format = -1;  // 0, 4, 6, or -1 for none
    std::size_t base = 0;
    Format4 f4;
};

}  // namespace

std::u16string pov_text_to_ucs2(std::string_view text, TextEncoding encoding) {
    const std::size_t nul = text.find('\0');
    if (nul != std::string_view::npos) text = text.substr(0, nul);
    std::u16string out;
    out.reserve(text.size());
    if (encoding == TextEncoding::ascii) {
        for (const char c : text) {
            const auto byte = static_cast<unsigned char>(c);
            out.push_back(byte < 0x80 ? static_cast<char16_t>(byte) : u' ');
        }
        return out;
    }
    // Convert_UTF8_To_UCS2 with gUTF8SequenceArray / gUTF8Offsets
    // (parsestr.cpp 55-82): the lead byte gives the count of continuation
    // bytes; the code is their plain sum shifted, less a fixed offset.
    static constexpr std::uint32_t kOffsets[6] = {0x00000000UL, 0x00003080UL, 0x000E2080UL,
                                                  0x03C82080UL, 0xFA082080UL, 0x82082080UL};
    for (std::size_t i = 0; i < text.size(); ++i) {
        const auto lead = static_cast<unsigned char>(text[i]);
        const int length = lead < 0xC0   ? 0
                           : lead < 0xE0 ? 1
                           : lead < 0xF0 ? 2
                           : lead < 0xF8 ? 3
                           : lead < 0xFC ? 4
                                         : 5;
        if (length > 0 && i + length >= text.size()) {
            break;  // cut off by the end of the string (POV-Ray reads past it)
        }
        std::uint32_t code = 0;
        for (int j = length; j > 0; --j) {
            code += static_cast<unsigned char>(text[i]);
            code <<= 6;
            ++i;
        }
        code += static_cast<unsigned char>(text[i]);
        code -= kOffsets[length];
        out.push_back(code <= 0xFFFF ? static_cast<char16_t>(code) : u'\uFFFD');
    }
    return out;
}

struct TrueTypeFont::Impl {
    std::filesystem::path path;
    FT_Library library = nullptr;
    FT_Face face = nullptr;
    mutable std::mutex mutex;  // FreeType's face and the caches

    unsigned units_per_em = 0;
    unsigned num_glyphs = 0;
    int index_to_loc_format = 0;
    std::vector<std::uint32_t> loca;                           // numGlyphs + 1 entries (as present)
    std::vector<std::pair<std::uint16_t, std::int16_t>> hmtx;  // per glyph: advance, lsb
    Table glyf, cmap;
    std::vector<KernSubtable> kern;
    mutable std::map<int, CharMapChoice> charmaps;  // per encoding
    mutable std::map<std::pair<unsigned, bool>, FontGlyph> glyph_cache;

    ~Impl() {
        if (face) FT_Done_Face(face);
        if (library) FT_Done_FreeType(library);
    }

    [[noreturn]] void fail(const std::string& what) const {
        throw FontError("font " + quoted(path) + ": " + what);
    }

    // ProcessCharMap (1455-1600): platform IDs by preference, the first
    // subtable of that platform in format 0, 4 or 6.
    const CharMapChoice& choice(TextEncoding encoding) const {
        const int key = static_cast<int>(encoding);
        auto found = charmaps.find(key);
        if (found != charmaps.end()) return found->second;
        static constexpr int kAscii[4] = {1, 3, 0, 3};
        static constexpr int kUnicode[4] = {0, 3, 1, 3};
        const int* order = encoding == TextEncoding::ascii ? kAscii : kUnicode;
        CharMapChoice result;
        const unsigned count = cmap.u16(2);
        for (int j = 0; j < 4 && result.format < 0; ++j) {
            for (unsigned i = 0; i < count; ++i) {
                const std::size_t entry = 4 + 8 * std::size_t(i);
                if (cmap.u16(entry) != order[j]) continue;
                const std::size_t base = cmap.u32(entry + 4);
                const int format = cmap.u16(base);
                if (format != 0 && format != 4 && format != 6) continue;
                result.format = format;
                result.base = base;
                if (format == 4) {
                    Format4& f = result.f4;
                    f.base = base;
                    f.seg_count = cmap.u16(base + 6) >> 1;
                    f.end_at = base + 14;
                    f.start_at = f.end_at + 2 * std::size_t(f.seg_count) + 2;  // reservedPad
                    f.delta_at = f.start_at + 2 * std::size_t(f.seg_count);
                    f.range_at = f.delta_at + 2 * std::size_t(f.seg_count);
                }
                break;
            }
        }
        return charmaps.emplace(key, result).first->second;
    }

    unsigned lookup(char16_t code, TextEncoding encoding) const {
        const CharMapChoice& c = choice(encoding);
        unsigned search = code;
        switch (c.format) {
            case 0:  // ProcessFormat0Glyph 1608-1620: one byte per code
                return cmap.u8(c.base + 6 + search);
            case 6: {  // ProcessFormat6Glyph 1781-1800
                const unsigned first = cmap.u16(c.base + 6), entries = cmap.u16(c.base + 8);
                if (search >= first && search < first + entries) {
                    return cmap.u16(c.base + 10 + 2 * std::size_t(search - first));
                }
                return 0;
            }
            case 4: {  // ProcessFormat4Glyph 1700-1765
                const Format4& f = c.f4;
                unsigned glyph = 0;
                for (int attempt = 0; attempt < 2; ++attempt) {
                    for (unsigned i = 0; i < f.seg_count; ++i) {
                        if (search > cmap.u16(f.end_at + 2 * i)) continue;
                        const unsigned start = cmap.u16(f.start_at + 2 * i);
                        if (search >= start) {
                            const unsigned delta = cmap.u16(f.delta_at + 2 * i);
                            const unsigned range = cmap.u16(f.range_at + 2 * i);
                            if (range == 0) {
                                glyph = search + delta;
                            } else {
                                glyph = cmap.u16(f.range_at + 2 * i + range + 2 * (search - start));
                                if (glyph != 0) glyph += delta;
                            }
                        }
                        break;
                    }
                    if (glyph != 0 || search >= 0x100) break;
                    search += 0xF000;  // the Unicode user space, for symbol fonts
                }
                return glyph & 0xFFFF;  // returned as USHORT
            }
            default:
                return 0;
        }
    }

    // The glyph whose data begins at loca[index]: index itself, or (no data
    // of its own) the next glyph stored at the same place.
    std::optional<unsigned> data_glyph(unsigned index) const {
        if (index >= num_glyphs || index + 1 >= loca.size()) return std::nullopt;
        const std::uint32_t at = loca[index];
        for (unsigned k = index; k < num_glyphs && k + 1 < loca.size(); ++k) {
            if (loca[k] != at) return std::nullopt;
            if (loca[k + 1] > at) return k;
        }
        return std::nullopt;
    }

    FT_GlyphSlot load_raw(unsigned index) const {
        const FT_Error error =
            FT_Load_Glyph(face, index, FT_LOAD_NO_SCALE | FT_LOAD_NO_HINTING | FT_LOAD_NO_RECURSE);
        if (error != 0) {
            fail("glyph " + std::to_string(index) + " cannot be read (FreeType error " +
                 std::to_string(error) + ")");
        }
        return face->glyph;
    }

    // At most this many outline points in one glyph, its composites'
    // copies counted: real glyphs have a few hundred; a composite that
    // places another twice, sixteen levels deep, would make 2^16 copies.
    static constexpr std::size_t kMaxGlyphPoints = std::size_t(1) << 20;

    // ExtractGlyphOutline (1958-2360) for one glyph index. The header and
    // outline read at glyf + loca[index]; for the character ' ' nothing is
    // read (1968-1977). A composite that refers to a glyph being extracted
    // (itself, or one that contains it) is an error, as is a glyph past
    // kMaxGlyphPoints (issue 45: a self-referring glyph took 4 GB in a
    // minute); POV-Ray recurses until its stack runs out.
    FontGlyph extract(unsigned index, bool space) const {
        std::vector<unsigned> within;
        std::size_t point_count = 0;
        return extract(index, space, within, point_count);
    }
    // `within`: the composites being extracted around this one, outermost
    // first; `point_count`: the points of the outermost glyph so far.
    FontGlyph extract(unsigned index, bool space, std::vector<unsigned>& within,
                      std::size_t& point_count) const {
        FontGlyph g;
        g.glyph_index = index;
        g.metrics_index = index;
        if (space) return g;
        if (std::find(within.begin(), within.end(), index) != within.end())
            fail("glyph " + std::to_string(within.front()) +
                 " is a composite that contains glyph " + std::to_string(index) +
                 " inside itself (a cycle)");
        if (within.size() > 16)
            fail("glyph " + std::to_string(within.front()) + " nests composites more than 16 deep");
        if (index >= num_glyphs || index >= loca.size()) return g;
        const std::size_t at = loca[index];
        bool ok = true;
        const int contours = glyf.s16(at, &ok);
        g.x_min = glyf.s16(at + 2, &ok);
        g.y_min = glyf.s16(at + 4, &ok);
        g.x_max = glyf.s16(at + 6, &ok);
        g.y_max = glyf.s16(at + 8, &ok);
        if (!ok) {  // past the table (POV-Ray would read other data): nothing
            FontGlyph none;
            none.glyph_index = none.metrics_index = index;
            return none;
        }
        const std::optional<unsigned> data = data_glyph(index);
        if (contours == 0 || !data) return g;
        const FT_GlyphSlot slot = load_raw(*data);
        const double upem = units_per_em;
        if (contours > 0) {
            if (slot->format != FT_GLYPH_FORMAT_OUTLINE) return g;
            const FT_Outline& outline = slot->outline;
            int first = 0;
            for (int c = 0; c < outline.n_contours; ++c) {
                const int last = outline.contours[c];
                std::vector<FontGlyph::Point> points;
                point_count += std::size_t(std::max(0, last - first + 1));
                if (point_count > kMaxGlyphPoints)
                    fail("glyph " + std::to_string(within.empty() ? index : within.front()) +
                         " has more than " + std::to_string(kMaxGlyphPoints) +
                         " outline points, its composites' copies counted");
                for (int i = first; i <= last; ++i) {
                    const FT_Vector v = outline.points[i];
                    const int x = static_cast<int>(v.x), y = static_cast<int>(v.y);
                    g.x_min = std::min(g.x_min, x);
                    g.x_max = std::max(g.x_max, x);
                    g.y_min = std::min(g.y_min, y);
                    g.y_max = std::max(g.y_max, y);
                    points.push_back({{x / upem, y / upem}, (outline.tags[i] & 1) != 0});
                }
                g.contours.push_back(std::move(points));
                first = last + 1;
            }
            return g;
        }
        // Composite (2190-2350).
        if (slot->format != FT_GLYPH_FORMAT_COMPOSITE) return g;
        struct Component {
            int index;
            unsigned flags;
            int arg1, arg2;
            FT_Matrix m;
        };
        std::vector<Component> components;
        for (FT_UInt i = 0; i < slot->num_subglyphs; ++i) {
            Component c{};
            FT_Int sub = 0, a1 = 0, a2 = 0;
            FT_UInt flags = 0;
            if (FT_Get_SubGlyph_Info(slot, i, &sub, &flags, &a1, &a2, &c.m) != 0) continue;
            c.index = sub;
            c.flags = flags;
            // POV-Ray reads word arguments signed and byte arguments
            // unsigned (2215-2226).
            c.arg1 = (flags & kArgsAreWords) ? static_cast<std::int16_t>(a1) : (a1 & 0xFF);
            c.arg2 = (flags & kArgsAreWords) ? static_cast<std::int16_t>(a2) : (a2 & 0xFF);
            components.push_back(c);
        }
        auto to_short = [](double v) {  // a double stored in a SHORT: truncated
            return static_cast<int>(std::clamp(std::trunc(v), -32768.0, 32767.0));
        };
        for (const Component& c : components) {
            if (!(c.flags & kArgsAreXyValues)) continue;  // point matching: skipped (2262-2266)
            if (c.flags & kUseMyMetrics) g.metrics_index = static_cast<unsigned>(c.index);
            within.push_back(index);
            const FontGlyph sub =
                extract(static_cast<unsigned>(c.index), false, within, point_count);
            within.pop_back();
            if (sub.contours.empty()) continue;
            // FreeType's matrix holds the file's F2Dot14 values times 4 in
            // 16.16: xx, yx, xy, yy in file order. POV-Ray names them
            // xscale, scale01, scale10, yscale and applies
            // x' = xscale x + scale01 y, y' = scale10 x + yscale y (2300-2303).
            const double xscale = c.m.xx / 65536.0, scale01 = c.m.yx / 65536.0;
            const double scale10 = c.m.xy / 65536.0, yscale = c.m.yy / 65536.0;
            const double xoff = c.arg1 / upem, yoff = c.arg2 / upem;
            for (const auto& contour : sub.contours) {
                std::vector<FontGlyph::Point> points;
                for (const FontGlyph::Point& q : contour) {
                    const double x = xscale * q.p.x + scale01 * q.p.y + xoff;
                    const double y = scale10 * q.p.x + yscale * q.p.y + yoff;
                    // The header (font units) compared with em units (2306-2316).
                    if (x < g.x_min) g.x_min = to_short(x);
                    if (x > g.x_max) g.x_max = to_short(x);
                    if (y < g.y_min) g.y_min = to_short(y);
                    if (y > g.y_max) g.y_max = to_short(y);
                    points.push_back({{x, y}, q.on_curve});
                }
                g.contours.push_back(std::move(points));
            }
        }
        return g;
    }
};

TrueTypeFont::TrueTypeFont(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
TrueTypeFont::~TrueTypeFont() = default;

std::shared_ptr<const TrueTypeFont> TrueTypeFont::load(const std::filesystem::path& path) {
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) {
        throw FontError("font file " + quoted(path) + " not found");
    }
    if (!std::filesystem::is_regular_file(path, ec)) {
        throw FontError("font file " + quoted(path) + " is not a regular file");
    }
    auto impl = std::make_unique<Impl>();
    impl->path = path;
    if (FT_Init_FreeType(&impl->library) != 0) {
        impl->library = nullptr;
        impl->fail("FreeType could not be started");
    }
    if (const FT_Error error = FT_New_Face(impl->library, path.c_str(), 0, &impl->face)) {
        impl->face = nullptr;
        impl->fail("not a font file FreeType can read (FreeType error " + std::to_string(error) +
                   ")");
    }
    FT_Face face = impl->face;
    if (!FT_IS_SFNT(face)) impl->fail("not a TrueType font (no sfnt tables)");
    impl->glyf = load_table(face, TTAG_glyf);
    if (!impl->glyf.present) {
        impl->fail(
            "not a TrueType font with quadratic outlines (no 'glyf' table: an OpenType/CFF font "
            "with cubic outlines, or a bitmap font)");
    }
    const Table head = load_table(face, TTAG_head);
    const Table maxp = load_table(face, TTAG_maxp);
    const Table hhea = load_table(face, TTAG_hhea);
    const Table hmtx = load_table(face, TTAG_hmtx);
    const Table loca = load_table(face, TTAG_loca);
    impl->cmap = load_table(face, TTAG_cmap);
    for (const auto& [table, name] : {std::pair{&head, "head"},
                                      {&maxp, "maxp"},
                                      {&hhea, "hhea"},
                                      {&hmtx, "hmtx"},
                                      {&loca, "loca"},
                                      {&impl->cmap, "cmap"}}) {
        if (!table->present)
            impl->fail(std::string("the required table '") + name + "' is missing");
    }
    // ProcessHeadTable (1050-1105).
    if (head.bytes.size() < 54 || head.u32(12) != 0x5F0F3CF5) impl->fail("damaged 'head' table");
    impl->units_per_em = head.u16(18);
    impl->index_to_loc_format = head.s16(50);
    if (impl->units_per_em == 0) impl->fail("unitsPerEm is 0");
    if (impl->index_to_loc_format != 0 && impl->index_to_loc_format != 1) {
        impl->fail("damaged 'head' table (indexToLocFormat)");
    }
    // ProcessMaxpTable (1154-1165), ProcessLocaTable (1110-1150).
    impl->num_glyphs = maxp.u16(4);
    if (impl->num_glyphs == 0) impl->fail("no glyphs");
    for (unsigned i = 0; i <= impl->num_glyphs; ++i) {
        bool ok = true;
        const std::uint32_t at = impl->index_to_loc_format == 0
                                     ? std::uint32_t(loca.u16(2 * std::size_t(i), &ok)) << 1
                                     : loca.u32(4 * std::size_t(i), &ok);
        if (!ok) break;
        impl->loca.push_back(at);
    }
    // ProcessHheaTable (1274-1320), ProcessHmtxTable (1323-1345).
    const unsigned metrics = hhea.u16(34);
    if (metrics == 0) impl->fail("damaged 'hhea' table (numberOfHMetrics is 0)");
    std::uint16_t last_advance = 0;
    std::size_t at = 0;
    for (unsigned i = 0; i < impl->num_glyphs; ++i) {
        if (i < metrics) {
            last_advance = hmtx.u16(at);
            impl->hmtx.emplace_back(last_advance, hmtx.s16(at + 2));
            at += 4;
        } else {
            impl->hmtx.emplace_back(last_advance, hmtx.s16(at));
            at += 2;
        }
    }
    // ProcessKernTable (1169-1270): format 0 subtables read one after the
    // other; other formats skipped by their length.
    const Table kern = load_table(face, TTAG_kern);
    if (kern.present) {
        const unsigned count = kern.u16(2);
        std::size_t p = 4;
        for (unsigned i = 0; i < count && p < kern.bytes.size(); ++i) {
            KernSubtable sub;
            const unsigned length = kern.u16(p + 2);
            sub.coverage = kern.u16(p + 4);
            p += 6;
            if ((sub.coverage >> 8) == 0) {
                const unsigned pairs = kern.u16(p);
                p += 8;
                for (unsigned k = 0; k < pairs && p + 6 <= kern.bytes.size(); ++k, p += 6) {
                    sub.pairs.push_back({kern.u16(p), kern.u16(p + 2), kern.s16(p + 4)});
                }
            } else {
                p += length >= 6 ? length - 6 : 0;
            }
            impl->kern.push_back(std::move(sub));
        }
    }
    return std::shared_ptr<const TrueTypeFont>(new TrueTypeFont(std::move(impl)));
}

const std::filesystem::path& TrueTypeFont::path() const {
    return impl_->path;
}

unsigned TrueTypeFont::units_per_em() const {
    return impl_->units_per_em;
}

unsigned TrueTypeFont::glyph_count() const {
    return impl_->num_glyphs;
}

unsigned TrueTypeFont::glyph_index(char16_t code, TextEncoding encoding) const {
    std::lock_guard lock(impl_->mutex);
    return impl_->lookup(code, encoding);
}

FontGlyph TrueTypeFont::glyph(char16_t code, TextEncoding encoding) const {
    std::lock_guard lock(impl_->mutex);
    const unsigned index = impl_->lookup(code, encoding);
    const bool space = code == u' ';
    const auto key = std::make_pair(index, space);
    auto found = impl_->glyph_cache.find(key);
    if (found == impl_->glyph_cache.end()) {
        FontGlyph g = impl_->extract(index, space);
        if (g.metrics_index < impl_->hmtx.size()) {
            g.advance_width = impl_->hmtx[g.metrics_index].first;
            g.left_side_bearing = impl_->hmtx[g.metrics_index].second;
        }
        found = impl_->glyph_cache.emplace(key, std::move(g)).first;
    }
    return found->second;
}

glm::ivec2 TrueTypeFont::kerning(unsigned left, unsigned right) const {
    // ProcessNewTTF 533-607, FWord arithmetic kept.
    std::int16_t kx = 0, ky = 0;
    std::int16_t min_x = static_cast<std::int16_t>(-static_cast<int>(impl_->units_per_em));
    std::int16_t min_y = min_x;
    const auto& tables = impl_->kern;
    for (std::size_t j = 0; j < tables.size(); ++j) {
        // POV-Ray reads the coverage of the first subtable for all (537-538).
        const unsigned coverage = tables[0].coverage;
        if (!(coverage & kKernHorizontal)) continue;
        for (const KernPair& pair : tables[j].pairs) {
            if (pair.left == left && pair.right == right) {
                if (coverage & kKernMinimum) {
                    (coverage & kKernCrossStream ? min_y : min_x) = pair.value;
                } else if (coverage & kKernCrossStream) {
                    if (pair.value == static_cast<std::int16_t>(0x8000)) {
                        ky = 0;
                    } else {
                        ky = coverage & kKernOverride ? pair.value
                                                      : static_cast<std::int16_t>(ky + pair.value);
                    }
                } else {
                    kx = coverage & kKernOverride ? pair.value
                                                  : static_cast<std::int16_t>(kx + pair.value);
                }
                break;
            }
            if (pair.left > left) break;  // pairs sorted by left glyph
        }
    }
    return {std::max(kx, min_x), std::max(ky, min_y)};
}

std::vector<std::vector<geometry::TextSegment>> pov_glyph_segments(const FontGlyph& glyph,
                                                                   glm::dvec2 translation) {
    using geometry::TextSegment;
    std::vector<std::vector<TextSegment>> out;
    for (const auto& contour : glyph.contours) {
        const std::size_t n = contour.size();
        if (n == 0) continue;
        // Point j for j = 0..n, point n repeating point 0 (2410-2416).
        auto point = [&](std::size_t j) { return contour[j == n ? 0 : j].p + translation; };
        auto on = [&](std::size_t j) { return contour[j == n ? 0 : j].on_curve; };
        std::vector<TextSegment> segments;
        glm::dvec2 x0 = point(0);
        for (std::size_t j = 1; j <= n; ++j) {
            const glm::dvec2 x1 = point(j);
            if (on(j)) {
                segments.push_back({x0, 0.5 * (x0 + x1), x1, false});
                x0 = x1;
                continue;
            }
            glm::dvec2 x2;
            if (j == n) {
                x2 = point(0);
            } else {
                x2 = point(j + 1);
                if (!on(j + 1)) x2 = 0.5 * (x1 + x2);
            }
            segments.push_back({x0, x1, x2, true});
            x0 = x2;
        }
        out.push_back(std::move(segments));
    }
    return out;
}

geometry::TextGeometry lay_out_text(const TrueTypeFont& font, std::u16string_view codes,
                                    double thickness, glm::dvec3 offset, TextEncoding encoding) {
    geometry::TextGeometry text;
    text.thickness = thickness;
    const double funit = 1.0 / static_cast<double>(font.units_per_em());
    glm::dvec3 total(0.0);
    unsigned last_index = 0;
    for (std::size_t i = 0; i < codes.size() && codes[i] != 0; ++i) {
        const FontGlyph g = font.glyph(codes[i], encoding);
        glm::dvec2 place;
        if (i == 0) {
            // Start the glyph's box at the origin (556-570).
            total.x = -g.x_min * funit;
            place = {total.x, total.y};
            total.x = (g.advance_width - g.left_side_bearing) * funit;
        } else {
            const glm::ivec2 kern = font.kerning(last_index, g.metrics_index);
            place.x = total.x + static_cast<double>(g.left_side_bearing - g.x_min + kern.x) * funit;
            place.y = total.y + static_cast<double>(kern.y) * funit;
            total.x += (g.advance_width + kern.x) * funit;
        }
        total += offset;
        geometry::TextGlyph glyph = geometry::make_text_glyph(pov_glyph_segments(g, place), place);
        glyph.code = codes[i];
        glyph.glyph_index = g.glyph_index;
        text.glyphs.push_back(std::move(glyph));
        last_index = g.glyph_index;
    }
    return text;
}

geometry::TextGeometry lay_out_text(const TrueTypeFont& font, const std::string& text,
                                    double thickness, glm::dvec3 offset, TextEncoding encoding) {
    const std::u16string codes = pov_text_to_ucs2(text, encoding);
    return lay_out_text(font, std::u16string_view(codes), thickness, offset, encoding);
}

}  // namespace hexant::runtime::objects
