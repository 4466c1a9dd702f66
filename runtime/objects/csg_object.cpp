#include "runtime/objects/csg_object.hpp"

#include <algorithm>
#include <optional>

namespace hexant::runtime {

CsgObject::CsgObject(Csg::Kind kind, std::vector<IntelligentObjectPtr> children, bool inverse)
    : kind_(kind), children_(std::move(children)), inverse_(inverse) {
    full_shadow_ = casts_shadow() && !filters_light();
}

// An intersection's surface lies in the solid of each member, so one
// member whose solid is bounded bounds it; a difference's lies on its
// first member's surface or inside its solid (`inverse` members, whose
// solids are everything outside them, do not count).
bool CsgObject::bounded() const {
    switch (kind_) {
        case Csg::Kind::Union:
        case Csg::Kind::Merge:
            return std::all_of(children_.begin(), children_.end(),
                               [](const auto& c) { return c->bounded(); });
        case Csg::Kind::Intersection:
            return std::any_of(children_.begin(), children_.end(),
                               [](const auto& c) { return c->solid_bounded(); });
        case Csg::Kind::Difference:
            return !children_.empty() && children_.front()->solid_bounded();
    }
    return false;
}

bool CsgObject::solid_bounded() const {
    if (inverse_) return false;
    switch (kind_) {
        case Csg::Kind::Union:
        case Csg::Kind::Merge:
            return std::all_of(children_.begin(), children_.end(),
                               [](const auto& c) { return c->solid_bounded(); });
        case Csg::Kind::Intersection:
        case Csg::Kind::Difference:
            return bounded();
    }
    return false;
}

void CsgObject::bound(const Box4& region, std::vector<SlabBound>& out) const {
    if (children_.empty()) return;
    switch (kind_) {
        case Csg::Kind::Union:
        case Csg::Kind::Merge:
            for (const auto& c : children_) c->bound(region, out);
            return;
        case Csg::Kind::Intersection: {
            // The result lies inside every child's solid, and a bounded
            // solid lies inside the convex hull of its surface, so any
            // bounded child's bounds hold it: take the one whose bounds are
            // smallest in total.
            std::vector<SlabBound> best, mine;
            double best_volume = 0.0;
            bool found = false;
            for (const auto& c : children_) {
                if (!c->solid_bounded()) continue;
                mine.clear();
                c->bound(region, mine);
                double volume = 0.0;
                for (const auto& b : mine) volume += b.box().volume();
                if (!found || volume < best_volume) {
                    best.swap(mine);
                    best_volume = volume;
                    found = true;
                }
            }
            out.insert(out.end(), best.begin(), best.end());
            return;
        }
        case Csg::Kind::Difference:
            // Every surface of A - B lies on A or inside A.
            children_.front()->bound(region, out);
            return;
    }
}

Box4 CsgObject::box_over(const Interval& t) const {
    if (children_.empty()) return Box4::empty();
    switch (kind_) {
        case Csg::Kind::Union:
        case Csg::Kind::Merge: {
            Box4 box = Box4::empty();
            for (const auto& c : children_) box.extend(c->box_over(t));
            return box;
        }
        case Csg::Kind::Intersection: {
            // Inside every child's solid, and a bounded solid lies inside
            // the box of its surface.
            std::optional<Box4> box;
            for (const auto& c : children_) {
                if (!c->solid_bounded()) continue;
                const Box4 b = c->box_over(t);
                box = box ? box->intersection(b) : b;
            }
            return box ? *box : Box4::empty();
        }
        case Csg::Kind::Difference:
            return children_.front()->box_over(t);
    }
    return Box4::empty();
}

// Chords follow the children that hold the surface: every child for a
// union or merge, the bounded ones for an intersection (its surface lies in
// each bounded child's solid, and the children's bounds hold their whole
// object boxes), the first for a difference. Their placed boxes are
// unioned and their bounds take the largest, so each child's points stay
// inside.
std::vector<const IntelligentObject*> CsgObject::chord_children() const {
    std::vector<const IntelligentObject*> out;
    for (const auto& c : children_) {
        if (kind_ == Csg::Kind::Intersection && !c->solid_bounded()) continue;
        out.push_back(c.get());
        if (kind_ == Csg::Kind::Difference) break;
    }
    return out;
}

std::optional<IntelligentObject::ChordBound> CsgObject::chord_bound_over(const Interval& t) const {
    const auto children = chord_children();
    if (children.empty()) return std::nullopt;
    ChordBound all;
    for (const IntelligentObject* c : children) {
        const auto b = c->chord_bound_over(t);
        if (!b) {
            if (c->moves() || !c->bounded()) return std::nullopt;
            continue;  // a still child: its placed box is its box, margin 0
        }
        all.acceleration = glm::max(all.acceleration, b->acceleration);
        all.margin = glm::max(all.margin, b->margin);
    }
    return all;
}

Box4 CsgObject::placed_box_at(double t) const {
    Box4 box = Box4::empty();
    for (const IntelligentObject* c : chord_children()) box.extend(c->placed_box_at(t));
    return box;
}

bool CsgObject::keeps(std::size_t index, const Event& event) const {
    switch (kind_) {
        case Csg::Kind::Union:
            return true;
        case Csg::Kind::Merge:  // no surface inside another child
            for (std::size_t j = 0; j < children_.size(); ++j)
                if (j != index && children_[j]->inside(event)) return false;
            return true;
        case Csg::Kind::Intersection:  // the surface of one, inside all others
            for (std::size_t j = 0; j < children_.size(); ++j)
                if (j != index && !children_[j]->inside(event)) return false;
            return true;
        case Csg::Kind::Difference:
            if (index == 0) {  // A's surface outside every B
                for (std::size_t j = 1; j < children_.size(); ++j)
                    if (children_[j]->inside(event)) return false;
                return true;
            }
            // a B's surface inside A and outside the other Bs
            if (!children_[0]->inside(event)) return false;
            for (std::size_t j = 1; j < children_.size(); ++j)
                if (j != index && children_[j]->inside(event)) return false;
            return true;
    }
    return true;
}

std::optional<ObjectHit> CsgObject::intersect(const Ray4& ray, double s_min, double s_max) const {
    std::optional<ObjectHit> nearest;
    for (std::size_t i = 0; i < children_.size(); ++i) {
        double from = s_min;
        // Walk along child i's surface events until one belongs to the
        // combined surface; each step starts strictly after the last hit.
        for (int guard = 0; guard < 1024; ++guard) {
            auto hit = children_[i]->intersect(ray, from, s_max);
            if (!hit) break;
            if (keeps(i, hit->event)) {
                if (kind_ == Csg::Kind::Difference && i > 0) hit->flipped = !hit->flipped;
                s_max = hit->s;
                nearest = hit;
                break;
            }
            if (!(hit->s > from)) break;  // no progress: give up on this child
            from = hit->s;
        }
    }
    if (nearest && inverse_) nearest->flipped = !nearest->flipped;
    return nearest;
}

SurfacePoint CsgObject::complete(const Ray4& ray, const ObjectHit& hit) const {
    return hit.object->complete(ray, hit);
}

bool CsgObject::inside(const Event& event) const {
    bool in = false;
    switch (kind_) {
        case Csg::Kind::Union:
        case Csg::Kind::Merge:
            in = std::any_of(children_.begin(), children_.end(),
                             [&](const auto& c) { return c->inside(event); });
            break;
        case Csg::Kind::Intersection:
            in = !children_.empty() && std::all_of(children_.begin(), children_.end(),
                                                   [&](const auto& c) { return c->inside(event); });
            break;
        case Csg::Kind::Difference:
            in = !children_.empty() && children_[0]->inside(event) &&
                 std::none_of(children_.begin() + 1, children_.end(),
                              [&](const auto& c) { return c->inside(event); });
            break;
    }
    return in != inverse_;
}

double CsgObject::occupancy(const Box4& region) const {
    double total = 0.0;
    switch (kind_) {
        case Csg::Kind::Union:
        case Csg::Kind::Merge:  // overlaps count twice: an upper estimate, capped
            for (const auto& c : children_) total += c->occupancy(region);
            break;
        case Csg::Kind::Intersection:
            total = 1.0;
            for (const auto& c : children_) total = std::min(total, c->occupancy(region));
            break;
        case Csg::Kind::Difference:
            total = children_.empty() ? 0.0 : children_[0]->occupancy(region);
            break;
    }
    total = std::clamp(total, 0.0, 1.0);
    return inverse_ ? 1.0 - total : total;
}

bool CsgObject::moves() const {
    return std::any_of(children_.begin(), children_.end(),
                       [](const auto& c) { return c->moves(); });
}

bool CsgObject::deformed() const {
    return std::any_of(children_.begin(), children_.end(),
                       [](const auto& c) { return c->deformed(); });
}

bool CsgObject::filters_light() const {
    return std::any_of(children_.begin(), children_.end(),
                       [](const auto& c) { return c->filters_light(); });
}

bool CsgObject::casts_shadow() const {
    return std::any_of(children_.begin(), children_.end(),
                       [](const auto& c) { return c->casts_shadow(); });
}

IntelligentObject::RefractiveInterior CsgObject::refractive_interior(double t) const {
    for (const auto& c : children_)
        if (const RefractiveInterior r = c->refractive_interior(t); r.key) return r;
    return {};
}

const MediaVolume* CsgObject::interior_media() const {
    for (const auto& c : children_)
        if (const MediaVolume* media = c->interior_media()) return media;
    return nullptr;
}

}  // namespace hexant::runtime
