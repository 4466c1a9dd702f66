#include "runtime/scene/rainbow.hpp"

#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>

namespace hexant::runtime {

std::string Rainbow::finish() {
    constexpr double kEpsilon = 1.0e-10;                      // POV-Ray's EPSILON
    constexpr double kHalfDegree = std::numbers::pi / 360.0;  // M_PI_360
    if (arc_given) arc_angle *= kHalfDegree;
    if (falloff_given) falloff_angle *= kHalfDegree;
    // (Parse_Rainbow: an arc angle alone is the falloff angle too.)
    if (arc_given && !falloff_given) falloff_angle = arc_angle;
    if (arc_angle < falloff_angle)
        return "the rainbow's arc_angle is smaller than its falloff_angle";
    falloff_width = arc_angle - falloff_angle;
    if (std::fabs(glm::dot(direction, direction)) < kEpsilon)
        return "the rainbow's direction is the zero vector";
    if (std::fabs(glm::dot(up, up)) < kEpsilon) return "the rainbow's up vector is the zero vector";
    direction = glm::normalize(direction);
    up = glm::normalize(up);
    if (std::fabs(1.0 - std::fabs(glm::dot(up, direction))) < kEpsilon)
        return "the rainbow's up and direction vectors are colinear";
    // Up and antisolar made perpendicular, as POV-Ray makes them.
    right = glm::normalize(glm::cross(up, direction));
    up = glm::normalize(glm::cross(direction, right));
    angle = (angle - 0.5 * width) * (std::numbers::pi / 180.0);
    width *= std::numbers::pi / 180.0;
    return {};
}

std::array<double, 5> Rainbow::colour_at(double index) const {
    // POV-Ray's Search_Blend_Map: below the first entry its colour, above
    // the last the last's, between two a linear blend.
    if (index <= colour_map.front().value) return colour_map.front().colour;
    for (std::size_t i = 1; i < colour_map.size(); ++i) {
        const Entry& hi = colour_map[i];
        if (index > hi.value) continue;
        const Entry& lo = colour_map[i - 1];
        const double span = hi.value - lo.value;
        const double w = span > 0.0 ? (index - lo.value) / span : 1.0;
        std::array<double, 5> c;
        for (std::size_t k = 0; k < 5; ++k) c[k] = lo.colour[k] + w * (hi.colour[k] - lo.colour[k]);
        return c;
    }
    return colour_map.back().colour;
}

}  // namespace hexant::runtime
