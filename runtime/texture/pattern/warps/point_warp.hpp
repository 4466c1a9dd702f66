// The warps that move a point by a rule of their own, besides a transform
// and turbulence: repeat, black_hole and the mapping warps, each in its
// own file here. A PointWarp is one as the scene wrote it (its numbers
// time functions); a CompiledPointWarp is one ready for the tracer, its
// numbers on one tape, resolved once when none moves.
//
// None of them turns a normal: POV-Ray 3.7's Warp_Normal and UnWarp_Normal
// turn a normal by a pattern's transforms only.
#pragma once

#include <memory>
#include <variant>
#include <vector>

#include <glm/vec3.hpp>

#include "runtime/texture/pattern/warps/black_hole_warp.hpp"
#include "runtime/texture/pattern/warps/mapping_warp.hpp"
#include "runtime/texture/pattern/warps/repeat_warp.hpp"

namespace hexant::runtime {
class TimeTape;
}

namespace hexant::runtime::pattern {

using PointWarp = std::variant<RepeatWarp, BlackHoleWarp, MappingWarp>;

bool depends_on_time(const PointWarp& warp);

class CompiledPointWarp {
  public:
    explicit CompiledPointWarp(const PointWarp& source);
    // The point warped at time t.
    glm::dvec3 apply(const glm::dvec3& p, double t) const;

  private:
    using At = std::variant<RepeatAt, BlackHoleAt, MappingAt>;
    At at(const double* numbers) const;

    PointWarp source_;
    std::shared_ptr<const TimeTape> tape_;  // its numbers, when one moves
    At fixed_;                              // else the warp at every instant
};

}  // namespace hexant::runtime::pattern
