// An intelligent object that exists only during its lifetime (a set of
// time intervals: runtime/time/lifetime.hpp), as an object made under a branch
// whose condition depends on `clock` does. Outside its lifetime it has no
// surface: its bounds are empty there, so the spacetime hierarchy never
// holds it and no ray tests it, and a ray (or a blurred pixel's sample)
// whose time is outside misses it. The switch is exact: a sample at the
// first double of a piece sees the object, one at the double before does
// not.
#pragma once

#include "runtime/objects/intelligent_object.hpp"
#include "runtime/time/lifetime.hpp"

namespace hexant::runtime {

class LifetimeObject final : public IntelligentObject {
  public:
    // `inside_when_absent`: what inside() answers outside the lifetime. An
    // intersection's member that does not exist must not empty the
    // intersection (POV-Ray intersects the members there are): true there;
    // false anywhere else (a union's or a difference's member that does not
    // exist adds or takes away nothing).
    LifetimeObject(IntelligentObjectPtr inner, Lifetime lifetime, bool inside_when_absent);

    const Lifetime& lifetime() const { return lifetime_; }

    // An intersection's member that is absent part of the time does not
    // hold the intersection then: it cannot be the one whose bounds bound
    // the intersection (CsgObject takes its bounded members' bounds), so
    // it answers as an unbounded member does.
    bool bounded() const override { return !inside_when_absent_ && inner_->bounded(); }
    bool solid_bounded() const override { return !inside_when_absent_ && inner_->solid_bounded(); }
    void bound(const Box4& region, std::vector<SlabBound>& out) const override;
    Box4 box_over(const Interval& t) const override;
    std::optional<ChordBound> chord_bound_over(const Interval& t) const override;
    Box4 placed_box_at(double t) const override;
    std::optional<ObjectHit> intersect(const Ray4& ray, double s_min, double s_max) const override;
    bool occluded(const Ray4& ray, double s_min, double s_max) const override;
    SurfacePoint complete(const Ray4& ray, const ObjectHit& hit) const override {
        return inner_->complete(ray, hit);
    }
    bool inside(const Event& event) const override;
    double occupancy(const Box4& region) const override;
    bool moves() const override { return true; }
    bool deformed() const override { return inner_->deformed(); }
    bool casts_shadow() const override { return inner_->casts_shadow(); }
    bool filters_light() const override { return inner_->filters_light(); }
    bool casts_full_shadow() const override { return inner_->casts_full_shadow(); }
    const MediaVolume* interior_media() const override { return inner_->interior_media(); }
    RefractiveInterior refractive_interior(double t) const override {
        return inner_->refractive_interior(t);
    }

  private:
    // Calls f(lo, hi) for each span of the ray's parameter in (s_min, s_max)
    // whose times are in the lifetime, nearest first; stops when f returns
    // true.
    template <class F>
    void for_each_span(const Ray4& ray, double s_min, double s_max, F f) const;

    IntelligentObjectPtr inner_;
    Lifetime lifetime_;
    bool inside_when_absent_;
};

}  // namespace hexant::runtime
