// Brute force: every object tested on every ray. The reference that both
// hierarchies must match, image for image.
#include "tracer/object_test.hpp"
#include "tracer/ray_query.hpp"

namespace hexant::tracer::query_detail {

namespace {

using runtime::ObjectHit;
using runtime::Ray4;

class BruteForce final : public RayQuery {
  public:
    explicit BruteForce(ObjectSet objects) : objects_(std::move(objects)) {}
    void prepare_frame(double, double, Counters&) override {}
    std::optional<ObjectHit> first_hit(const Ray4& ray, double s_min, double s_max,
                                       ThreadState& state) const override {
        state.mailbox.next_ray();
        std::optional<ObjectHit> best = first_unbounded(objects_, ray, s_min, s_max, state);
        double best_s = best ? best->s : s_max;
        const ObjectTest test{ray, s_min, s_max, state};
        for (std::size_t i = 0; i < objects_.bounded.size(); ++i)
            test.nearest(std::uint32_t(i), *objects_.bounded[i], best, best_s);
        return best;
    }
    bool occluded(const Ray4& ray, double s_min, double s_max, ThreadState& state) const override {
        state.mailbox.next_ray();
        if (unbounded_occludes(objects_, ray, s_min, s_max, state)) return true;
        const ObjectTest test{ray, s_min, s_max, state};
        for (std::size_t i = 0; i < objects_.bounded.size(); ++i)
            if (test.occludes(std::uint32_t(i), *objects_.bounded[i])) return true;
        return false;
    }
    std::size_t object_count() const override { return objects_.size(); }
    void count_full_hierarchy(Counters&) const override {}
    void measure_memory(Counters&) const override {}

  private:
    ObjectSet objects_;
};

}  // namespace

std::unique_ptr<RayQuery> make_brute(ObjectSet objects) {
    return std::make_unique<BruteForce>(std::move(objects));
}

}  // namespace hexant::tracer::query_detail
