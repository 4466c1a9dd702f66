// Finishes of equal numbers as one block: what reading a scene does with
// each finish { } it finishes, so that 10^5 objects written with the same
// `finish { phong 0.6 }` hold one Finish between them (8 to 16 bytes each
// where each held 280: issue 43's memory). POV-Ray shares a finish between
// the objects that name one #declare'd finish; this shares equal ones
// however they were written.
//
// Only a finish whose every amount is a constant and that notes nothing
// unrendered is pooled (equal constants are the same finish; a function
// of time is compared by nothing cheaper than its identity). The tracer's
// compiled finishes are shared the same way (TextureEvaluator::compile).
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <vector>

#include "runtime/texture/material.hpp"

namespace hexant::runtime {

class FinishPool {
  public:
    // The pool's block for a finish equal to `finish` (the first such one
    // given), or a block of its own if it is not pooled.
    std::shared_ptr<Finish> share(Finish&& finish);
    // Distinct finishes pooled.
    std::size_t size() const { return pool_.size(); }

  private:
    // The finish's amounts' bits and flags, in a fixed order.
    std::map<std::vector<std::uint64_t>, std::shared_ptr<Finish>> pool_;
};

}  // namespace hexant::runtime
