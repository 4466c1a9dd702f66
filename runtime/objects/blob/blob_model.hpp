// The blob's time functions: its threshold and its components' centres,
// ends, radii, strengths and own transforms.
#pragma once

#include <cmath>
#include <optional>
#include <utility>
#include <vector>

#include "runtime/motion/motion.hpp"
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
                              CompiledScalar(blob.radii[i]), CompiledScalar(blob.strengths[i]),
                              std::nullopt});
            auto& p = parts_.back();
            if (i < blob.transforms.size() && !blob.transforms[i].empty())
                p.motion.emplace(blob.transforms[i]);
            is_static_ = is_static_ && p.a.is_constant() && p.b.is_constant() &&
                         p.radius.is_constant() && p.strength.is_constant() &&
                         (!p.motion || p.motion->is_static());
            texture_of_.push_back(i < blob.texture_index.size() ? blob.texture_index[i] : -1);
        }
        for (const int k : texture_of_) blended_ = blended_ || k >= 0;
    }

    bool is_static() const { return is_static_; }
    Geometry at(double t) const {
        Geometry g;
        g.threshold = threshold_.at(t);
        g.components.reserve(parts_.size());
        for (const auto& p : parts_) {
            // POV-Ray squares the radius: a negative one is its magnitude.
            geometry::BlobComponent c{p.kind, p.a.at(t), p.b.at(t), std::fabs(p.radius.at(t)),
                                      p.strength.at(t)};
            if (p.motion) {
                const Motion::Placement placed = p.motion->placement_at(t);
                c.transformed = true;
                c.to_blob = placed.to_world;
                c.to_component = placed.to_object;
            }
            g.components.push_back(c);
        }
        return g;
    }
    // Whether some component has a texture of its own: then the blob's
    // textures are blended by density (POV-Ray's MULTITEXTURE_FLAG).
    bool blends_textures() const { return blended_; }
    // Component i's texture: an index into the record's textures, or -1
    // for the blob's own.
    const std::vector<int>& texture_of_components() const { return texture_of_; }
    // The textures at object point p and their weights, as POV-Ray's
    // Determine_Textures: each component with a field there lends its
    // texture (k >= 0) or the blob's (-1), weighed by its |field|, the
    // weights then scaled to sum to 1; one below POV-Ray's default
    // adc_bailout (1/255) is left out, as its trace.cpp skips it.
    void texture_weights(const Geometry& g, const glm::dvec3& p,
                         std::vector<std::pair<int, double>>& out) const {
        std::vector<double> density;
        geometry::blob_component_densities(g, p, density);
        double sum = 0.0;
        for (const double d : density) sum += d;
        out.clear();
        if (!(sum > 0.0) || !std::isfinite(sum)) return;
        for (std::size_t i = 0; i < density.size() && i < texture_of_.size(); ++i) {
            const double w = density[i] / sum;
            if (w > 0.0 && !(w < 1.0 / 255.0)) out.emplace_back(texture_of_[i], w);
        }
    }
    // The union of the components' reaches over t (POV-Ray finds the
    // surface only where some component reaches): a sphere's ball, a
    // cylinder's capsule, which lies within the box of its two end balls.
    IntervalBox box_over(const Interval& t) const {
        IntervalBox box = empty_interval_box();
        for (const auto& p : parts_) {
            const Interval r(0.0, p.radius.over(t).magnitude());
            IntervalBox reach = ball_box(p.a.over(t), r);
            if (p.kind == geometry::BlobComponent::Kind::cylinder)
                reach = hull(reach, ball_box(p.b.over(t), r));
            // A transformed component's reach, carried out by its own
            // motion's conservative box over t.
            if (p.motion) reach = p.motion->world_box(reach, t);
            box = hull(box, reach);
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
        std::optional<Motion> motion;  // its own transforms, if any
    };
    CompiledScalar threshold_;
    std::vector<Part> parts_;
    std::vector<int> texture_of_;
    bool is_static_ = true;
    bool blended_ = false;
};

}  // namespace hexant::runtime::objects
