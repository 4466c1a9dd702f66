// The text's time functions: its thickness (the glyphs are fixed when the
// scene is read).
#pragma once

#include <algorithm>

#include "runtime/objects/model_support.hpp"
#include "runtime/objects/text/text.hpp"
#include "runtime/objects/text/text_geometry.hpp"

namespace hexant::runtime::objects {

class TextModel {
  public:
    using Geometry = geometry::TextGeometry;
    static constexpr bool kSolid = true;

    explicit TextModel(const Text& text) : glyphs_(text.glyphs), thickness_(text.thickness) {
        outline_ = empty_interval_box();
        for (const auto& glyph : glyphs_) {
            if (glyph.segments.empty()) continue;
            outline_[0] = hull(outline_[0], Interval(glyph.lo.x, glyph.hi.x));
            outline_[1] = hull(outline_[1], Interval(glyph.lo.y, glyph.hi.y));
        }
    }

    bool is_static() const { return thickness_.is_constant(); }
    Geometry at(double t) const { return {glyphs_, thickness_.at(t)}; }
    // The outlines' box, between z = 0 and every thickness over t.
    IntervalBox box_over(const Interval& t) const {
        if (outline_[0].is_empty()) return empty_interval_box();
        const Interval depth = thickness_.over(t);
        return {outline_[0], outline_[1],
                Interval(std::min(0.0, depth.lo), std::max(0.0, depth.hi))};
    }
    // Only the cap at z = thickness moves.
    double surface_motion(const Interval& t, const Geometry& mid) const {
        return deviation(thickness_, t, mid.thickness);
    }
    // Outlines of curves under the even-odd rule: sampled by the caller.
    static double volume(const Geometry&) { return -1.0; }

  private:
    geometry::TextGlyphs glyphs_;
    CompiledScalar thickness_;
    IntervalBox outline_;
};

}  // namespace hexant::runtime::objects
