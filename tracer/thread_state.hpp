// What one thread carries between rays: its mailbox, its counters and the
// shader's scratch space.
#pragma once

#include <cstdint>
#include <deque>
#include <vector>

#include <glm/vec3.hpp>

#include "runtime/objects/intelligent_object.hpp"
#include "runtime/texture/texture_evaluator.hpp"
#include "tracer/counters.hpp"
#include "tracer/mailbox.hpp"
#include "tracer/radiosity_cache.hpp"
#include "tracer/spectral_band.hpp"
#include "tracer/time_index.hpp"

namespace hexant::tracer {

// What the shader learns at one hit, kept per trace depth so that a hit's
// reflected and refracted rays do not overwrite it, and reused from hit to
// hit so that shading allocates nothing once warm.
struct ShadingScratch {
    runtime::TextureSample texture;
    // Per light, what is known of it at this hit: nothing yet; that it
    // does not shine here; where it lies (its direction and how far a
    // shadow ray looks); then whether a shadow ray reached it. Shared by
    // every layer and map entry at the hit, as POV-Ray's lightColorCache
    // is, so that each light's shadow ray is cast once.
    struct Light {
        enum class State { Unknown, Dark, Placed, Seen, Shadowed };
        State state = State::Unknown;
        glm::dvec3 to_light{0.0};
        double reach = 0.0;
        glm::dvec3 colour{0.0};
    };
    std::vector<Light> lights;
};

// The pixel sample a primary ray carries (tracer/sample_pattern.hpp): its
// set's seed, its index and count in the set, and whether it is jittered.
// The shader draws the further dimensions of distributed ray tracing from
// it (sample_pair), so that they too depend on (frame, pixel, sample) only.
struct SampleIndex {
    std::uint32_t seed = 0, index = 0, count = 1;
    bool jitter = false;
};

// Where radiosity stands on the path being traced (tracer/shader_radiosity.cpp):
// how many gathering bounces deep it is (0: not on a gathering ray; POV-Ray's
// radiosityRecursionDepth), and where records gathered now are kept: the
// pretrace block's list, a final-trace gather's own, or nowhere.
struct RadiosityPath {
    int depth = 0;
    bool pretrace = false;
    std::vector<RadiosityRecord>* kept = nullptr;
    // The final trace's records of the pixel whose samples are being
    // traced (its run of samples in a round, ThreadState::pixel_run): the
    // pixel's later samples reuse them, as POV-Ray's final trace reuses a
    // tile's, without a record depending on another pixel's thread.
    std::vector<RadiosityRecord> pixel;
    std::uint64_t pixel_run = ~std::uint64_t(0);
};

struct ThreadState {
    Mailbox mailbox;
    Counters counters;
    SampleIndex sample{};
    // The kind of ray being walked (runtime::RaySight): objects hidden from
    // it are passed by (tracer/object_test.hpp).
    std::uint8_t sight = runtime::kSightAll;
    // A flat object the shadow ray being walked leaves, heading away from
    // it: the ray cannot meet it, and ObjectTest::occludes passes it by
    // (runtime::IntelligentObject::flat). Null for every other ray.
    const runtime::IntelligentObject* leaving = nullptr;
    // This thread's copy of the spacetime hierarchy's time index.
    LocalTimeIndex time_index{};
    // Of the rays on the path being traced, how many passed straight
    // through a surface (the same ior on both sides): POV-Ray traces those
    // as the ray continued, no new trace level (TraceRay's continuedRay),
    // so a ray's level is its depth less these (tracer/shader.cpp).
    int straight_passes = 0;
    RadiosityPath radiosity{};
    // The spectral band the path being traced took at a dispersive
    // surface (none: a ray of every colour; tracer/spectral_band.hpp).
    SpectralBand band{};
    // The squared error (linear light, the mean of the channels) of the
    // photon map's estimates the sample being traced took on the surfaces
    // its camera ray saw (Shader::photon_light): the photon map's noise,
    // the same for every sample of a frame, which the blocks' estimate of
    // the pixel's noise cannot see. Reset by the renderer per sample.
    double photon_variance = 0.0;
    // Counts the runs of samples this thread has traced, one pixel's
    // samples of one round each (sample_frame): what a pixel's samples
    // share is kept within one run.
    std::uint64_t pixel_run = 0;
    std::deque<ShadingScratch>
        shading{};  // by depth (a deque: a deeper one leaves the others in place)
    ShadingScratch& shading_at(int depth) {
        while (shading.size() <= static_cast<std::size_t>(depth)) shading.emplace_back();
        return shading[static_cast<std::size_t>(depth)];
    }
};

}  // namespace hexant::tracer
