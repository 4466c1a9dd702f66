// Spacetime mode, the paper's: one hierarchy over the whole animation's
// spacetime, built once (lazily: as rays reach its cells), whose rays each
// carry their own time.
#include <chrono>

#include "tracer/ray_query.hpp"
#include "tracer/traversal.hpp"

namespace hexant::tracer::query_detail {

namespace {

using runtime::Box4;
using runtime::ObjectHit;
using runtime::Ray4;

SweptObjects timed_sweeps(const ObjectSet& objects, const Box4& animation,
                          const BuildOptions& options, Counters& counters) {
    const auto start = std::chrono::steady_clock::now();
    SweptObjects swept = SweptObjects::of(objects.bounded, animation, options);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    counters.build_seconds += seconds;
    counters.sweep_seconds += seconds;
    return swept;
}

class SpacetimeQuery final : public RayQuery {
  public:
    SpacetimeQuery(ObjectSet objects, const Box4& animation, const BuildOptions& options,
                   Counters& counters)
        : objects_(std::move(objects)),
          swept_(timed_sweeps(objects_, animation, options, counters)),
          hierarchy_(swept_, hierarchy_root(swept_, animation, options), options, counters) {}

    // The slabs of frames done (or not yet begun) are let go: memory holds
    // what this frame's rays need, whatever the animation's length. Then
    // the frame's time index: its rays skip the chain of time nodes.
    void prepare_frame(double t0, double t1, Counters&) override { hierarchy_.enter_frame(t0, t1); }

    std::optional<ObjectHit> first_hit(const Ray4& ray, double s_min, double s_max,
                                       ThreadState& state) const override {
        state.mailbox.next_ray();
        std::optional<ObjectHit> best = first_unbounded(objects_, ray, s_min, s_max, state);
        auto found = tracer::first_hit(hierarchy_, ray, s_min, best ? best->s : s_max, state);
        if (found) best = found;
        return best;
    }
    bool occluded(const Ray4& ray, double s_min, double s_max, ThreadState& state) const override {
        state.mailbox.next_ray();
        if (unbounded_occludes(objects_, ray, s_min, s_max, state)) return true;
        return tracer::occluded(hierarchy_, ray, s_min, s_max, state);
    }
    std::size_t object_count() const override { return objects_.size(); }
    void count_full_hierarchy(Counters& counters) const override {
        hierarchy_.count_full(counters);
    }

    void measure_memory(Counters& counters) const override {
        counters.node_bytes = hierarchy_.peak_bytes();
        counters.sweep_bytes = swept_.bytes();
    }

  private:
    ObjectSet objects_;
    SweptObjects swept_;
    Hierarchy hierarchy_;
};

}  // namespace

std::unique_ptr<RayQuery> make_spacetime(ObjectSet objects, const Box4& animation,
                                         const BuildOptions& options, Counters& counters) {
    BuildOptions all = options;
    all.split = SplitMode::Spacetime;
    return std::make_unique<SpacetimeQuery>(std::move(objects), animation, all, counters);
}

}  // namespace hexant::tracer::query_detail
