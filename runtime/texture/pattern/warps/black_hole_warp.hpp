// warp { black_hole <center>, radius [strength S] [falloff F] [inverse]
// [repeat <v>] [turbulence <v>] [type T] }: the pattern within the radius
// drawn toward the centre (pushed away when inverse), each point read
// min(1, ((radius - d) / radius)^falloff * strength) of its distance d
// further out (in when inverse); repeat copies the hole every repeat step
// along each axis it names, and turbulence moves each copy's centre by up
// to its amount (POV-Ray 3.7's Warp_EPoint, BLACK_HOLE_WARP; Parse_Warp;
// Check_BH_Parameters).
#pragma once

#include <vector>

#include <glm/vec3.hpp>

#include "runtime/time/time_function.hpp"
#include "runtime/time/vector_function.hpp"

namespace hexant::runtime::pattern {

// As the scene wrote it.
struct BlackHoleWarp {
    Vector3Function center{{0.0, 0.0, 0.0}};
    TimeFunction radius = 1.0;
    TimeFunction strength = 1.0;
    TimeFunction falloff = 2.0;  // POV-Ray's Power
    bool inverse = false;
    int type = 0;  // only type 0 moves points (POV-Ray has no other yet)
    // repeat and turbulence in the order written: POV-Ray's parser checks
    // them against the centre and radius after each (Check_BH_Parameters),
    // moving the centre and widening the repeat; the order decides how.
    struct Placement {
        bool repeat = true;  // else turbulence
        Vector3Function amount;
    };
    std::vector<Placement> placements;

    bool depends_on_time() const;
};

// At one instant, after Check_BH_Parameters.
struct BlackHoleAt {
    glm::dvec3 center{0.0};
    glm::dvec3 repeat{0.0};
    glm::dvec3 uncertainty{0.0};
    double radius = 1.0, strength = 1.0, power = 2.0;
    bool inverse = false, repeats = false, uncertain = false;
    int type = 0;
};

// The black hole at one instant from its numbers at that instant: the
// centre, radius, strength, falloff, then each placement's amount.
BlackHoleAt black_hole_at(const BlackHoleWarp& warp, const double* numbers);
// Its numbers in that order.
std::vector<TimeFunction> black_hole_numbers(const BlackHoleWarp& warp);

glm::dvec3 black_hole_point(const BlackHoleAt& hole, const glm::dvec3& p);

}  // namespace hexant::runtime::pattern
