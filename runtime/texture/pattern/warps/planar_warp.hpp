// warp { planar [<normal>, distance] }: every point moved onto the plane
// (x, y, distance), turned for the normal (POV-Ray 3.7's warp_planar).
#pragma once

#include "runtime/texture/pattern/warps/mapping_warp.hpp"

namespace hexant::runtime::pattern {

inline glm::dvec3 planar_point(const MappingAt& m, const glm::dvec3& p) {
    return oriented(m.orientation, p.x, p.y, m.distance);
}

}  // namespace hexant::runtime::pattern
