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
#include "tracer/photon_map.hpp"

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
// that reach the ray (none for a shadow ray). `photons`: the frame's media
// photons (null: none), whose light each sample scatters too, lit by a
// light or not (POV-Ray's ComputeMediaPhotons: the photons within a sphere
// over its volume, each as a light from its direction).
glm::dvec3 through_media(const std::vector<const runtime::MediaVolume::One*>& media,
                         const MediaRay& ray, const std::vector<MediaLight>& lights,
                         MediaRandom& random, const MediaLightFn& light_at,
                         const glm::dvec3& colour, const PhotonMap* photons = nullptr);

// Where a photon's way through media leaves media photons (POV-Ray's
// DepositMediaPhotons): every `spread` x `depth` x `spacing_factor` along
// the way (the photons' spacing there; without depth for a parallel
// light), at most `max_steps` in an interval (then farther apart), each
// jittered by `jitter`. `keep` receives each photon's place, its distance
// along the way and its light: the photon's light where it entered, times
// the spacing and the spread and, for a light that is not parallel, the
// distance from the light (the volume a photon stands for, less the
// spread squared and distance squared the caller multiplies in as for a
// surface photon).
struct MediaPhotonDeposit {
    double spread = 0.0;
    double depth = 0.0;  // the photon's way from its light to the way's start
    bool parallel = false;
    int max_steps = 0;
    double spacing_factor = 1.0;
    double jitter = 0.4;
    std::function<void(const glm::dvec3& point, double along, const glm::dvec3& colour)> keep;
};

// A photon's light `colour` after its way `ray` through `media` (POV-Ray's
// ComputeMediaAndDepositPhotons for a photon ray): dimmed by their optical
// depth, sampled as `deposit` places its photons (null: no photons left,
// the media's own samples). Media without extinction leave none and dim
// nothing, as in POV-Ray.
glm::dvec3 photon_through_media(const std::vector<const runtime::MediaVolume::One*>& media,
                                const MediaRay& ray, MediaRandom& random,
                                const MediaPhotonDeposit* deposit, const glm::dvec3& colour);

}  // namespace hexant::tracer
