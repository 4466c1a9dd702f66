#include "tracer/ray_query.hpp"

#include <stdexcept>

#include "tracer/object_test.hpp"

namespace hexant::tracer {

using runtime::Box4;
using runtime::ObjectHit;
using runtime::Ray4;

Mode parse_mode(const std::string& name) {
    if (name == "spacetime") return Mode::Spacetime;
    if (name == "frames") return Mode::Frames;
    if (name == "brute") return Mode::Brute;
    throw std::invalid_argument("unknown mode '" + name + "' (spacetime, frames or brute)");
}

const char* mode_name(Mode mode) {
    switch (mode) {
        case Mode::Spacetime:
            return "spacetime";
        case Mode::Frames:
            return "frames";
        case Mode::Brute:
            return "brute";
    }
    return "?";
}

ObjectSet ObjectSet::of(std::span<const runtime::IntelligentObjectPtr> objects) {
    ObjectSet set;
    for (const auto& o : objects) (o->bounded() ? set.bounded : set.unbounded).push_back(o.get());
    return set;
}

Box4 enclosing_box(const ObjectSet& objects, double t0, double t1) {
    Box4 box = Box4::empty();
    for (const runtime::IntelligentObject* object : objects.bounded)
        box.extend(object->box_over(runtime::Interval(t0, t1)));
    return box;
}

std::unique_ptr<RayQuery> make_ray_query(Mode mode, ObjectSet objects, const Box4& animation,
                                         const BuildOptions& options, Counters& counters) {
    switch (mode) {
        case Mode::Brute:
            return query_detail::make_brute(std::move(objects));
        case Mode::Frames:
            return query_detail::make_frames(std::move(objects), animation, options, counters);
        case Mode::Spacetime:
            break;
    }
    return query_detail::make_spacetime(std::move(objects), animation, options, counters);
}

namespace query_detail {

std::optional<ObjectHit> first_unbounded(const ObjectSet& set, const Ray4& ray, double s_min,
                                         double s_max, ThreadState& state) {
    std::optional<ObjectHit> best;
    double best_s = s_max;
    const ObjectTest test{ray, s_min, s_max, state};
    for (std::size_t i = 0; i < set.unbounded.size(); ++i)
        test.nearest(std::uint32_t(set.bounded.size() + i), *set.unbounded[i], best, best_s);
    return best;
}

bool unbounded_occludes(const ObjectSet& set, const Ray4& ray, double s_min, double s_max,
                        ThreadState& state) {
    const ObjectTest test{ray, s_min, s_max, state};
    for (std::size_t i = 0; i < set.unbounded.size(); ++i)
        if (test.occludes(std::uint32_t(set.bounded.size() + i), *set.unbounded[i])) return true;
    return false;
}

Box4 hierarchy_root(const SweptObjects& swept, const Box4& given, const BuildOptions& options) {
    if (options.criterion == Criterion::Paper) return given;
    Box4 objects = Box4::empty();
    for (const auto& sweep : swept.sweeps) objects.extend(sweep.box_over(given.time()));
    Box4 root = given.intersection(objects);
    root.lo.w = given.lo.w;
    root.hi.w = given.hi.w;
    // A flat extent (everything in one plane) keeps a little thickness, so
    // that halving it means something.
    for (int i = 0; i < 3; ++i) {
        if (!(root.lo[i] <= root.hi[i])) return given;
        if (root.hi[i] > root.lo[i]) continue;
        const double pad = std::max(1e-9, std::fabs(root.lo[i]) * 1e-9);
        root.lo[i] -= pad;
        root.hi[i] += pad;
    }
    return root;
}

}  // namespace query_detail

}  // namespace hexant::tracer
