// Each object is tested at most once per ray, however many leaves hold it:
// the first test's answer (hit or miss, over the whole ray segment) is kept
// under the ray's stamp, so a hit that lies beyond the current cell is found
// again, not recomputed, when the traversal reaches the cell that holds it.
// One mailbox per thread.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "runtime/intelligent_object.hpp"

namespace hexant::tracer {

class Mailbox {
public:
    explicit Mailbox(std::size_t objects = 0) : stamps_(objects, 0), answers_(objects) {}

    // Starts a new ray: every earlier answer becomes stale.
    void next_ray() {
        if (++stamp_ == 0) {  // wrapped after 2^32 rays: clear for real
            std::fill(stamps_.begin(), stamps_.end(), 0);
            stamp_ = 1;
        }
    }
    void resize(std::size_t objects) {
        stamps_.assign(objects, 0);
        answers_.assign(objects, std::nullopt);
    }

    // The kept answer for object i on this ray, if it was tested.
    const std::optional<runtime::ObjectHit>* find(std::uint32_t i) const {
        return stamps_[i] == stamp_ ? &answers_[i] : nullptr;
    }
    const std::optional<runtime::ObjectHit>& keep(std::uint32_t i,
                                                  std::optional<runtime::ObjectHit> answer) {
        stamps_[i] = stamp_;
        return answers_[i] = std::move(answer);
    }

private:
    std::vector<std::uint32_t> stamps_;
    std::vector<std::optional<runtime::ObjectHit>> answers_;
    std::uint32_t stamp_ = 1;
};

}  // namespace hexant::tracer
