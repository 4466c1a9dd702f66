#include "runtime/objects/lifetime_object.hpp"

#include <algorithm>

namespace hexant::runtime {

LifetimeObject::LifetimeObject(IntelligentObjectPtr inner, Lifetime lifetime,
                               bool inside_when_absent)
    : inner_(std::move(inner)),
      lifetime_(std::move(lifetime)),
      inside_when_absent_(inside_when_absent) {}

void LifetimeObject::bound(const Box4& region, std::vector<SlabBound>& out) const {
    for (const Interval& piece : lifetime_.within(region.time())) {
        Box4 part = region;
        part.lo.w = piece.lo;
        part.hi.w = piece.hi;
        inner_->bound(part, out);
    }
}

Box4 LifetimeObject::box_over(const Interval& t) const {
    Box4 box = Box4::empty();
    for (const Interval& piece : lifetime_.within(t)) box.extend(inner_->box_over(piece));
    return box;
}

std::optional<IntelligentObject::ChordBound> LifetimeObject::chord_bound_over(
    const Interval& t) const {
    // Chords join placed boxes at both ends: only across time it lives
    // through whole.
    if (!lifetime_.holds_all(t)) return std::nullopt;
    return inner_->chord_bound_over(t);
}

Box4 LifetimeObject::placed_box_at(double t) const {
    return lifetime_.contains(t) ? inner_->placed_box_at(t) : Box4::empty();
}

template <class F>
void LifetimeObject::for_each_span(const Ray4& ray, double s_min, double s_max, F f) const {
    const double w0 = ray.origin.w, dw = ray.direction.w;
    if (dw == 0.0) {
        // A ray at one instant (the renderer's, with infinite light speed).
        if (lifetime_.contains(w0)) f(s_min, s_max);
        return;
    }
    // Time runs along the ray: the parameters whose times fall in each
    // piece, in the order the ray meets them.
    const std::vector<Interval>& pieces = lifetime_.pieces();
    const auto span = [&](const Interval& piece) {
        double a = (piece.lo - w0) / dw, b = (piece.hi - w0) / dw;
        if (a > b) std::swap(a, b);
        // Widened by a step each way: the division rounds, and a hit at a
        // piece's end must not fall between two spans (the object's own
        // answer there is tested against its time below).
        return std::pair{std::max(s_min, interval_detail::next_down(a)),
                         std::min(s_max, interval_detail::next_up(b))};
    };
    const std::size_t n = pieces.size();
    for (std::size_t k = 0; k < n; ++k) {
        const auto [lo, hi] = span(pieces[dw > 0.0 ? k : n - 1 - k]);
        if (lo < hi && f(lo, hi)) return;
    }
}

std::optional<ObjectHit> LifetimeObject::intersect(const Ray4& ray, double s_min,
                                                   double s_max) const {
    if (lifetime_.is_always()) return inner_->intersect(ray, s_min, s_max);
    std::optional<ObjectHit> found;
    for_each_span(ray, s_min, s_max, [&](double lo, double hi) {
        auto hit = inner_->intersect(ray, lo, hi);
        // (A span widened past its piece: the hit's own time decides.)
        while (hit && !lifetime_.contains(hit->event.w)) hit = inner_->intersect(ray, hit->s, hi);
        found = hit;
        return found.has_value();
    });
    return found;
}

bool LifetimeObject::occluded(const Ray4& ray, double s_min, double s_max) const {
    if (ray.direction.w == 0.0)
        return lifetime_.contains(ray.origin.w) && inner_->occluded(ray, s_min, s_max);
    return intersect(ray, s_min, s_max).has_value();
}

bool LifetimeObject::inside(const Event& event) const {
    return lifetime_.contains(event.w) ? inner_->inside(event) : inside_when_absent_;
}

double LifetimeObject::occupancy(const Box4& region) const {
    const Interval t = region.time();
    const double whole = t.width();
    if (!(whole > 0.0)) return lifetime_.contains(t.lo) ? inner_->occupancy(region) : 0.0;
    double alive = 0.0;
    for (const Interval& piece : lifetime_.within(t)) alive += piece.width();
    return inner_->occupancy(region) * std::clamp(alive / whole, 0.0, 1.0);
}

}  // namespace hexant::runtime
