#include "tracer/ray_query.hpp"

#include <algorithm>
#include <array>
#include <stdexcept>

#include "runtime/slab_ray.hpp"

namespace hexant::tracer {

using runtime::Box4;
using runtime::IntelligentObject;
using runtime::ObjectHit;
using runtime::Ray4;
using runtime::SlabRay;

Mode parse_mode(const std::string& name) {
    if (name == "spacetime") return Mode::Spacetime;
    if (name == "frames") return Mode::Frames;
    if (name == "brute") return Mode::Brute;
    throw std::invalid_argument("unknown mode '" + name + "' (spacetime, frames or brute)");
}

const char* mode_name(Mode mode) {
    switch (mode) {
        case Mode::Spacetime: return "spacetime";
        case Mode::Frames: return "frames";
        case Mode::Brute: return "brute";
    }
    return "?";
}

ObjectSet ObjectSet::of(std::span<const runtime::IntelligentObjectPtr> objects) {
    ObjectSet set;
    for (const auto& o : objects) (o->bounded() ? set.bounded : set.unbounded).push_back(o.get());
    return set;
}

runtime::Box4 enclosing_box(const ObjectSet& objects, double t0, double t1) {
    // Asked about (nearly) all of space, each object bounds itself.
    constexpr double kFar = 1e300;
    Box4 everywhere;
    everywhere.lo = runtime::Event(-kFar, -kFar, -kFar, t0);
    everywhere.hi = runtime::Event(kFar, kFar, kFar, t1);
    Box4 box = Box4::empty();
    std::vector<runtime::SlabBound> bounds;
    for (const IntelligentObject* object : objects.bounded) {
        bounds.clear();
        object->bound(everywhere, bounds);
        for (const auto& b : bounds) box.extend(b.box());
    }
    return box;
}

namespace {

// Tests an object once per ray (through the mailbox) over the whole segment.
const std::optional<ObjectHit>& test(std::uint32_t index, const IntelligentObject& object,
                                     const Ray4& ray, double s_min, double s_max,
                                     ThreadState& state) {
    if (const auto* kept = state.mailbox.find(index)) {
        ++state.counters.mailbox_hits;
        return *kept;
    }
    ++state.counters.object_tests;
    return state.mailbox.keep(index, object.intersect(ray, s_min, s_max));
}

// One ray's walk through a hierarchy: children nearest first among those
// the ray enters (a ray at one instant enters only the children whose time
// half holds it), each object tested once, and the walk stops after the
// first leaf whose span holds the best hit found (cells do not overlap, so
// nothing later can be nearer). A hit found beyond its leaf (an object in
// several cells) stays a candidate that prunes later cells and is accepted
// when the walk reaches it; the answer is the nearest hit tested.
class Walk {
public:
    Walk(const Hierarchy& h, std::span<const IntelligentObject* const> objects, const Ray4& ray,
         double s_min, double s_max, bool shadow, ThreadState& state)
        : h_(h), objects_(objects), ray_(ray), slab_ray_(ray), s_min_(s_min), s_max_(s_max),
          shadow_(shadow), state_(state), best_s_(s_max), instant_(ray.direction.w == 0.0),
          time_(ray.origin.w) {}

    void run() {
        if (h_.empty()) return;
        double enter, exit;
        if (!slab_ray_.clip(h_.root().region, s_min_, s_max_, &enter, &exit)) return;
        visit(h_.root(), enter, exit);
    }
    const std::optional<ObjectHit>& best() const { return best_; }
    bool blocked() const { return blocked_; }

private:
    // True when the walk may stop.
    bool visit(const Cell& cell, double enter, double exit) {
        if (instant_ && cell.splits_time_only) {
            for (std::uint32_t c = 0; c < cell.child_count; ++c) {
                const Cell& child = h_.cells()[cell.first_child + c];
                if (time_ >= child.region.lo.w && time_ <= child.region.hi.w)
                    return visit(child, enter, exit);
            }
            return false;
        }
        ++state_.counters.bound_tests;
        if (!slab_ray_.intersect(cell.bound, enter, exit)) return false;
        if (cell.is_leaf()) {
            for (const std::uint32_t index : h_.objects_of(cell)) {
                const IntelligentObject& object = *objects_[index];
                if (shadow_ && !object.casts_shadow()) continue;
                const auto& hit = test(index, object, ray_, s_min_, s_max_, state_);
                if (!hit) continue;
                if (shadow_) {
                    blocked_ = true;
                    return true;
                }
                if (hit->s < best_s_) {
                    best_ = hit;
                    best_s_ = hit->s;
                }
            }
            return best_ && best_s_ <= exit;
        }
        // Children the ray enters, by entry parameter.
        std::array<std::pair<double, std::uint32_t>, 16> order;
        std::array<double, 16> exits;
        int n = 0;
        for (std::uint32_t c = 0; c < cell.child_count; ++c) {
            const std::uint32_t index = cell.first_child + c;
            const runtime::Box4& region = h_.cells()[index].region;
            // A ray at one instant sees only the children whose time holds it.
            if (instant_ && (time_ < region.lo.w || time_ > region.hi.w)) continue;
            double e, x;
            if (!slab_ray_.clip(region, enter, exit, &e, &x)) continue;
            exits[n] = x;
            order[n++] = {e, index};
        }
        // Insertion sort (at most 16), keeping each exit with its child.
        for (int i = 1; i < n; ++i)
            for (int j = i; j > 0 && order[j].first < order[j - 1].first; --j) {
                std::swap(order[j], order[j - 1]);
                std::swap(exits[j], exits[j - 1]);
            }
        for (int i = 0; i < n; ++i) {
            if (order[i].first > best_s_) break;
            if (visit(h_.cells()[order[i].second], order[i].first, std::min(exits[i], best_s_)))
                return true;
        }
        return false;
    }

    const Hierarchy& h_;
    std::span<const IntelligentObject* const> objects_;
    const Ray4& ray_;
    SlabRay slab_ray_;
    double s_min_, s_max_;
    bool shadow_;
    ThreadState& state_;
    double best_s_;
    std::optional<ObjectHit> best_;
    bool blocked_ = false;
    bool instant_;
    double time_;
};

// The unbounded objects, tested on every ray; their indices follow the
// bounded ones' in the mailbox.
std::optional<ObjectHit> first_unbounded(const ObjectSet& set, const Ray4& ray, double s_min,
                                         double s_max, ThreadState& state) {
    std::optional<ObjectHit> best;
    for (std::size_t i = 0; i < set.unbounded.size(); ++i) {
        const auto index = static_cast<std::uint32_t>(set.bounded.size() + i);
        const auto& hit = test(index, *set.unbounded[i], ray, s_min, s_max, state);
        if (hit && (!best || hit->s < best->s)) best = hit;
    }
    return best;
}

bool unbounded_occludes(const ObjectSet& set, const Ray4& ray, double s_min, double s_max,
                        ThreadState& state) {
    for (std::size_t i = 0; i < set.unbounded.size(); ++i) {
        if (!set.unbounded[i]->casts_shadow()) continue;
        const auto index = static_cast<std::uint32_t>(set.bounded.size() + i);
        if (test(index, *set.unbounded[i], ray, s_min, s_max, state)) return true;
    }
    return false;
}

class BruteForce final : public RayQuery {
public:
    explicit BruteForce(ObjectSet objects) : objects_(std::move(objects)) {}
    void prepare_frame(double, double, Counters&) override {}
    std::optional<ObjectHit> first_hit(const Ray4& ray, double s_min, double s_max,
                                       ThreadState& state) const override {
        state.mailbox.next_ray();
        std::optional<ObjectHit> best = first_unbounded(objects_, ray, s_min, s_max, state);
        for (std::size_t i = 0; i < objects_.bounded.size(); ++i) {
            const auto& hit = test(static_cast<std::uint32_t>(i), *objects_.bounded[i], ray, s_min,
                                   s_max, state);
            if (hit && (!best || hit->s < best->s)) best = hit;
        }
        return best;
    }
    bool occluded(const Ray4& ray, double s_min, double s_max,
                  ThreadState& state) const override {
        state.mailbox.next_ray();
        if (unbounded_occludes(objects_, ray, s_min, s_max, state)) return true;
        for (std::size_t i = 0; i < objects_.bounded.size(); ++i) {
            if (!objects_.bounded[i]->casts_shadow()) continue;
            if (test(static_cast<std::uint32_t>(i), *objects_.bounded[i], ray, s_min, s_max, state))
                return true;
        }
        return false;
    }
    std::size_t object_count() const override { return objects_.size(); }

private:
    ObjectSet objects_;
};

// One hierarchy: over the whole animation (spacetime mode) or over the
// current frame's shutter (frames mode, rebuilt by prepare_frame).
class HierarchyQuery final : public RayQuery {
public:
    HierarchyQuery(ObjectSet objects, const Box4& animation, const BuildOptions& options,
                   bool per_frame, Counters& counters)
        : objects_(std::move(objects)), animation_(animation), options_(options),
          per_frame_(per_frame) {
        if (!per_frame_) hierarchy_ = Hierarchy::build(objects_.bounded, animation_, options_, counters);
    }
    void prepare_frame(double t0, double t1, Counters& counters) override {
        if (!per_frame_) return;
        Box4 root = animation_;
        root.lo.w = t0;
        root.hi.w = t1;
        hierarchy_ = Hierarchy::build(objects_.bounded, root, options_, counters);
    }
    std::optional<ObjectHit> first_hit(const Ray4& ray, double s_min, double s_max,
                                       ThreadState& state) const override {
        state.mailbox.next_ray();
        std::optional<ObjectHit> best = first_unbounded(objects_, ray, s_min, s_max, state);
        Walk walk(hierarchy_, objects_.bounded, ray, s_min, best ? best->s : s_max, false, state);
        walk.run();
        if (walk.best() && (!best || walk.best()->s < best->s)) best = walk.best();
        return best;
    }
    bool occluded(const Ray4& ray, double s_min, double s_max,
                  ThreadState& state) const override {
        state.mailbox.next_ray();
        if (unbounded_occludes(objects_, ray, s_min, s_max, state)) return true;
        Walk walk(hierarchy_, objects_.bounded, ray, s_min, s_max, true, state);
        walk.run();
        return walk.blocked();
    }
    std::size_t object_count() const override { return objects_.size(); }
    const Hierarchy& hierarchy() const { return hierarchy_; }

private:
    ObjectSet objects_;
    Box4 animation_;
    BuildOptions options_;
    bool per_frame_;
    Hierarchy hierarchy_;
};

}  // namespace

std::unique_ptr<RayQuery> make_ray_query(Mode mode, ObjectSet objects, const Box4& animation,
                                         const BuildOptions& options, Counters& counters) {
    switch (mode) {
        case Mode::Brute: return std::make_unique<BruteForce>(std::move(objects));
        case Mode::Frames: {
            BuildOptions frame = options;
            frame.split = SplitMode::Space;
            return std::make_unique<HierarchyQuery>(std::move(objects), animation, frame, true,
                                                    counters);
        }
        case Mode::Spacetime: break;
    }
    BuildOptions all = options;
    all.split = SplitMode::Spacetime;
    return std::make_unique<HierarchyQuery>(std::move(objects), animation, all, false, counters);
}

}  // namespace hexant::tracer
