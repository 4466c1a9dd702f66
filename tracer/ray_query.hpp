// The question every mode of the tracer answers for a ray: the first surface
// event along it, or whether anything casting a shadow lies on a segment.
// Three modes answer it (docs/design.md, "Spacetime query"): one spacetime hierarchy for the
// whole animation (spacetime_query.cpp), a spatial hierarchy per frame, the
// paper's baseline (frame_baseline.cpp), and brute force, the reference
// (brute_force.cpp). They must agree; at equal distances the object written first is kept
// (object_test.hpp).
#pragma once

#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "runtime/geometry/spacetime.hpp"
#include "runtime/objects/intelligent_object.hpp"
#include "tracer/counters.hpp"
#include "tracer/hierarchy.hpp"
#include "tracer/thread_state.hpp"

namespace hexant::tracer {

enum class Mode { Spacetime, Frames, Brute };

// "spacetime", "frames", "brute"; throws std::invalid_argument otherwise.
Mode parse_mode(const std::string& name);
const char* mode_name(Mode mode);

// The scene's objects as the tracer holds them: the hierarchy indexes the
// bounded ones; the unbounded ones (planes) are tested on every ray. In a
// thread's mailbox the unbounded ones follow the bounded ones.
struct ObjectSet {
    std::vector<const runtime::IntelligentObject*> bounded;
    std::vector<const runtime::IntelligentObject*> unbounded;

    static ObjectSet of(std::span<const runtime::IntelligentObjectPtr> objects);
    std::size_t size() const { return bounded.size() + unbounded.size(); }
};

// The smallest box the bounded objects' own boxes fit in over [t0, t1]:
// the root cell is this, extended by the eye and the lights.
runtime::Box4 enclosing_box(const ObjectSet& objects, double t0, double t1);

class RayQuery {
  public:
    virtual ~RayQuery() = default;
    // Make ready for rays with times in [t0, t1] (one frame's shutter):
    // the frame-by-frame mode builds that frame's hierarchy here; spacetime
    // mode lets go of the slabs of time outside it; brute force has
    // nothing to do.
    virtual void prepare_frame(double t0, double t1, Counters& counters) = 0;
    // The nearest surface event with s_min < s < s_max.
    virtual std::optional<runtime::ObjectHit> first_hit(const runtime::Ray4& ray, double s_min,
                                                        double s_max, ThreadState& state) const = 0;
    // Does an object that casts a full shadow (casts shadows and lets no
    // light through: IntelligentObject::filters_light) meet the ray with
    // s_min < s < s_max?
    virtual bool occluded(const runtime::Ray4& ray, double s_min, double s_max,
                          ThreadState& state) const = 0;
    // The mailbox size a thread needs.
    virtual std::size_t object_count() const = 0;
    // Statistics (with BuildOptions::count_full): builds what a lazy build
    // left of the hierarchy in use and adds the cells of its full build to
    // counters.cells_full; the frame-by-frame mode counts each earlier
    // frame's as it replaces it.
    virtual void count_full_hierarchy(Counters& counters) const = 0;
    // Records in counters.node_bytes the bytes of hierarchy nodes (spacetime:
    // the most held at once so far; frames: the last frame's hierarchy) and
    // in counters.sweep_bytes the sweeps'.
    virtual void measure_memory(Counters& counters) const = 0;
};

// `animation` is the root's spacetime box (objects, lights and eye over the
// whole time range); the frame-by-frame mode takes its space part.
std::unique_ptr<RayQuery> make_ray_query(Mode mode, ObjectSet objects,
                                         const runtime::Box4& animation,
                                         const BuildOptions& options, Counters& counters);

namespace query_detail {
std::unique_ptr<RayQuery> make_spacetime(ObjectSet objects, const runtime::Box4& animation,
                                         const BuildOptions& options, Counters& counters);
std::unique_ptr<RayQuery> make_frames(ObjectSet objects, const runtime::Box4& animation,
                                      const BuildOptions& options, Counters& counters);
std::unique_ptr<RayQuery> make_brute(ObjectSet objects);

// The unbounded objects, tested on every ray (through the mailbox).
std::optional<runtime::ObjectHit> first_unbounded(const ObjectSet& set, const runtime::Ray4& ray,
                                                  double s_min, double s_max, ThreadState& state);
bool unbounded_occludes(const ObjectSet& set, const runtime::Ray4& ray, double s_min, double s_max,
                        ThreadState& state);
// The root of a hierarchy over `time`: the cost criterion's is the objects'
// own extent (its splits then fall where the objects are); the paper's is
// `given` (the objects, the eye and the lights), as the paper builds it.
runtime::Box4 hierarchy_root(const SweptObjects& swept, const runtime::Box4& given,
                             const BuildOptions& options);
}  // namespace query_detail

}  // namespace hexant::tracer
