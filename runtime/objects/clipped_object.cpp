#include "runtime/objects/clipped_object.hpp"

#include <algorithm>
#include <optional>
#include <utility>

namespace hexant::runtime {

ClippedObject::ClippedObject(IntelligentObjectPtr object, Limits clips)
    : object_(std::move(object)), clips_(std::move(clips)) {
    bounded_ = object_->bounded() || std::any_of(clips_->begin(), clips_->end(),
                                                 [](const auto& c) { return c->solid_bounded(); });
    moves_ = object_->moves() ||
             std::any_of(clips_->begin(), clips_->end(), [](const auto& c) { return c->moves(); });
    deformed_ = object_->deformed() || std::any_of(clips_->begin(), clips_->end(),
                                                   [](const auto& c) { return c->deformed(); });
}

bool ClippedObject::solid_bounded() const {
    return object_->solid_bounded() ||
           std::any_of(clips_->begin(), clips_->end(),
                       [](const auto& c) { return c->solid_bounded(); });
}

const IntelligentObject* ClippedObject::bounding_clip() const {
    for (const auto& c : *clips_)
        if (c->solid_bounded()) return c.get();
    return nullptr;
}

void ClippedObject::bound(const Box4& region, std::vector<SlabBound>& out) const {
    if (object_->bounded()) {
        object_->bound(region, out);
        return;
    }
    // No extent of its own: the boxes of the bounded clipping solids (a
    // clip's own bound() may hold only its surface's pieces, not the
    // solid inside them).
    if (!bounding_clip() || region.is_empty()) return;
    const Box4 box = box_over(region.time());
    if (box.is_empty()) return;
    SlabBound b = SlabBound::empty();
    b.add(box);
    b.clip(region);
    if (!b.is_empty()) out.push_back(b);
}

// The object's box where it has one, cut by each bounded clipping solid's.
Box4 ClippedObject::box_over(const Interval& t) const {
    std::optional<Box4> box;
    if (object_->bounded()) box = object_->box_over(t);
    for (const auto& c : *clips_) {
        if (!c->solid_bounded()) continue;
        const Box4 b = c->box_over(t);
        box = box ? box->intersection(b) : b;
    }
    return box ? *box : Box4::empty();
}

// Chords follow the object; without an extent of its own, its bounding
// clip's.
std::optional<IntelligentObject::ChordBound> ClippedObject::chord_bound_over(
    const Interval& t) const {
    if (object_->bounded()) return object_->chord_bound_over(t);
    if (const IntelligentObject* clip = bounding_clip()) return clip->chord_bound_over(t);
    return std::nullopt;
}

Box4 ClippedObject::placed_box_at(double t) const {
    if (object_->bounded()) return object_->placed_box_at(t);
    if (const IntelligentObject* clip = bounding_clip()) return clip->placed_box_at(t);
    return box_over(Interval(t));
}

bool ClippedObject::kept(const Event& event) const {
    return std::all_of(clips_->begin(), clips_->end(),
                       [&](const auto& c) { return c->inside(event); });
}

std::optional<ObjectHit> ClippedObject::intersect(const Ray4& ray, double s_min,
                                                  double s_max) const {
    double from = s_min;
    // Along the object's surface events until one lies inside every clip;
    // each step starts strictly after the last hit (as CsgObject's walk).
    for (int guard = 0; guard < 1024; ++guard) {
        auto hit = object_->intersect(ray, from, s_max);
        if (!hit) return std::nullopt;
        if (kept(hit->event)) return hit;
        if (!(hit->s > from)) return std::nullopt;
        from = hit->s;
    }
    return std::nullopt;
}

bool ClippedObject::inside(const Event& event) const {
    return object_->inside(event) && kept(event);
}

double ClippedObject::occupancy(const Box4& region) const {
    double total = object_->occupancy(region);
    for (const auto& c : *clips_) total = std::min(total, c->occupancy(region));
    return total;
}

}  // namespace hexant::runtime
