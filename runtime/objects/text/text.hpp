// POV-Ray's text { ttf "FONT.ttf" "STRING", THICKNESS, OFFSET }: the glyphs
// of a TrueType font laid out as POV-Ray 3.7 places them, extruded along +z
// (text_geometry.hpp, true_type_font.hpp). The object kind
// (runtime/objects/shape_kind.hpp).
//
// The font is read and the string laid out when the scene is read: the
// thickness may be a function of time, the offset (which places the glyphs)
// may not. A string that changes with clock (str(clock, ...)) is a text per
// piece of time, made by the language as for any argument that is a
// TimedString.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "runtime/motion/transform.hpp"
#include "runtime/objects/shape_kind.hpp"
#include "runtime/objects/text/text_geometry.hpp"
#include "runtime/time/vector_function.hpp"

namespace hexant::runtime {

namespace objects {
class TextModel;
}  // namespace objects

struct Text {
    static constexpr std::string_view keyword = "text";
    static constexpr std::array<std::string_view, 2> options{"internal", "ttf"};
    using Model = objects::TextModel;

    std::string font;    // as the scene names it
    std::string string;  // as the scene gives it
    TimeFunction thickness = 1.0;
    glm::dvec3 offset{0.0};
    // The glyphs in text space, 1 unit = 1 em, shared by every copy.
    geometry::TextGlyphs glyphs;

    // Throws through `a` (font not found or unreadable, `internal` fonts,
    // an offset that depends on clock).
    static Text read(const objects::ShapeArguments& a);
    // What POV-Ray's parser applies before the scene's own transformations
    // (Parse_TrueType: a turn of 0.001 degrees about each axis "to fix
    // cracks in text that lies along an axis").
    static Transform placement();
    // Objects it makes (ObjectRecord::objects): a glyph a character, each
    // about an object's memory.
    std::uint64_t objects() const { return glyphs.size(); }
    template <class F>
    void parameters(F&& f) const {
        f("font", "font", font);
        f("string", "string", string);
        f("thickness", "thickness", thickness);
        f("offset", "offset", Vector3Function{{offset.x, offset.y, offset.z}});
        f("glyphs", "glyphs", objects::DescribedParameter{std::to_string(glyphs.size())});
    }
};

}  // namespace hexant::runtime

#include "runtime/objects/text/text_model.hpp"
