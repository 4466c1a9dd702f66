// An object met by a ray during a walk: tested once per ray over the ray's
// whole segment (mailbox.hpp), counted, and, for shadow rays, asked only
// whether it occludes (IntelligentObject::occluded).
#pragma once

#include <cstdint>
#include <optional>

#include "runtime/objects/intelligent_object.hpp"
#include "tracer/thread_state.hpp"

namespace hexant::tracer {

struct ObjectTest {
    const runtime::Ray4& ray;
    double s_min, s_max;  // the whole segment, whatever the walk has found
    ThreadState& state;
    // The index of the object whose hit is best so far (nearest()).
    mutable std::uint32_t best_index = UINT32_MAX;

    // Object `index` (its mailbox slot): a nearer hit than best_s replaces
    // best, and so does one at the same distance from an object earlier in
    // the scene (coincident surfaces: the first written shows, as in
    // POV-Ray, whatever order a walk meets them in). Returns whether it did.
    bool nearest(std::uint32_t index, const runtime::IntelligentObject& object,
                 std::optional<runtime::ObjectHit>& best, double& best_s) const {
        // (An object hidden from this kind of ray: no_image, no_reflection.)
        if (object.flags().hidden_from & state.sight) return false;
        std::int32_t slot = state.mailbox.find(index);
        if (slot == Mailbox::kUntested) {
            ++state.counters.object_tests;
            slot = state.mailbox.keep(index, object.intersect(ray, s_min, s_max));
        } else {
            ++state.counters.mailbox_hits;
        }
        if (slot < 0) return false;
        const runtime::ObjectHit& hit = state.mailbox.hit(slot);
        if (!(hit.s < best_s) && !(hit.s == best_s && best && index < best_index)) return false;
        best = hit;
        best_s = hit.s;
        best_index = index;
        return true;
    }

    // Does object `index` cast a full shadow on the segment (one that may
    // let light through is the shader's to filter)?
    bool occludes(std::uint32_t index, const runtime::IntelligentObject& object) const {
        if (!object.casts_full_shadow() || &object == state.leaving) return false;
        if (state.mailbox.find(index) != Mailbox::kUntested) {
            ++state.counters.mailbox_hits;
            return false;  // tested on this ray already: it did not occlude
        }
        ++state.counters.object_tests;
        if (object.occluded(ray, s_min, s_max)) return true;
        state.mailbox.keep(index, std::nullopt);
        return false;
    }
};

}  // namespace hexant::tracer
