// An object with bounded_by, as POV-Ray 3.7 renders it (its parser's
// Parse_Object_Mods and Link_To_Frame, core/scene/object.cpp's
// Ray_In_Bound), with its default Remove_Bounds=on:
//
//   - the object's bounding box becomes the box of its bounds (the common
//     part of the boxes of those not `inverse`) where that is smaller in
//     volume, and a ray that misses that box never meets the object (the
//     box gate);
//   - where the bounds are kept (a CSG object, a poly or a text, and any
//     object inside a CSG or a clip), a ray that meets the object is also
//     one that meets every bounding object, or starts inside it (the exact
//     gate); elsewhere POV-Ray removes them ("Unnecessary bounding object
//     removed") and the box gate alone is left.
//
// The object's hits are then taken wherever they lie, so a bound smaller
// than its object cuts it along what each ray sees: a plane bounded by a
// sphere shows the sphere's box filled with the plane, near or far. A bound
// that holds its object changes nothing. Each gate is a property of the
// whole ray (from its origin on, at its own time), not of the stretch a
// query asks about, so every query along one ray agrees. Bounds, boxes and
// motion are the object's own: its hits are its own, only fewer.
//
// The bounding objects carry the object's transform (the factory builds
// them under it); the members of a bounded union split apart share them.
#pragma once

#include <memory>
#include <vector>

#include "runtime/objects/intelligent_object.hpp"

namespace hexant::runtime {

class BoundedObject final : public IntelligentObject {
  public:
    using Limits = std::shared_ptr<const std::vector<IntelligentObjectPtr>>;
    // `exact`: whether POV-Ray keeps the bounds (the exact gate). `box_always`:
    // use the box gate whatever the object's own box (a member of a
    // union kept whole for a member of no finite extent: the union's box
    // is unbounded).
    BoundedObject(IntelligentObjectPtr object, Limits bounds, bool exact, bool box_always);

    bool bounded() const override { return object_->bounded(); }
    bool solid_bounded() const override { return object_->solid_bounded(); }
    void bound(const Box4& region, std::vector<SlabBound>& out) const override {
        object_->bound(region, out);
    }
    Box4 box_over(const Interval& t) const override { return object_->box_over(t); }
    std::optional<ChordBound> chord_bound_over(const Interval& t) const override {
        return object_->chord_bound_over(t);
    }
    Box4 placed_box_at(double t) const override { return object_->placed_box_at(t); }
    std::optional<ObjectHit> intersect(const Ray4& ray, double s_min, double s_max) const override;
    bool occluded(const Ray4& ray, double s_min, double s_max) const override;
    SurfacePoint complete(const Ray4& ray, const ObjectHit& hit) const override {
        return object_->complete(ray, hit);
    }
    // POV-Ray's Inside_Object does not look at the bounds.
    bool inside(const Event& event) const override { return object_->inside(event); }
    double occupancy(const Box4& region) const override { return object_->occupancy(region); }
    bool moves() const override { return object_->moves(); }
    bool deformed() const override { return object_->deformed(); }
    bool casts_shadow() const override { return object_->casts_shadow(); }
    bool filters_light() const override { return object_->filters_light(); }
    bool casts_full_shadow() const override { return object_->casts_full_shadow(); }
    const MediaVolume* interior_media() const override { return object_->interior_media(); }
    RefractiveInterior refractive_interior(double t) const override {
        return object_->refractive_interior(t);
    }

  private:
    // The box gate at time t: empty optional where there is none.
    struct Gate {
        bool used = false;
        Box4 box;
    };
    Gate gate_at(double t) const;
    bool passes(const Ray4& ray) const;

    IntelligentObjectPtr object_;
    Limits bounds_;
    bool exact_, box_always_;
    bool moves_;       // the object or a bound
    Gate still_gate_;  // gate_at(0) where nothing moves
};

}  // namespace hexant::runtime
