// POV-Ray 3.7's rainbow { } (atmosph.cpp's RAINBOW, parstxtr.cpp's
// Parse_Rainbow, trace.cpp's ComputeRainbow): a band of colours at an
// angle about the antisolar direction, laid over what a ray sees, fainter
// the nearer it ends (exp(-depth / distance)). Read as POV-Ray reads it and
// then prepared as Parse_Rainbow prepares it (finish()), so that at()
// follows ComputeRainbow step for step.
#pragma once

#include <array>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

namespace hexant::runtime {

struct Rainbow {
    // As written (angles in degrees), POV-Ray's defaults.
    glm::dvec3 direction{0.0};  // the antisolar vector
    glm::dvec3 up{0.0, 1.0, 0.0};
    double angle = 0.0, width = 0.0;
    double distance = 1.0e7;  // POV-Ray's MAX_DISTANCE
    double jitter = 0.0;
    // POV-Ray keeps 180 (not turned into radians) when one is not given,
    // which no angle reaches; given, each is halved into radians.
    double arc_angle = 180.0, falloff_angle = 180.0;
    bool arc_given = false, falloff_given = false;
    // color_map { }: value, then red, green, blue, filter, transmit.
    struct Entry {
        double value;
        std::array<double, 5> colour;
    };
    std::vector<Entry> colour_map;

    // After finish(): unit antisolar, up and right vectors, perpendicular;
    // angle and width in radians (angle at the band's inner edge).
    glm::dvec3 right{1.0, 0.0, 0.0};
    double falloff_width = 0.0;

    // Parse_Rainbow's checks and preparation; an error message, or empty.
    std::string finish();
    // ComputeRainbow's colour at map index `index` (gradient x: the map
    // searched at index, linear between entries).
    std::array<double, 5> colour_at(double index) const;
};

// ComputeRainbow over all the rainbows: `colour` seen along unit direction
// `d` to `depth`, `random` a number in [0, 1) for each rainbow's jitter.
// Returns the colour with the bands laid over it (unchanged where none).
template <class Random>
glm::dvec3 through_rainbows(const std::vector<Rainbow>& rainbows, const glm::dvec3& colour,
                            const glm::dvec3& d, double depth, Random&& random);

}  // namespace hexant::runtime

#include "runtime/scene/rainbow_impl.hpp"
