// An instance (Embree's instancing, pbrt-v4's TransformedPrimitive): the
// members of a union that stand still inside it, built once in the union's
// own space under one static hierarchy of their own (box_hierarchy.hpp) and
// carried through the world by the union's moving transform. The spacetime
// hierarchy sees one intelligent object, swept as one rigid box, instead of
// every member swept by the whole motion; a ray at one instant is moved
// into the union's space by the placement at its time, and the members
// answer there.
//
// The factory (object_factory.cpp) builds one only where nothing about the
// members changes with time but their textures, the union's transform is
// affine and moves, and light is instant (a ray that travels in time would
// see the members along a curve). A member's hit keeps it: `complete`
// composes the placement with the member's own map, so the shading, the
// textures (already in world terms) and the point's error come out as if the
// member had been placed in the world itself.
#pragma once

#include <vector>

#include "runtime/motion/motion.hpp"
#include "runtime/objects/box_hierarchy.hpp"
#include "runtime/objects/intelligent_object.hpp"
#include "runtime/objects/model_support.hpp"

namespace hexant::runtime {

class InstanceObject final : public IntelligentObject {
  public:
    // `members`: bounded objects that do not move, in the union's space;
    // `placement`: the union's space to the world, affine. Throws
    // std::invalid_argument otherwise.
    InstanceObject(std::vector<IntelligentObjectPtr> members, const Transform& placement);

    bool solid_bounded() const override { return solid_bounded_; }
    void bound(const Box4& region, std::vector<SlabBound>& out) const override;
    Box4 box_over(const Interval& t) const override;
    std::optional<ChordBound> chord_bound_over(const Interval& t) const override;
    Box4 placed_box_at(double t) const override;
    // Rays at one instant only (or any ray while the placement stands still):
    // throws std::logic_error for a ray that travels in time through a
    // moving instance, which the factory never builds.
    std::optional<ObjectHit> intersect(const Ray4& ray, double s_min, double s_max) const override;
    bool occluded(const Ray4& ray, double s_min, double s_max) const override;
    SurfacePoint complete(const Ray4& ray, const ObjectHit& hit) const override;
    // Inside any member (a union's inside).
    bool inside(const Event& event) const override;
    double occupancy(const Box4& region) const override;
    bool moves() const override { return !motion_.is_static(); }
    bool deformed() const override { return false; }
    bool casts_shadow() const override { return casts_shadow_; }
    bool filters_light() const override { return filters_light_; }
    bool casts_full_shadow() const override { return full_shadow_; }
    // (Its members share the union's interior: the first member's.)
    const MediaVolume* interior_media() const override;
    RefractiveInterior refractive_interior(double t) const override;

    std::size_t size() const { return members_.size(); }

  private:
    // The ray in the union's space at the ray's instant.
    Ray4 to_members(const Ray4& ray, const Motion::Placement& placement) const;

    std::vector<IntelligentObjectPtr> members_;  // in the hierarchy's leaf order
    objects::BoxHierarchy hierarchy_;
    Motion motion_;
    IntervalBox box_{};  // every member, in the union's space
    bool solid_bounded_ = true;
    bool casts_shadow_ = false;
    bool filters_light_ = false;
    bool full_shadow_ = true;
};

}  // namespace hexant::runtime
