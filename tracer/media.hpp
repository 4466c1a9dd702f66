// Participating media along a ray, as POV-Ray 3.7 integrates them
// (source/backend/interior/media.cpp, MediaFunction::ComputeMedia): the
// ray's stretch split into the pieces the lights reach (spotlight cones,
// cylinder beams) and into the largest `intervals` of its media, each
// sampled by the method of that media (1: at random, 2: evenly with
// jitter, 3: adaptively between the ends, POV-Ray's default); each
// sample's extinction, emission and light scattered toward the viewer by
// the media's phase functions; the colour behind dimmed by the optical
// depth and the light gathered added. Every sample is taken at the ray's
// own time, so media that move with clock blur as objects do.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <vector>

#include <glm/vec3.hpp>

#include "runtime/scene/media_volume.hpp"
#include "tracer/inside.hpp"

namespace hexant::tracer {

// A light as media see it along one ray: which of the shader's lights,
// and the stretch of the ray it reaches (ShadedLight::media_interval).
struct MediaLight {
    std::size_t index = 0;
    double s0 = 0.0, s1 = 0.0;
};

// The light of one of the shader's lights arriving at a point in the
// media at the ray's time, after its shadow ray (zero when shadowed), and
// the unit direction toward it.
using MediaLightFn =
    std::function<glm::dvec3(std::size_t light, const glm::dvec3& point, glm::dvec3& to_light)>;

// A stream of numbers in [0, 1) for methods 1 and 2 and jitter: POV-Ray
// draws them from its own generator; here each ray's are its own,
// seeded by the sample, so images do not depend on the threads.
class MediaRandom {
  public:
    explicit MediaRandom(std::uint64_t seed) : state_(seed * 0x9E3779B97F4A7C15ull + 1) {}
    double next();

  private:
    std::uint64_t state_;
};

struct MediaRay {
    glm::dvec3 origin{0.0}, direction{0.0};  // direction: unit
    double depth = 0.0;                      // to the surface hit (or POV-Ray's 2e10)
    double time = 0.0;
    bool shadow = false;  // a shadow ray: extinction only
};

// `colour`, the light arriving at the ray's end from beyond, as it reaches
// the ray's origin through `media` (every media of every interior the ray
// is inside, or the atmosphere's): dimmed by their optical depth and with
// what they emit and scatter toward the origin added. `lights`: the lights
// that reach the ray (none for a shadow ray).
glm::dvec3 through_media(const std::vector<const runtime::MediaVolume::One*>& media,
                         const MediaRay& ray, const std::vector<MediaLight>& lights,
                         MediaRandom& random, const MediaLightFn& light_at,
                         const glm::dvec3& colour);

}  // namespace hexant::tracer
