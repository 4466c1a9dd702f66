// The blob's time functions: its threshold and its components' centres,
// ends, radii and strengths.
#pragma once

#include <cmath>
#include <vector>

#include "runtime/objects/blob/blob.hpp"
#include "runtime/objects/blob/blob_geometry.hpp"
#include "runtime/objects/model_support.hpp"

namespace hexant::runtime::objects {

class BlobModel {
  public:
    using Geometry = geometry::BlobGeometry;
    static constexpr bool kSolid = true;

    explicit BlobModel(const Blob& blob) : threshold_(blob.threshold) {
        is_static_ = threshold_.is_constant();
        for (std::size_t i = 0; i < blob.kinds.size(); ++i) {
            parts_.push_back({blob.kinds[i], CompiledVector3(blob.a[i]), CompiledVector3(blob.b[i]),
                              CompiledScalar(blob.radii[i]), CompiledScalar(blob.strengths[i])});
            const auto& p = parts_.back();
            is_static_ = is_static_ && p.a.is_constant() && p.b.is_constant() &&
                         p.radius.is_constant() && p.strength.is_constant();
        }
    }

    bool is_static() const { return is_static_; }
    Geometry at(double t) const {
        Geometry g;
        g.threshold = threshold_.at(t);
        g.components.reserve(parts_.size());
        for (const auto& p : parts_)
            // POV-Ray squares the radius: a negative one is its magnitude.
            g.components.push_back(
                {p.kind, p.a.at(t), p.b.at(t), std::fabs(p.radius.at(t)), p.strength.at(t)});
        return g;
    }
    // The union of the components' reaches over t (POV-Ray finds the
    // surface only where some component reaches): a sphere's ball, a
    // cylinder's capsule, which lies within the box of its two end balls.
    IntervalBox box_over(const Interval& t) const {
        IntervalBox box = empty_interval_box();
        for (const auto& p : parts_) {
            const Interval r(0.0, p.radius.over(t).magnitude());
            box = hull(box, ball_box(p.a.over(t), r));
            if (p.kind == geometry::BlobComponent::Kind::cylinder)
                box = hull(box, ball_box(p.b.over(t), r));
        }
        return box;
    }
    // Components that move or change merge and part: the surface may move
    // anywhere within the reaches, so the reaches' box's diagonal bounds it.
    double surface_motion(const Interval& t, const Geometry&) const {
        if (is_static_) return 0.0;
        const IntervalBox box = box_over(t);
        double sum = 0.0;
        for (int i = 0; i < 3; ++i) {
            const double w = box[i].hi - box[i].lo;
            if (!(w >= 0.0)) return 0.0;  // no components
            sum += w * w;
        }
        return std::nextafter(std::sqrt(sum) * (1.0 + 4.0 * 1.1102230246251565e-16),
                              std::numeric_limits<double>::infinity());
    }
    static double volume(const Geometry&) { return -1.0; }

  private:
    struct Part {
        geometry::BlobComponent::Kind kind;
        CompiledVector3 a, b;
        CompiledScalar radius, strength;
    };
    CompiledScalar threshold_;
    std::vector<Part> parts_;
    bool is_static_ = true;
};

}  // namespace hexant::runtime::objects
