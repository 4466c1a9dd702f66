// A finite speed of light (Glassner's seed paper, "Spacetime rays": "the
// time component of the direction vector ... set to a value consistent with
// the speed of light in the database"): light seen at time t along a ray left the event s scene
// units away at t - s / C, so every ray the renderer casts (camera, shadow, reflected, refracted)
// runs back in time as it goes, its 4D direction (d, -|d| / C). A fast object is then seen where it
// was when the light left it. The intelligent objects and the hierarchy's walk already answer such
// rays (a ray whose time changes crosses cells in time too).
//
// The animation has a first instant; before it the scene is not defined
// (its parameters were checked over the animation's time only). A ray that
// would run back past `floor` (the root cell's first instant) goes on from
// there at that instant, as if the scene had stood still before the
// animation began: two pieces, the first travelling in time, the second at
// one instant.
#pragma once

#include <cmath>
#include <limits>
#include <optional>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "runtime/geometry/spacetime.hpp"

namespace hexant::tracer {

struct LightTravel {
    // 1 / C in clock units per scene unit; 0: light is instant (C infinite),
    // and every ray has direction.w exactly 0, as it always had.
    double time_per_distance = 0.0;
    // The earliest time a ray reaches (see above).
    double floor = -std::numeric_limits<double>::infinity();

    bool instant() const { return time_per_distance == 0.0; }

    // The ray from (origin, t) along `direction` (any length): its w is
    // -|direction| / C, 0 when instant.
    runtime::Ray4 ray(const glm::dvec3& origin, double t, const glm::dvec3& direction) const {
        const double w = instant() ? 0.0 : -time_per_distance * glm::length(direction);
        return {runtime::Event(origin, t), runtime::Event(direction, w)};
    }

    // Where a travelling ray reaches the floor: its parameter there (the
    // first piece's end), infinity when it never does (instant, or C so
    // large that it does not within double range).
    static double floor_parameter(const runtime::Ray4& ray, double floor) {
        if (!(ray.direction.w < 0.0)) return std::numeric_limits<double>::infinity();
        const double s = (ray.origin.w - floor) / -ray.direction.w;
        return s > 0.0 ? s : 0.0;
    }
    // The second piece: from the floor event on, at the floor's instant.
    static runtime::Ray4 held_piece(const runtime::Ray4& ray, double s_floor, double floor) {
        runtime::Event origin = ray.at(s_floor);
        origin.w = floor;
        runtime::Event direction = ray.direction;
        direction.w = 0.0;
        return {origin, direction};
    }
};

}  // namespace hexant::tracer
