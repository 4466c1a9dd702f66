// The paper's frame-by-frame baseline: for each frame a spatial hierarchy
// built anew over that frame's shutter (the same builder, splitting x, y
// and z only), every object bounded by a box that holds it over the whole
// shutter. Objects compute their sweeps once, as in spacetime mode; each
// frame's hierarchy clips them to its own time.
#include <chrono>

#include "tracer/ray_query.hpp"
#include "tracer/traversal.hpp"

namespace hexant::tracer::query_detail {

namespace {

using runtime::Box4;
using runtime::ObjectHit;
using runtime::Ray4;

class FrameBaseline final : public RayQuery {
  public:
    FrameBaseline(ObjectSet objects, const Box4& animation, const BuildOptions& options,
                  Counters& counters)
        : objects_(std::move(objects)), animation_(animation), options_(options) {
        const auto start = std::chrono::steady_clock::now();
        swept_ = SweptObjects::of(objects_.bounded, animation, options);
        const double seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        counters.build_seconds += seconds;
        counters.sweep_seconds += seconds;
    }

    void prepare_frame(double t0, double t1, Counters& counters) override {
        if (hierarchy_ && options_.count_full) hierarchy_->count_full(counters);
        Box4 root = animation_;
        root.lo.w = t0;
        root.hi.w = t1;
        hierarchy_.reset();
        hierarchy_ = std::make_unique<Hierarchy>(swept_, hierarchy_root(swept_, root, options_),
                                                 options_, counters);
    }

    std::optional<ObjectHit> first_hit(const Ray4& ray, double s_min, double s_max,
                                       ThreadState& state) const override {
        state.mailbox.next_ray();
        std::optional<ObjectHit> best = first_unbounded(objects_, ray, s_min, s_max, state);
        if (!hierarchy_) return best;
        auto found = tracer::first_hit(*hierarchy_, ray, s_min, best ? best->s : s_max, state);
        if (found) best = found;
        return best;
    }
    bool occluded(const Ray4& ray, double s_min, double s_max, ThreadState& state) const override {
        state.mailbox.next_ray();
        if (unbounded_occludes(objects_, ray, s_min, s_max, state)) return true;
        return hierarchy_ && tracer::occluded(*hierarchy_, ray, s_min, s_max, state);
    }
    std::size_t object_count() const override { return objects_.size(); }
    // The last frame's; each earlier one was counted as it was replaced
    // (with BuildOptions::count_full).
    void count_full_hierarchy(Counters& counters) const override {
        if (hierarchy_) hierarchy_->count_full(counters);
    }

    void measure_memory(Counters& counters) const override {
        counters.node_bytes = (hierarchy_ ? hierarchy_->bytes() : 0);
        counters.sweep_bytes = swept_.bytes();
    }

  private:
    ObjectSet objects_;
    Box4 animation_;
    BuildOptions options_;
    SweptObjects swept_;
    std::unique_ptr<Hierarchy> hierarchy_;
};

}  // namespace

std::unique_ptr<RayQuery> make_frames(ObjectSet objects, const Box4& animation,
                                      const BuildOptions& options, Counters& counters) {
    BuildOptions frame = options;
    frame.split = SplitMode::Space;
    return std::make_unique<FrameBaseline>(std::move(objects), animation, frame, counters);
}

}  // namespace hexant::tracer::query_detail
