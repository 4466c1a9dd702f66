// One shape as an intelligent object: a model (the shape's time functions,
// runtime/objects/*_model.hpp), its motion (transforms and deformations) and
// its texture. The paths are chosen once per call by what the object uses:
//   - static and undeformed: the cached geometry and inverse matrix, one
//     plain ray/shape routine (no tape, no time);
//   - moving, undeformed, ray at one instant: the geometry and matrices at
//     the ray's time, the same routine;
//   - deformed, or a ray that travels in time through a moving object: the
//     ray's curved image in object space, solved by first_hit_on_curve
//     (interval bisection, no root skipped).
#pragma once

#include <algorithm>
#include <limits>
#include <memory>
#include <optional>
#include <utility>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>

#include "runtime/bounds/occupancy_sampling.hpp"
#include "runtime/bounds/ray_box_clip.hpp"
#include "runtime/bounds/swept_bound.hpp"
#include "runtime/geometry/curved_path_root.hpp"
#include "runtime/geometry/offset_ray.hpp"
#include "runtime/motion/motion.hpp"
#include "runtime/motion/normal_transform.hpp"
#include "runtime/objects/intelligent_object.hpp"
#include "runtime/objects/model_support.hpp"
#include "runtime/objects/rigid_bounds.hpp"
#include "runtime/texture/texture_evaluator.hpp"

namespace hexant::runtime {

struct PrimitiveOptions {
    bool inverse = false;    // POV-Ray's `inverse`: inside and outside swapped
    bool no_shadow = false;  // casts no shadow
};

// A kind whose surface lies in one plane at every instant (Model::kFlat).
template <class Model>
constexpr bool is_flat_model() {
    if constexpr (requires { Model::kFlat; })
        return Model::kFlat;
    else
        return false;
}

// A kind whose solid is convex whatever its parameters (Model::kConvex).
template <class Model>
constexpr bool is_convex_model() {
    if constexpr (requires { Model::kConvex; })
        return Model::kConvex;
    else
        return false;
}

template <class Model>
constexpr bool is_unbounded_model() {
    if constexpr (requires { Model::kUnbounded; })
        return Model::kUnbounded;
    else
        return false;
}

// Whether POV-Ray 3.7 maps the kind's surface to (u, v) of its own
// (sphere, box, torus, lathe, sor, mesh: their UVCoord).
template <class Model>
constexpr bool has_uv_mapping() {
    if constexpr (requires { Model::kUvMapping; })
        return Model::kUvMapping;
    else
        return false;
}

template <class Model>
class Primitive final : public IntelligentObject {
  public:
    using Geometry = typename Model::Geometry;
    static constexpr bool kUnbounded = is_unbounded_model<Model>();
    // A model made of parts with bounds of their own (a mesh's hierarchy).
    static constexpr bool kHasPieces = requires(const Model& m) {
        m.pieces([](const IntervalBox&) { return 0; }, [](const IntervalBox&) {});
    };
    // A model whose parts may have textures of their own (a mesh's faces).
    static constexpr bool kHasPartTextures = requires(const Model& m) { m.texture_of(0); };
    // A model that blends its textures by weight at a point (a blob's
    // components).
    static constexpr bool kBlendsTextures = requires(const Model& m) { m.blends_textures(); };

    // `part_textures`: the textures a model's parts name (Model::texture_of),
    // already in world terms.
    Primitive(Model model, const Transform& transform, TextureEvaluator texture,
              PrimitiveOptions options, std::vector<TextureEvaluator> part_textures = {})
        : model_(std::move(model)),
          motion_(transform),
          texture_(std::move(texture)),
          part_textures_(std::move(part_textures)),
          options_(options) {
        moves_ = !model_.is_static() || !motion_.is_static();
        filters_light_ = !texture_.opaque();
        for (const TextureEvaluator& part : part_textures_)
            filters_light_ = filters_light_ || !part.opaque();
        if (model_.is_static()) {
            static_geometry_ = model_.at(0.0);
            if constexpr (!kUnbounded)
                static_object_box_ =
                    objects::to_interval_box(geometry::object_bounds(*static_geometry_));
        }
        if (!moves_) {
            Still still;
            if constexpr (!kUnbounded) {
                still.world_box = world_box_over(Interval(0.0));
                still.reaches = motion_.twist_reaches(static_object_box_, Interval(0.0));
            }
            if (motion_.is_affine()) {
                still.affine = true;
                still.linear = glm::dmat3(motion_.matrix_at(0.0));
                still.normals = NormalMap(still.linear);
            }
            still_ = std::make_unique<const Still>(std::move(still));
        }
    }

    bool bounded() const override { return !kUnbounded; }
    bool solid_bounded() const override { return !kUnbounded && !options_.inverse; }
    bool moves() const override { return moves_; }
    bool deformed() const override { return !motion_.is_affine(); }
    // (An affine map keeps a plane a plane; a deformation bends it.)
    bool flat() const override { return is_flat_model<Model>() && motion_.is_affine(); }
    // (An affine map keeps a convex solid convex; `inverse` turns it out.)
    bool convex() const override {
        return is_convex_model<Model>() && motion_.is_affine() && !options_.inverse;
    }
    bool casts_shadow() const override { return !options_.no_shadow; }
    bool filters_light() const override { return filters_light_; }
    bool casts_full_shadow() const override { return !options_.no_shadow && !filters_light_; }
    const MediaVolume* interior_media() const override { return texture_.media(); }
    RefractiveInterior refractive_interior(double t) const override {
        const void* key = texture_.interior_key();
        const auto dispersion = texture_.dispersion_at(t);
        return {key ? key : static_cast<const void*>(this), texture_.ior_at(t), false,
                dispersion.value, dispersion.samples};
    }

    void bound(const Box4& region, std::vector<SlabBound>& out) const override {
        if constexpr (kUnbounded) return;
        if (region.is_empty()) return;
        if constexpr (kHasPieces) {
            bound_by_pieces(region, out);
            return;
        }
        append_rigid_bounds(
            region, moves_, moves_ ? IntervalBox{} : still_->world_box,
            [this](const Interval& t) { return world_box_over(t); }, out);
    }

    Box4 box_over(const Interval& t) const override {
        if constexpr (kUnbounded) return Box4::empty();
        if (t.is_empty()) return Box4::empty();
        return box_over_time(moves_ ? world_box_over(t) : still_->world_box, t);
    }

    // A rigid shape on an affine motion: rigid_bounds.hpp's.
    std::optional<ChordBound> chord_bound_over(const Interval& t) const override {
        if constexpr (kUnbounded) return std::nullopt;
        if (!moves_ || !model_.is_static() || !motion_.is_affine() || !(t.lo <= t.hi))
            return std::nullopt;
        return rigid_chord_bound(motion_, static_object_box_, t);
    }

    Box4 placed_box_at(double t) const override {
        if constexpr (kUnbounded) return Box4::empty();
        if (!moves_ || !model_.is_static() || !motion_.is_affine()) return box_over(Interval(t));
        const AffineMap<double> map = motion_.map_at(t);
        IntervalBox world;
        // A model may know its own shape's box under a map (a sphere's is
        // tighter than its object box's image, which a turn makes up to
        // sqrt(3) times wider).
        if constexpr (requires { Model::placed_box(*static_geometry_, map); })
            world = Model::placed_box(*static_geometry_, map);
        else
            world = map.apply(static_object_box_);
        return {Event(world[0].lo, world[1].lo, world[2].lo, t),
                Event(world[0].hi, world[1].hi, world[2].hi, t)};
    }

    std::optional<ObjectHit> intersect(const Ray4& ray, double s_min, double s_max) const override {
        if (!(s_min < s_max)) return std::nullopt;
        const bool one_instant = ray.direction.w == 0.0 || !moves_;
        if (motion_.is_affine() && (one_instant || kUnbounded))
            return intersect_affine(ray, s_min, s_max, motion_);
        if (one_instant && !motion_.is_static()) {
            // A ray at one instant sees the motion frozen there: no time
            // function is evaluated per piece of the curved search, and a
            // deformation that is none at this instant costs nothing.
            const Motion frozen = motion_.at_instant(ray.origin.w);
            if (frozen.is_affine()) return intersect_affine(ray, s_min, s_max, frozen);
            return intersect_curved(ray, s_min, s_max, frozen);
        }
        return intersect_curved(ray, s_min, s_max, motion_);
    }

    glm::dmat3 to_world_linear_at(const glm::dvec3& object_point, double t) const override {
        return motion_.is_affine() ? glm::dmat3(motion_.matrix_at(t))
                                   : motion_.jacobian_at(object_point, t);
    }

    SurfacePoint complete(const Ray4& ray, const ObjectHit& hit) const override {
        const double t = hit.event.w;
        // (An object that never moves and is not deformed has its map and
        // its normals' map already: the same products, formed once.)
        const NormalMap* fixed_normals =
            !hit.has_linear && still_ && still_->affine ? &still_->normals : nullptr;
        const glm::dmat3 linear = hit.has_linear  ? hit.to_world_linear
                                  : fixed_normals ? still_->linear
                                                  : to_world_linear_at(hit.object_point, t);
        const auto to_world_normal = [&](const glm::dvec3& n, const glm::dvec3& fallback) {
            return fixed_normals ? fixed_normals->apply(n, fallback)
                                 : transform_normal(linear, n, fallback);
        };
        glm::dvec3 facing = -glm::dvec3(ray.direction);
        const double length = glm::length(facing);
        facing = length > 0.0 && std::isfinite(length) ? facing / length : glm::dvec3(0, 1, 0);
        SurfacePoint p;
        p.event = hit.event;
        // The point's error in the world, for the one hit that is shaded.
        if (hit.object_error != glm::dvec3(0.0))
            p.error = geometry::world_error(linear, hit.object_point, glm::dvec3(hit.event),
                                            hit.object_error);
        p.geometric_normal = to_world_normal(hit.object_normal, facing);
        // (Only a smooth triangle's shading normal differs from its own. A
        // kind that blends its normals in the world, as POV-Ray's smooth
        // height field, forms it here, where the map to the world is known.)
        glm::dvec3 object_shading = hit.object_shading_normal;
        if constexpr (requires(const Model& m) {
                          m.world_shading_normal(hit.object_point, linear);
                      }) {
            if (const auto n = model_.world_shading_normal(hit.object_point, linear))
                object_shading = *n;
        }
        p.shading_normal = object_shading == hit.object_normal
                               ? p.geometric_normal
                               : to_world_normal(object_shading, p.geometric_normal);
        if (hit.flipped) {
            p.geometric_normal = -p.geometric_normal;
            p.shading_normal = -p.shading_normal;
        }
        // The surface's (u, v) for uv_mapping: a kind's own where POV-Ray
        // 3.7 gives it one (Model::kUvMapping; a model may leave it to be
        // formed here, for the one hit that is shaded), else the world
        // point's x and y (POV-Ray's ObjectBase::UVCoord).
        if constexpr (has_uv_mapping<Model>()) {
            if constexpr (requires { Model::uv(hit.object_normal); })
                p.uv = Model::uv(hit.object_normal);
            else
                p.uv = hit.uv;
        } else {
            p.uv = glm::dvec2(hit.event.x, hit.event.y);
        }
        p.texture = &texture_;
        if constexpr (kHasPartTextures) {
            const int k = model_.texture_of(hit.part);
            if (k >= 0 && static_cast<std::size_t>(k) < part_textures_.size())
                p.texture = &part_textures_[k];
        }
        if constexpr (kBlendsTextures) {
            if (model_.blends_textures()) {
                std::vector<std::pair<int, double>> weights;
                if (static_geometry_)
                    model_.texture_weights(*static_geometry_, hit.object_point, weights);
                else
                    model_.texture_weights(model_.at(t), hit.object_point, weights);
                p.blended = true;
                p.blend.reserve(weights.size());
                for (const auto& [k, w] : weights)
                    p.blend.push_back({k >= 0 && static_cast<std::size_t>(k) < part_textures_.size()
                                           ? &part_textures_[k]
                                           : &texture_,
                                       w});
            }
        }
        // Met from inside (POV-Ray's normaldirection > 0, trace.cpp): the
        // interior texture, over a face's own too (Mesh::Determine_Textures).
        if (const TextureEvaluator* inside = texture_.interior_texture())
            if (glm::dot(p.shading_normal, glm::dvec3(ray.direction)) > 0.0) p.texture = inside;
        return p;
    }

    bool inside(const Event& event) const override {
        if constexpr (!Model::kSolid) {
            return false;  // flat shapes have no inside, `inverse` or not
        } else {
            const double t = event.w;
            const glm::dvec3 p = to_object(glm::dvec3(event), t);
            const bool in = static_geometry_ ? geometry::inside(*static_geometry_, p)
                                             : geometry::inside(model_.at(t), p);
            return in != options_.inverse;
        }
    }

    double occupancy(const Box4& region) const override {
        if constexpr (!Model::kSolid) return 0.0;
        if (region.is_empty() || !(region.volume() > 0.0)) return 0.0;
        const auto inside_at = [this](const Event& e) { return inside(e); };
        if (options_.inverse || kUnbounded) return sampled_occupancy(region, inside_at);
        const IntervalBox world = world_box_over(region.time());
        const Box4 near = piece_box(world, region.time(), region);
        if (near.is_empty()) return 0.0;
        const double share = near.volume() / region.volume();
        if (!moves_ && motion_.is_affine() && contains_box(region, world)) {
            // Exact: the whole solid lies in the region at every instant.
            const double volume = Model::volume(*static_geometry_);
            if (volume >= 0.0) {
                const double det = std::fabs(glm::determinant(glm::dmat3(motion_.matrix_at(0.0))));
                const glm::dvec4 e = region.hi - region.lo;
                return std::clamp(volume * det / (e.x * e.y * e.z), 0.0, 1.0);
            }
        }
        if (!(near.volume() > 0.0)) return 0.0;
        return share * sampled_occupancy(near, inside_at);
    }

  private:
    // Does the region hold the whole world box in space?
    static bool contains_box(const Box4& region, const IntervalBox& world) {
        for (int i = 0; i < 3; ++i)
            if (world[i].lo < region.lo[i] || world[i].hi > region.hi[i]) return false;
        return true;
    }

    // A conservative world box of the surface over every instant of t.
    IntervalBox world_box_over(const Interval& t) const {
        const IntervalBox object_box = model_.is_static() ? static_object_box_ : model_.box_over(t);
        return motion_.world_box(object_box, t);
    }

    glm::dvec3 to_object(const glm::dvec3& p, double t) const {
        if (motion_.is_identity()) return p;
        if (motion_.is_affine()) return glm::dvec3(motion_.inverse_at(t) * glm::dvec4(p, 1.0));
        const auto q = motion_.template to_object<double>({p.x, p.y, p.z}, t);
        return {q[0], q[1], q[2]};
    }

    glm::dvec3 to_world(const glm::dvec3& p, double t) const {
        if (motion_.is_identity()) return p;
        if (motion_.is_affine()) return glm::dvec3(motion_.matrix_at(t) * glm::dvec4(p, 1.0));
        const auto q = motion_.template to_world<double>({p.x, p.y, p.z}, t);
        return {q[0], q[1], q[2]};
    }

    // `to_world_at` maps the surface point to the world at the hit's time.
    template <class ToWorld>
    ObjectHit make_hit(const Ray4& ray, double s, const geometry::SurfaceHit& surface,
                       ToWorld&& to_world_at) const {
        ObjectHit hit;
        hit.s = s;
        const double t = ray.origin.w + s * ray.direction.w;
        // The world point from the surface point (exact to the surface's own
        // ulps), not from the ray, whose origin may lie far away.
        hit.event = Event(to_world_at(surface.point, t), t);
        hit.object = this;
        hit.object_point = surface.point;
        hit.object_error = surface.error;
        hit.object_normal = surface.normal;
        hit.object_shading_normal = surface.shading_normal;
        hit.uv = surface.uv;
        hit.part = surface.part;
        hit.flipped = options_.inverse;
        return hit;
    }

    // `motion` is motion_, or motion_ frozen at the ray's instant.
    std::optional<ObjectHit> intersect_affine(const Ray4& ray, double s_min, double s_max,
                                              const Motion& motion) const {
        const double t = ray.origin.w;
        geometry::Ray3 local{glm::dvec3(ray.origin), glm::dvec3(ray.direction)};
        const auto find = [&]() {
            return static_geometry_ ? geometry::intersect(*static_geometry_, local, s_min, s_max)
                                    : geometry::intersect(model_.at(t), local, s_min, s_max);
        };
        if (motion.is_identity()) {
            const auto surface = find();
            if (!surface) return std::nullopt;
            return make_hit(ray, surface->s, *surface,
                            [](const glm::dvec3& p, double) { return p; });
        }
        // The ray is at one instant (or the object does not move): one
        // placement serves the ray and the hit.
        const Motion::Placement placement = motion.placement_at(t);
        local.origin = glm::dvec3(placement.to_object * glm::dvec4(local.origin, 1.0));
        local.direction = glm::dmat3(placement.to_object) * local.direction;
        const auto surface = find();
        if (!surface) return std::nullopt;
        ObjectHit hit = make_hit(ray, surface->s, *surface, [&](const glm::dvec3& p, double) {
            return glm::dvec3(placement.to_world * glm::dvec4(p, 1.0));
        });
        if (!motion.is_static()) {
            hit.to_world_linear = glm::dmat3(placement.to_world);
            hit.has_linear = true;
        }
        return hit;
    }

    // The most times a chord's hit on a surface that changes along the ray
    // is solved again at the hit's own instant (chord_hit below): a
    // contraction by v / c per step meets its fixed point in the doubles
    // long before, unless the surface outruns light.
    static constexpr int kMostRefinements = 40;

    // The ray's image in object space is a curve: the deformation bends it,
    // or the ray's time runs along it through a moving frame.
    std::optional<ObjectHit> intersect_curved(const Ray4& ray, double s_min, double s_max,
                                              const Motion& motion) const {
        const glm::dvec3 o(ray.origin), d(ray.direction);
        const double ow = ray.origin.w, dw = ray.direction.w;
        const auto time_over = [&](const Interval& s) {
            return dw == 0.0 ? Interval(ow) : Interval(ow) + s * Interval(dw);
        };
        // Only a finite stretch of time can be bounded: a ray travelling in
        // time needs a finite segment (the tracer's cells give one).
        const Interval ray_time = time_over(Interval(s_min, s_max));
        if (!std::isfinite(ray_time.lo) || !std::isfinite(ray_time.hi)) return std::nullopt;
        double a = s_min, b = s_max;
        if (!clip_ray_to_box(o, d, world_box_over(ray_time), a, b)) return std::nullopt;
        const IntervalBox object_box =
            model_.is_static() ? static_object_box_ : model_.box_over(ray_time);
        const double size = largest_width(object_box);
        if (!std::isfinite(size)) return std::nullopt;

        // The surface is one fixed geometry unless it changes along the ray.
        const bool fixed = model_.is_static() || dw == 0.0;
        std::optional<Geometry> fixed_geometry;
        if (fixed) fixed_geometry = static_geometry_ ? *static_geometry_ : model_.at(ow);

        // A twisted object's surface stays within some distance of the
        // twist's axis: a piece of the path beyond it is dropped at once
        // (its box, turned into object space, would come out around the axis).
        // (Fixed for an object that never changes: computed once, then.)
        std::vector<double> changing_reaches;
        if (moves_) changing_reaches = motion.twist_reaches(object_box, ray_time);
        // (An unbounded object keeps none: it has no reaches, as a moving one
        // that was given none.)
        const std::vector<double>& reaches = moves_ || !still_ ? changing_reaches : still_->reaches;
        const auto box_over = [&](const Interval& s) {
            const std::array<Interval, 3> world{Interval(o.x) + s * Interval(d.x),
                                                Interval(o.y) + s * Interval(d.y),
                                                Interval(o.z) + s * Interval(d.z)};
            const auto q = motion.to_object_within(world, time_over(s), reaches);
            if (!q) return geometry::Box3::nowhere();
            const auto& r = *q;
            return geometry::Box3{{r[0].lo, r[1].lo, r[2].lo}, {r[0].hi, r[1].hi, r[2].hi}};
        };
        const auto point_at = [&](double s) {
            const auto q = motion.template to_object<double>(
                {o.x + s * d.x, o.y + s * d.y, o.z + s * d.z}, ow + s * dw);
            return glm::dvec3(q[0], q[1], q[2]);
        };
        const auto may_meet = [&](const geometry::Box3& box, const Interval& s) {
            if (box.is_nowhere()) return false;
            if (fixed) return geometry::surface_may_meet(*fixed_geometry, box);
            // The surface at the piece's middle time, and the box widened by
            // how far the surface moves during the piece.
            const Interval t = time_over(s);
            const Geometry mid = model_.at(t.mid());
            const double r = model_.surface_motion(t, mid);
            const glm::dvec3 widen(r);
            return geometry::surface_may_meet(mid, geometry::Box3{box.lo - widen, box.hi + widen});
        };
        const auto chord_hit = [&](const geometry::Ray3& chord, double u0, double u1,
                                   const Interval& s) {
            if (fixed) return geometry::intersect(*fixed_geometry, chord, u0, u1);
            // The surface at the piece's middle instant, then again at the
            // instant of the hit that gives, until the hit and its instant
            // agree: the event must lie on the surface as it stands at the
            // event's own time, or a ray leaving it (a shadow ray running
            // back in time) meets it again just behind its start, as it
            // stood a fraction of a piece earlier, and shadows itself. Each
            // step shrinks the disagreement by about (v / c) / cos, the
            // surface's speed over light's against the incidence.
            auto hit = geometry::intersect(model_.at(time_over(s).mid()), chord, u0, u1);
            double used = std::numeric_limits<double>::quiet_NaN();
            for (int refine = 0; hit && refine < kMostRefinements; ++refine) {
                const double u = std::clamp(hit->s, 0.0, 1.0);
                if (u == used) break;
                used = u;
                hit = geometry::intersect(model_.at(ow + (s.lo + u * (s.hi - s.lo)) * dw), chord,
                                          u0, u1);
            }
            return hit;
        };
        const auto found = first_hit_on_curve(a, b, size, box_over, point_at, may_meet, chord_hit);
        if (!found || !(found->s > s_min && found->s < s_max)) return std::nullopt;
        return make_hit(ray, found->s, found->surface, [&](const glm::dvec3& p, double t) {
            const auto q = motion.template to_world<double>({p.x, p.y, p.z}, t);
            return glm::dvec3(q[0], q[1], q[2]);
        });
    }

    // The paper's star cluster: where the region is small against the
    // object, the boxes of the model's parts that meet it (a mesh's
    // hierarchy nodes, descended while a node crosses the region's edge and
    // is more than half the region's size, at most kMaxPieces of them),
    // each swept over the region's time.
    void bound_by_pieces(const Box4& region, std::vector<SlabBound>& out) const {
        constexpr std::size_t kMaxPieces = 32;
        const Interval time = moves_ ? region.time() : Interval(0.0);
        const glm::dvec4 extent = region.hi - region.lo;
        const double size = std::max({extent.x, extent.y, extent.z});
        std::vector<IntervalBox> chosen;
        model_.pieces(
            [&](const IntervalBox& box) {
                const IntervalBox world = motion_.world_box(box, time);
                if (piece_box(world, region.time(), region).is_empty()) return 0;
                // A part wholly inside the region gains nothing from its
                // children; one across its edge does, while large.
                if (contains_box(region, world) || largest_width(world) <= 0.5 * size ||
                    chosen.size() >= kMaxPieces)
                    return 1;
                return 2;
            },
            [&](const IntervalBox& box) { chosen.push_back(box); });
        std::vector<Box4> pieces;
        for (const auto& box : chosen) {
            pieces.clear();
            if (moves_)
                swept_pieces(
                    region, region.time(), 0,
                    [&](const Interval& t) { return motion_.world_box(box, t); }, pieces);
            else
                pieces.push_back(piece_box(motion_.world_box(box, time), region.time(), region));
            append_swept_bounds(pieces, region, out);  // a bound per part
        }
    }

    Model model_;
    Motion motion_;
    TextureEvaluator texture_;
    bool filters_light_ = false;
    std::vector<TextureEvaluator> part_textures_;
    PrimitiveOptions options_;
    bool moves_ = false;
    std::optional<Geometry> static_geometry_;
    IntervalBox static_object_box_{};
    // What an object that never changes keeps: its world box, and
    // motion_.twist_reaches over it (bounded kinds); undeformed, its map to
    // the world's linear part and that map's action on normals. Apart, so
    // that a moving object (10^5 of them in the scale scene) does not carry
    // them unused.
    struct Still {
        IntervalBox world_box{};
        std::vector<double> reaches;
        bool affine = false;
        glm::dmat3 linear{1.0};
        NormalMap normals;
    };
    std::unique_ptr<const Still> still_;  // when !moves_
};

}  // namespace hexant::runtime
