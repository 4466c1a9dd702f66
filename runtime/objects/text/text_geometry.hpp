// POV-Ray's text { ttf "font" "string", thickness, offset } in text space:
// the glyphs' outlines (closed contours of lines and quadratic Beziers in the
// x-y plane, placed by lay_out_text in true_type_font.hpp) swept along +z
// from z = 0 to z = thickness (POV-Ray 3.7, truetype.cpp, GlyphIntersect,
// GetZeroOneHits, Inside_Glyph, Inside).
//
// Filling: the even-odd rule over all contours of one glyph (Inside_Glyph
// counts crossings of all contours and tests crossings & 1), whatever the
// contours' direction; overlapping contours of one glyph leave a hole where
// they overlap, as in POV-Ray. Glyphs are separate solids (POV-Ray makes a
// union of one object per character): where two glyphs overlap both sets of
// surfaces exist and a point is inside when it is inside either.
//
// Hits: part 0 the cap at z = 0 (normal -z), part 1 the cap at
// z = thickness (normal +z), part 2 a side wall (normal horizontal, from the
// curve's tangent, pointing out of the glyph by the even-odd rule). uv: the
// hit's (x, y) in text space (POV-Ray defines no uv mapping for text).
//
// Thickness: POV-Ray keeps the sign. thickness > 0 is the solid described
// above. thickness <= 0 (POV-Ray 3.7 renders it, checked with povray 3.7):
// only the two caps, at z = 0 (normal -z) and z = thickness (normal +z),
// no side walls (GlyphIntersect accepts wall hits with 0 <= z <= depth
// only); inside() is then true only for thickness == 0 on the plane z = 0
// (Inside: 0 <= z <= depth). For thickness == 0 the two caps coincide and
// the nearer is reported (part 0, normal -z): a flat text.
//
// An empty text (no glyph with a segment: empty string, only spaces) or a
// non-finite thickness is an empty shape: no hits, nothing inside, bounds
// Box3::nowhere().
//
// Accuracy: the walls are found in 2D by the signed distances of each
// segment's points from the ray's line (difference_of_products, exact in
// sign); a quadratic's distance along the curve is a quadratic in the
// curve parameter whose discriminant is formed without cancellation
// (f1^2 - f0 f2). Neighbouring segments judge their shared end by the same
// number, and a segment whose ends lie on opposite sides of the line always
// reports its crossing, so rays do not slip through the joints. The hit
// point is evaluated on the curve (sides) or on the cap plane (caps) from an
// origin moved next to the text (local_ray.hpp).
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "runtime/geometry/ray3.hpp"

namespace hexant::runtime::geometry {

// One piece of a closed outline: the line p0 -> p2 (control unused) or the
// quadratic Bezier p0, control, p2.
struct TextSegment {
    glm::dvec2 p0{0.0}, control{0.0}, p2{0.0};
    bool quadratic = false;
};

// One character's outline in text space. Build it with make_text_glyph:
// intersect and inside rely on its invariants (every quadratic monotone in
// y, lo/hi containing every point of every segment).
struct TextGlyph {
    std::vector<TextSegment> segments;  // all contours, each closed, in order
    glm::dvec2 lo{0.0}, hi{0.0};        // 2D box of the segments' points (control points included)
    // Informational (the layout's): the translation that placed the font's
    // outline (em units) in text space, the character and its glyph index.
    glm::dvec2 translation{0.0};
    std::uint32_t code = 0;
    unsigned glyph_index = 0;
};

// A list of glyphs that copies share (copy on write): a text's geometry is
// copied for each instant when its thickness moves, its glyphs never are.
class TextGlyphs {
  public:
    std::size_t size() const { return list_->size(); }
    bool empty() const { return list_->empty(); }
    const TextGlyph& operator[](std::size_t i) const { return (*list_)[i]; }
    std::vector<TextGlyph>::const_iterator begin() const { return list_->begin(); }
    std::vector<TextGlyph>::const_iterator end() const { return list_->end(); }
    void push_back(TextGlyph glyph) {
        if (list_.use_count() > 1) list_ = std::make_shared<std::vector<TextGlyph>>(*list_);
        list_->push_back(std::move(glyph));
    }

  private:
    std::shared_ptr<std::vector<TextGlyph>> list_ = std::make_shared<std::vector<TextGlyph>>();
};

struct TextGeometry {
    TextGlyphs glyphs;       // glyphs without segments (spaces) may be present
    double thickness = 1.0;  // caps at z = 0 and z = thickness (see above for <= 0)
};

// A glyph from closed contours, each a list of segments in order (each
// segment's p0 the previous one's p2, the last one's p2 the first one's p0;
// a contour that does not close is closed by a line). Zero-length lines are
// dropped; each quadratic is split at its extreme in y (so that every piece
// is monotone in y); lo/hi are computed.
TextGlyph make_text_glyph(const std::vector<std::vector<TextSegment>>& contours,
                          glm::dvec2 translation = glm::dvec2(0.0));

// Whether the 2D point lies inside the glyph's outline by the even-odd rule
// (half-open in y: a segment counts when exactly one end lies strictly above
// the point's y, and it passes right of the point).
bool inside_outline(const TextGlyph& glyph, glm::dvec2 p);

std::optional<SurfaceHit> intersect(const TextGeometry& text, const Ray3& ray, double s_min,
                                    double s_max);
bool inside(const TextGeometry& text, glm::dvec3 p);
Box3 object_bounds(const TextGeometry& text);
bool surface_may_meet(const TextGeometry& text, const Box3& box);

}  // namespace hexant::runtime::geometry
