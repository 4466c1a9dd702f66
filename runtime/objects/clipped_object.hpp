// An object clipped by others: POV-Ray's clipped_by { OBJECTS }. Its
// surface is kept where it lies inside every clipping object's solid; the
// clipping objects add no surface of their own (unlike an intersection),
// so a clipped solid is open where it is cut. inside() is the object's and
// every clipping object's, as POV-Ray's Inside_Object tests the Clip list.
// The clipping objects carry the object's transform already (the factory
// builds them under it, runtime/objects/object_factory.cpp); the members
// of a clipped union split apart share them.
#pragma once

#include <memory>
#include <vector>

#include "runtime/objects/intelligent_object.hpp"

namespace hexant::runtime {

class ClippedObject final : public IntelligentObject {
  public:
    using Limits = std::shared_ptr<const std::vector<IntelligentObjectPtr>>;
    ClippedObject(IntelligentObjectPtr object, Limits clips);

    // Bounded where the object is, or where a clipping object's solid is:
    // the kept surface lies inside each clipping solid.
    bool bounded() const override { return bounded_; }
    bool solid_bounded() const override;
    void bound(const Box4& region, std::vector<SlabBound>& out) const override;
    Box4 box_over(const Interval& t) const override;
    std::optional<ChordBound> chord_bound_over(const Interval& t) const override;
    Box4 placed_box_at(double t) const override;
    std::optional<ObjectHit> intersect(const Ray4& ray, double s_min, double s_max) const override;
    SurfacePoint complete(const Ray4& ray, const ObjectHit& hit) const override {
        return object_->complete(ray, hit);
    }
    bool inside(const Event& event) const override;
    double occupancy(const Box4& region) const override;
    bool moves() const override { return moves_; }
    bool deformed() const override { return deformed_; }
    bool casts_shadow() const override { return object_->casts_shadow(); }
    bool filters_light() const override { return object_->filters_light(); }
    bool casts_full_shadow() const override { return object_->casts_full_shadow(); }
    const MediaVolume* interior_media() const override { return object_->interior_media(); }
    // (POV-Ray keeps a clipped union whole: its interior is entered once
    // however many of its members hold the eye.)
    RefractiveInterior refractive_interior(double t) const override {
        RefractiveInterior r = object_->refractive_interior(t);
        r.once = true;
        return r;
    }

  private:
    bool kept(const Event& event) const;
    // A clipping object whose solid is bounded (null when none is), for
    // an object of no extent of its own.
    const IntelligentObject* bounding_clip() const;

    IntelligentObjectPtr object_;
    Limits clips_;
    bool bounded_ = false, moves_ = false, deformed_ = false;
};

}  // namespace hexant::runtime
