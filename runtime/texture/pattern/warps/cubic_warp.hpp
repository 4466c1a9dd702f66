// warp { cubic }: a point projected from the origin onto the cube's face
// its largest coordinate names, and that face unfolded into a cross in the
// unit square (x in quarters, y in thirds), z the distance along that
// coordinate (POV-Ray 3.7's warp_cubic).
#pragma once

#include <cmath>

#include <glm/vec3.hpp>

namespace hexant::runtime::pattern {

inline glm::dvec3 cubic_point(const glm::dvec3& p) {
    double x = p.x, y = p.y, z = p.z;
    const double ax = std::fabs(x), ay = std::fabs(y), az = std::fabs(z);
    if (x >= 0 && x >= ay && x >= az)
        return {0.75 - 0.25 * (z / x + 1.0) / 2.0, 1.0 / 3.0 + (1.0 / 3.0) * (y / x + 1.0) / 2.0,
                x};
    if (y >= 0 && y >= ax && y >= az)
        return {0.25 + 0.25 * (x / y + 1.0) / 2.0, 1.0 - (1.0 / 3.0) * (z / y + 1.0) / 2.0, y};
    if (z >= 0 && z >= ax && z >= ay)
        return {0.25 + 0.25 * (x / z + 1.0) / 2.0, 1.0 / 3.0 + (1.0 / 3.0) * (y / z + 1.0) / 2.0,
                z};
    if (x < 0 && x <= -ay && x <= -az) {
        x = -x;
        return {0.25 * (z / x + 1.0) / 2.0, 1.0 / 3.0 + (1.0 / 3.0) * (y / x + 1.0) / 2.0, x};
    }
    if (y < 0 && y <= -ax && y <= -az) {
        y = -y;
        return {0.25 + 0.25 * (x / y + 1.0) / 2.0, (1.0 / 3.0) * (z / y + 1.0) / 2.0, y};
    }
    z = -z;
    return {1.0 - 0.25 * (x / z + 1.0) / 2.0, 1.0 / 3.0 + (1.0 / 3.0) * (y / z + 1.0) / 2.0, z};
}

}  // namespace hexant::runtime::pattern
