// The lazy hierarchy: the root built at once, every other cell when a ray
// first reaches it (Hierarchy::expand), and the slabs of time the frames
// have passed released again (Hierarchy::release_outside). The builder's
// parts are hierarchy_builder.hpp's files.
#include "tracer/hierarchy.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>

#include <tbb/parallel_for.h>

#include "runtime/work_counts.hpp"
#include "tracer/hierarchy_builder.hpp"

namespace hexant::tracer {

using runtime::Box4;
using runtime::Interval;

SweptObjects SweptObjects::of(std::span<const runtime::IntelligentObject* const> objects,
                              const Box4& scene, const BuildOptions& options) {
    SweptObjects set;
    set.objects.assign(objects.begin(), objects.end());
    const Interval time = scene.time();
    set.time = time;
    runtime::SweepPricing pricing;
    pricing.object_cost = options.moving_object_cost;  // only moving objects are cut
    // The rays spread over the objects' own extent (a camera looks at
    // them), not over the eye and lights the root also holds.
    Box4 extent = Box4::empty();
    for (const auto* o : objects) extent.extend(o->box_over(time).intersection(scene));
    const double area = surface_area(extent);
    if (options.rays_per_frame > 0.0 && options.frame_interval > 0.0 && area > 0.0 &&
        std::isfinite(area) && options.build_cost > 0.0)
        pricing.ray_density = options.rays_per_frame / options.frame_interval / area;
    std::size_t moving = 0;
    for (const auto* o : objects) moving += o->moves() ? 1 : 0;
    int depth = kMaxSweepDepth;
    while (depth > 0 && moving * (std::size_t(1) << depth) > kSweepPieceBudget) --depth;
    set.sweeps.resize(objects.size());
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, objects.size(), 64),
                      [&](const tbb::blocked_range<std::size_t>& r) {
                          for (std::size_t i = r.begin(); i < r.end(); ++i)
                              set.sweeps[i] =
                                  runtime::TimeSweep::of(*objects[i], time, depth, pricing);
                      });
    return set;
}

std::size_t SweptObjects::bytes() const {
    std::size_t total = objects.capacity() * sizeof(void*);
    for (const auto& s : sweeps) total += s.bytes();
    return total;
}

Hierarchy::Hierarchy(const SweptObjects& objects, const Box4& root, const BuildOptions& options,
                     Counters& counters)
    : objects_(objects),
      options_(options),
      region_(root),
      builder_(std::make_unique<Builder>(*this)) {
    const auto start = std::chrono::steady_clock::now();
    const std::uint64_t maps = runtime::this_thread_work.deformation_maps;
    std::vector<std::uint32_t> all;
    all.reserve(objects.objects.size());
    for (std::uint32_t i = 0; i < objects.objects.size(); ++i)
        if (!objects.sweeps[i].box_over(root.time()).intersection(root).is_empty())
            all.push_back(i);
    CellTime time;
    time.t = root.time();
    // Spacetime mode: the root's time is the sweeps', cut the same way.
    if (root.lo.w == objects.time.lo && root.hi.w == objects.time.hi) time.level = 0;
    root_ = builder_->build(arena_, root, time,
                            std::make_shared<const std::vector<std::uint32_t>>(std::move(all)), 0,
                            counters);
    counters.build_seconds +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    // The root is entered by every ray: never leave it pending.
    Counters first;
    while (root_.kind() == RefKind::Pending) root_ = expand(&root_, root_, first);
    first.build_seconds += first.lazy_build_seconds;
    first.lazy_build_seconds = 0.0;
    counters += first;
    counters.deformation_maps += runtime::this_thread_work.deformation_maps - maps;
}

Hierarchy::~Hierarchy() = default;

NodeRef Hierarchy::expand(NodeRef* slot, NodeRef pending, Counters& counters) const {
    PendingCell* p = pending.as<PendingCell>();
    // One large cell at a time: this one is reserved before its build
    // begins, and while another is reserved, that one is helped first.
    // Every wait is outside any cell's once flag, as when two threads reach
    // one cell (a wait on another flag from inside one deadlocked in
    // oneTBB: the helpers of the outer cell held the arena's only worker).
    struct Reservation {
        const Hierarchy& h;
        bool held = false;
        ~Reservation() {
            if (!held) return;
            h.large_build_.store(nullptr, std::memory_order_release);
            h.large_build_.notify_all();
        }
    } reservation{*this};
    if (p->object_count >= options_.large_build) {
        for (;;) {
            PendingCell* other = nullptr;
            if (large_build_.compare_exchange_strong(other, p, std::memory_order_acq_rel)) {
                reservation.held = true;
                break;
            }
            if (other == p) break;  // reserved by a thread about to build it: help it
            // Under way (or about to be): wait for it, helping. It would be
            // built here only had its build failed and its flag been reset.
            tbb::collaborative_call_once(other->once, [&] { build_pending(other, counters); });
            // Its reservation ends just after its flag: wait for that, not spin.
            large_build_.wait(other, std::memory_order_acquire);
        }
    }
    tbb::collaborative_call_once(p->once, [&] {
        p->slot = slot;
        build_pending(p, counters);
    });
    NodeRef::store(slot, p->built);
    return p->built;
}

void Hierarchy::build_pending(PendingCell* p, Counters& counters) const {
    const auto start = std::chrono::steady_clock::now();
    CellTime time;
    time.t = p->region.time();
    time.level = p->time_level;
    time.index = p->time_index;
    if (p->slab_root) {
        // Its own arena, and its objects kept for a build after a release.
        p->own = std::make_unique<NodeArena>();
        p->built = builder_->build(*p->own, p->region, time, p->objects, p->depth, counters);
        const std::lock_guard<std::mutex> lock(slabs_mutex_);
        live_slabs_.push_back({p->slot, p});
    } else {
        p->built = builder_->build(p->arena ? *p->arena : arena_, p->region, time, p->objects,
                                   p->depth, counters);
        p->objects.reset();
    }
    counters.lazy_build_seconds +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void Hierarchy::new_index_generation() const {
    static std::atomic<std::uint64_t> last{0};
    index_generation_.store(last.fetch_add(1, std::memory_order_relaxed) + 1,
                            std::memory_order_release);
}

void Hierarchy::release(const LiveSlab& slab) const {
    time_index_.clear();
    new_index_generation();
    PendingCell* p = slab.cell;
    NodeRef::store(slab.slot, NodeRef::node(RefKind::Pending, p));
    p->built = {};
    p->own.reset();  // its nodes, and the pending cells below it
    // A fresh flag: the next ray to reach it builds it again.
    p->once.~collaborative_once_flag();
    new (&p->once) tbb::collaborative_once_flag();
}

void Hierarchy::release_outside(double t0, double t1) {
    const std::lock_guard<std::mutex> lock(slabs_mutex_);
    peak_bytes_ = std::max(peak_bytes_, held_bytes());
    // A ray at the time a slab ends goes to the later half (traversal_simd.cpp),
    // so a slab ending where [t0, t1] begins is outside it.
    std::erase_if(live_slabs_, [&](const LiveSlab& s) {
        const bool outside = s.cell->region.hi.w <= t0 || s.cell->region.lo.w > t1;
        if (outside) release(s);
        return outside;
    });
}

void Hierarchy::enter_frame(double t0, double t1) {
    release_outside(t0, t1);
    time_index_.build(&root_, t0, t1);
    new_index_generation();
}

std::size_t Hierarchy::held_bytes() const {
    std::size_t held = arena_.bytes();
    for (const LiveSlab& s : live_slabs_) held += s.cell->own->bytes();
    return held;
}

std::size_t Hierarchy::bytes() const {
    const std::lock_guard<std::mutex> lock(slabs_mutex_);
    return held_bytes();
}

std::size_t Hierarchy::peak_bytes() const {
    const std::lock_guard<std::mutex> lock(slabs_mutex_);
    return std::max(peak_bytes_, held_bytes());
}

}  // namespace hexant::tracer
