#include "runtime/objects/bounded_object.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace hexant::runtime {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Volume of a box's space part; infinite for an unbounded one.
double volume(const Box4& b) {
    if (b.is_empty()) return 0.0;
    double v = 1.0;
    for (int i = 0; i < 3; ++i) v *= b.hi[i] - b.lo[i];
    return v;
}

// Does the ray, from its origin on, meet the box's space part (the slab
// test of POV-Ray's Intersect_BBox)?
bool meets(const Ray4& ray, const Box4& box) {
    double lo = 0.0, hi = kInf;
    for (int i = 0; i < 3; ++i) {
        const double o = ray.origin[i], d = ray.direction[i];
        if (d == 0.0) {
            if (!(o >= box.lo[i] && o <= box.hi[i])) return false;
            continue;
        }
        double a = (box.lo[i] - o) / d, b = (box.hi[i] - o) / d;
        if (a > b) std::swap(a, b);
        lo = std::max(lo, a);
        hi = std::min(hi, b);
        if (!(lo <= hi)) return false;
    }
    return true;
}

}  // namespace

BoundedObject::BoundedObject(IntelligentObjectPtr object, Limits bounds, bool exact,
                             bool box_always)
    : object_(std::move(object)),
      bounds_(std::move(bounds)),
      exact_(exact),
      box_always_(box_always) {
    moves_ = object_->moves() || std::any_of(bounds_->begin(), bounds_->end(),
                                             [](const auto& b) { return b->moves(); });
    if (!moves_) still_gate_ = gate_at(0.0);
}

BoundedObject::Gate BoundedObject::gate_at(double t) const {
    Gate gate;
    bool any = false;
    Box4 box;
    for (const auto& b : *bounds_) {
        // An unbounded or `inverse` bound has no box of its own (POV-Ray
        // skips inverted ones, and a plane's box is everything).
        if (!b->solid_bounded()) continue;
        const Box4 mine = b->box_over(Interval(t));
        box = any ? box.intersection(mine) : mine;
        any = true;
    }
    if (!any) return gate;
    const double own = object_->bounded() ? volume(object_->box_over(Interval(t))) : kInf;
    gate.used = box_always_ || volume(box) < own;
    gate.box = box;
    return gate;
}

bool BoundedObject::passes(const Ray4& ray) const {
    const Gate gate = moves_ ? gate_at(ray.origin.w) : still_gate_;
    if (gate.used && !meets(ray, gate.box)) return false;
    if (!exact_) return true;
    for (const auto& bound : *bounds_)
        if (!bound->occluded(ray, 0.0, kInf) && !bound->inside(ray.origin)) return false;
    return true;
}

std::optional<ObjectHit> BoundedObject::intersect(const Ray4& ray, double s_min,
                                                  double s_max) const {
    if (!passes(ray)) return std::nullopt;
    return object_->intersect(ray, s_min, s_max);
}

bool BoundedObject::occluded(const Ray4& ray, double s_min, double s_max) const {
    return passes(ray) && object_->occluded(ray, s_min, s_max);
}

}  // namespace hexant::runtime
