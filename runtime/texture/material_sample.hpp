// A texture evaluated at one event: plain numbers for the shader. Colours
// are linear (assumed_gamma 1.0), as POV-Ray holds them.
#pragma once

#include <glm/vec3.hpp>

namespace hexant::runtime {

struct MaterialSample {
    glm::dvec3 colour{0.0};  // the pigment's red, green, blue
    double filter = 0.0;
    double transmit = 0.0;
    // POV-Ray 3.7's finish, at the event's time.
    glm::dvec3 ambient{0.1};  // a colour, as emission
    double diffuse = 0.6;
    double diffuse_back = 0.0;  // light from behind the surface (Finish::diffuse_back)
    double brilliance = 1.0;
    double phong = 0.0;
    double phong_size = 40.0;
    double specular = 0.0;
    double roughness = 0.05;
    glm::dvec3 reflection{0.0};
    glm::dvec3 emission{0.0};
    double crand = 0.0;                // the most a light's diffuse intensity loses at random
    double metallic = 0.0;             // highlights' tint by the pigment
    double reflection_metallic = 0.0;  // the reflection's
    // Variable reflection (Finish): `reflection` is the minimum.
    glm::dvec3 reflection_max{0.0};
    double reflection_falloff = 1.0;
    double reflection_power = 1.0;  // 1 / the written exponent
    bool reflection_fresnel = false;
    bool conserve_energy = false;
    double irid = 0.0;  // iridescence (Finish)
    double irid_thickness = 0.0;
    double irid_turbulence = 0.0;
    double ior = 1.0;  // the interior's index of refraction
};

}  // namespace hexant::runtime
