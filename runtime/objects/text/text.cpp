#include "runtime/objects/text/text.hpp"

#include <map>
#include <mutex>

#include "runtime/objects/text/true_type_font.hpp"

namespace hexant::runtime {

namespace {

// Fonts by file, read once per process however many texts use them (a
// scene's digits may be a hundred text objects).
std::shared_ptr<const objects::TrueTypeFont> font_at(const std::filesystem::path& path) {
    static std::mutex mutex;
    static std::map<std::filesystem::path, std::weak_ptr<const objects::TrueTypeFont>> fonts;
    const std::lock_guard<std::mutex> lock(mutex);
    if (auto font = fonts[path].lock()) return font;
    auto font = objects::TrueTypeFont::load(path);
    fonts[path] = font;
    return font;
}

}  // namespace

// POV-Ray 3.7's internal fonts 0 to 3 are its four bundled TrueType files.
const char* const kInternalFonts[] = {"povlogo.ttf", "timrom.ttf", "cyrvetic.ttf", "crystal.ttf"};

Text Text::read(const objects::ShapeArguments& a) {
    const auto& options = a.options();
    const bool internal = options.size() == 1 && options.front() == "internal";
    if (!internal && (options.size() != 1 || options.front() != "ttf"))
        a.fail("text needs its font as ttf \"FILE.ttf\" (or internal N) before the string");
    a.need(4, 4,
           internal ? "a font number, a string, a thickness and an offset"
                    : "a font file, a string, a thickness and an offset");
    Text text;
    if (internal) {
        const long long id = a.count(0, "text's internal font", 0, 3);
        text.font = kInternalFonts[id];
    } else {
        text.font = a.string(0, "text's font file name");
    }
    text.string = a.string(1, "text's string");
    text.thickness = a.number(2, "text's thickness");
    const Vector3Function offset = a.vector3(3, "text's offset");
    if (offset.depends_on_time())
        a.fail(
            "text's offset depends on clock; it places the glyphs, which hexant lays out "
            "once (move or scale the text instead)");
    text.offset = offset(0.0);
    // POV-Ray adds ".ttf" to a name without an extension.
    std::string name = text.font;
    if (std::filesystem::path(name).extension().empty()) name += ".ttf";
    const auto encoding =
        a.charset() == "utf8" ? objects::TextEncoding::utf8 : objects::TextEncoding::ascii;
    try {
        const auto font = font_at(a.find_file(name, "font file"));
        geometry::TextGeometry laid =
            objects::lay_out_text(*font, text.string, 1.0, text.offset, encoding);
        text.glyphs = laid.glyphs;
    } catch (const objects::FontError& e) {
        a.fail(e.what());
    }
    return text;
}

Transform Text::placement() {
    TransformStep turn{};
    turn.kind = TransformKind::Rotate;
    turn.vector = Vector3Function{{0.001, 0.001, 0.001}};
    Transform t;
    t.append(turn);
    return t;
}

}  // namespace hexant::runtime
