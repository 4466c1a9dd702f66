// warp { repeat <direction> [offset <v>] [flip <v>] }: the slab of the
// pattern between 0 and the direction's length along its axis, copied
// along that axis; each copy shifted by offset times its number, and every
// odd copy mirrored in the axes flip names (POV-Ray 3.7's Warp_EPoint,
// REPEAT_WARP; the record and its parsing: Create_Warp and Parse_Warp).
#pragma once

#include <cmath>

#include <glm/vec3.hpp>

#include "runtime/time/time_function.hpp"
#include "runtime/time/vector_function.hpp"

namespace hexant::runtime::pattern {

// As the scene wrote it: the one axis the direction names (the language
// refuses a direction naming none or several, as Parse_Warp does) and the
// direction's component along it.
struct RepeatWarp {
    int axis = 0;
    TimeFunction width = 1.0;
    Vector3Function offset{{0.0, 0.0, 0.0}};
    Vector3Function flip{{0.0, 0.0, 0.0}};  // a non-zero component mirrors that axis

    bool depends_on_time() const {
        return width.depends_on_time() || offset.depends_on_time() || flip.depends_on_time();
    }
};

// At one instant, as POV-Ray keeps it: the width in single precision (its
// REPEAT record's SNGL Width), flip as -1 where mirrored, else 1.
struct RepeatAt {
    int axis = 0;
    float width = 1.0f;
    glm::dvec3 offset{0.0};
    glm::dvec3 flip{1.0};
};

inline RepeatAt repeat_at(int axis, double width, const glm::dvec3& offset,
                          const glm::dvec3& flip) {
    return {axis,
            static_cast<float>(width),
            offset,
            {flip.x != 0.0 ? -1.0 : 1.0, flip.y != 0.0 ? -1.0 : 1.0, flip.z != 0.0 ? -1.0 : 1.0}};
}

inline glm::dvec3 repeat_point(const RepeatAt& r, const glm::dvec3& p) {
    // The copy's number is a float (SNGL BlkNum), and its product with the
    // width is taken in single precision before the subtraction, as there.
    const float block = static_cast<float>(std::floor(p[r.axis] / static_cast<double>(r.width)));
    glm::dvec3 q = p;
    q[r.axis] = p[r.axis] - static_cast<double>(block * r.width);
    // ((int)BlkNum & 1; a number beyond int's range converts to INT_MIN on
    // the machines POV-Ray runs on: even.)
    const bool odd = std::fabs(block) < 2147483648.0f && (static_cast<long>(block) & 1) != 0;
    if (odd) {
        q *= r.flip;
        if (r.flip[r.axis] < 0.0) q[r.axis] = static_cast<double>(r.width) + q[r.axis];
    }
    return q + static_cast<double>(block) * r.offset;
}

}  // namespace hexant::runtime::pattern
