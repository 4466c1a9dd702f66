#include "runtime/objects/instance_object.hpp"

#include <stdexcept>

#include <glm/mat3x3.hpp>

#include "runtime/bounds/occupancy_sampling.hpp"
#include "runtime/bounds/swept_bound.hpp"
#include "runtime/geometry/offset_ray.hpp"
#include "runtime/objects/rigid_bounds.hpp"

namespace hexant::runtime {

namespace {

geometry::Box3 space_box(const Box4& box) {
    return {glm::dvec3(box.lo), glm::dvec3(box.hi)};
}

}  // namespace

InstanceObject::InstanceObject(std::vector<IntelligentObjectPtr> members,
                               const Transform& placement)
    : motion_(placement) {
    if (!motion_.is_affine()) throw std::invalid_argument("an instance's placement must be affine");
    std::vector<geometry::Box3> boxes;
    std::vector<glm::dvec3> centres;
    boxes.reserve(members.size());
    centres.reserve(members.size());
    box_ = objects::empty_interval_box();
    for (const IntelligentObjectPtr& m : members) {
        if (!m->bounded() || m->moves())
            throw std::invalid_argument("an instance's members must be bounded and stand still");
        // (Standing still, a member's box at any instant is its box.)
        const geometry::Box3 b = space_box(m->box_over(Interval(0.0)));
        boxes.push_back(b);
        centres.push_back(0.5 * (b.lo + b.hi));
        box_ = objects::hull(box_, objects::to_interval_box(b));
        solid_bounded_ = solid_bounded_ && m->solid_bounded();
        casts_shadow_ = casts_shadow_ || m->casts_shadow();
        filters_light_ = filters_light_ || m->filters_light();
        full_shadow_ = full_shadow_ && m->casts_full_shadow();
    }
    std::vector<std::uint32_t> order;
    hierarchy_ = objects::BoxHierarchy::build(boxes, centres, order);
    members_.reserve(members.size());
    for (const std::uint32_t k : order) members_.push_back(std::move(members[k]));
}

void InstanceObject::bound(const Box4& region, std::vector<SlabBound>& out) const {
    if (region.is_empty() || members_.empty()) return;
    const auto world_box_over = [this](const Interval& t) { return motion_.world_box(box_, t); };
    append_rigid_bounds(region, moves(), moves() ? IntervalBox{} : world_box_over(Interval(0.0)),
                        world_box_over, out);
}

Box4 InstanceObject::box_over(const Interval& t) const {
    if (t.is_empty() || members_.empty()) return Box4::empty();
    return box_over_time(motion_.world_box(box_, t), t);
}

std::optional<IntelligentObject::ChordBound> InstanceObject::chord_bound_over(
    const Interval& t) const {
    if (!moves() || members_.empty() || !(t.lo <= t.hi)) return std::nullopt;
    return rigid_chord_bound(motion_, box_, t);
}

Box4 InstanceObject::placed_box_at(double t) const {
    if (!moves() || members_.empty()) return box_over(Interval(t));
    const IntervalBox world = motion_.map_at(t).apply(box_);
    return {Event(world[0].lo, world[1].lo, world[2].lo, t),
            Event(world[0].hi, world[1].hi, world[2].hi, t)};
}

Ray4 InstanceObject::to_members(const Ray4& ray, const Motion::Placement& placement) const {
    if (ray.direction.w != 0.0 && moves())
        throw std::logic_error("an instance meets rays at one instant only");
    const glm::dvec3 o = glm::dvec3(placement.to_object * glm::dvec4(glm::dvec3(ray.origin), 1.0));
    const glm::dvec3 d = glm::dmat3(placement.to_object) * glm::dvec3(ray.direction);
    return {Event(o, ray.origin.w), Event(d, ray.direction.w)};
}

std::optional<ObjectHit> InstanceObject::intersect(const Ray4& ray, double s_min,
                                                   double s_max) const {
    if (!(s_min < s_max) || members_.empty()) return std::nullopt;
    const Motion::Placement placement = motion_.placement_at(ray.origin.w);
    // (The map is affine: the ray's parameter is the same in both spaces.)
    const Ray4 local = to_members(ray, placement);
    std::optional<ObjectHit> best;
    hierarchy_.traverse(geometry::Ray3{glm::dvec3(local.origin), glm::dvec3(local.direction)},
                        s_min, s_max, [&](std::uint32_t first, std::uint32_t count, double far) {
                            for (std::uint32_t k = first; k < first + count; ++k)
                                if (auto hit = members_[k]->intersect(local, s_min, far)) {
                                    far = hit->s;
                                    best = std::move(hit);
                                }
                            return far;
                        });
    if (!best) return std::nullopt;
    // The event in the world (the wrappers around the instance test it
    // there); the primitive hit stays the member's, for complete().
    best->member = best->object;
    best->object = this;
    best->event = Event(glm::dvec3(placement.to_world * glm::dvec4(glm::dvec3(best->event), 1.0)),
                        best->event.w);
    return best;
}

bool InstanceObject::occluded(const Ray4& ray, double s_min, double s_max) const {
    if (!(s_min < s_max) || members_.empty()) return false;
    const Ray4 local = to_members(ray, motion_.placement_at(ray.origin.w));
    bool found = false;
    hierarchy_.traverse(geometry::Ray3{glm::dvec3(local.origin), glm::dvec3(local.direction)},
                        s_min, s_max, [&](std::uint32_t first, std::uint32_t count, double far) {
                            for (std::uint32_t k = first; k < first + count && !found; ++k)
                                found = members_[k]->occluded(local, s_min, far);
                            return found ? s_min : far;  // (s_min: every box left lies beyond)
                        });
    return found;
}

SurfacePoint InstanceObject::complete(const Ray4& ray, const ObjectHit& hit) const {
    if (!hit.member) throw std::logic_error("an instance completes only its members' hits");
    // The member's primitive completes the hit in the world: its map to the
    // union's space, then the placement (the chain rule for normals); the
    // event and the textures are in the world already.
    const double t = hit.event.w;
    const Motion::Placement placement = motion_.placement_at(t);
    const glm::dmat3 member_linear = hit.member->to_world_linear_at(hit.object_point, t);
    ObjectHit own = hit;
    own.object = hit.member;
    own.member = nullptr;
    own.to_world_linear = glm::dmat3(placement.to_world) * member_linear;
    own.has_linear = true;
    SurfacePoint p = hit.member->complete(ray, own);
    // The point's error by the two steps it took: into the union's space,
    // where it was rounded at the size of its coordinates there (a member
    // placed far off and brought back by the union's transform: 1e5 away,
    // its point is good to 1e-11, not to the world point's ulps), then into
    // the world (geometry::world_error at each step).
    const glm::dvec3 world(hit.event);
    const glm::dvec3 local(placement.to_object * glm::dvec4(world, 1.0));
    const glm::dvec3 in_union =
        geometry::world_error(member_linear, hit.object_point, local, hit.object_error);
    const glm::dvec3 error =
        geometry::world_error(glm::dmat3(placement.to_world), local, world, in_union);
    p.error = glm::max(p.error, error);
    return p;
}

bool InstanceObject::inside(const Event& event) const {
    const glm::dvec3 p = glm::dvec3(motion_.inverse_at(event.w) * glm::dvec4(glm::dvec3(event), 1));
    const Event local(p, event.w);
    // (A member whose solid reaches outside its box, an `inverse` one, is
    // asked wherever the point is.)
    if (!solid_bounded_) {
        for (const IntelligentObjectPtr& m : members_)
            if (m->inside(local)) return true;
        return false;
    }
    bool in = false;
    hierarchy_.descend([&](const objects::BoxHierarchy::Node& node) {
        if (in) return false;
        for (int i = 0; i < 3; ++i)
            if (!(node.box.lo[i] <= p[i] && p[i] <= node.box.hi[i])) return false;
        for (std::uint32_t k = node.first; node.count > 0 && k < node.first + node.count; ++k)
            if (members_[k]->inside(local)) {
                in = true;
                break;
            }
        return true;
    });
    return in;
}

double InstanceObject::occupancy(const Box4& region) const {
    if (region.is_empty() || !(region.volume() > 0.0)) return 0.0;
    const auto inside_at = [this](const Event& e) { return inside(e); };
    if (!solid_bounded_) return sampled_occupancy(region, inside_at);
    const Box4 near = piece_box(motion_.world_box(box_, region.time()), region.time(), region);
    if (near.is_empty() || !(near.volume() > 0.0)) return 0.0;
    return near.volume() / region.volume() * sampled_occupancy(near, inside_at);
}

const MediaVolume* InstanceObject::interior_media() const {
    return members_.empty() ? nullptr : members_.front()->interior_media();
}

IntelligentObject::RefractiveInterior InstanceObject::refractive_interior(double t) const {
    return members_.empty() ? RefractiveInterior{} : members_.front()->refractive_interior(t);
}

}  // namespace hexant::runtime
