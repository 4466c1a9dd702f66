// Each object is tested at most once per ray, however many cells hold it:
// the first test's answer (hit or miss, over the whole ray segment) is kept
// under the ray's stamp, so a hit that lies beyond the current cell is found
// again, not recomputed, when the traversal reaches the cell that holds it.
// One mailbox per thread: eight bytes per object, plus the hits of the
// current ray.
#pragma once

#include <algorithm>
#include <cstdint>
#include <optional>
#include <vector>

#include "runtime/objects/intelligent_object.hpp"

namespace hexant::tracer {

class Mailbox {
  public:
    static constexpr std::int32_t kUntested = -2;
    static constexpr std::int32_t kMiss = -1;

    explicit Mailbox(std::size_t objects = 0) : stamps_(objects, 0), slots_(objects, 0) {}

    // Starts a new ray: every earlier answer becomes stale.
    void next_ray() {
        hits_.clear();
        if (++stamp_ == 0) {  // wrapped after 2^32 rays: clear for real
            std::fill(stamps_.begin(), stamps_.end(), 0);
            stamp_ = 1;
        }
    }
    void resize(std::size_t objects) {
        stamps_.assign(objects, 0);
        slots_.assign(objects, 0);
    }

    // kUntested, kMiss, or the index of the kept hit (see hit()).
    std::int32_t find(std::uint32_t i) const {
        return stamps_[i] == stamp_ ? slots_[i] : kUntested;
    }
    const runtime::ObjectHit& hit(std::int32_t slot) const { return hits_[std::size_t(slot)]; }

    // Keeps the answer for object i on this ray; returns what find() will.
    std::int32_t keep(std::uint32_t i, const std::optional<runtime::ObjectHit>& answer) {
        stamps_[i] = stamp_;
        if (!answer) return slots_[i] = kMiss;
        hits_.push_back(*answer);
        return slots_[i] = std::int32_t(hits_.size() - 1);
    }

  private:
    std::vector<std::uint32_t> stamps_;
    std::vector<std::int32_t> slots_;
    std::vector<runtime::ObjectHit> hits_;
    std::uint32_t stamp_ = 1;
};

}  // namespace hexant::tracer
