// Dispersion: a ray of every colour that meets a surface whose sides
// disperse light differently splits into spectral bands, each bent by its
// own ior and tinted by its own hue (POV-Ray 3.7's ComputeRefraction,
// render/trace.cpp). POV-Ray traces every band there; hexant, where a
// pixel's samples are jittered, gives each sample one band from its own
// dimension of the sample sequence (kWavelength, stratified with the
// pixel's place, time, lens and lights: the seed's fifth dimension), so
// that the pixel's mean is POV-Ray's image and costs one ray, not
// dispersion_samples. Unjittered samples and radiosity's gathering rays
// trace every band, as POV-Ray.
#pragma once

#include <algorithm>

#include <glm/vec3.hpp>

#include "tracer/inside.hpp"
#include "tracer/sample_pattern.hpp"
#include "tracer/spectral_band.hpp"
#include "tracer/thread_state.hpp"

namespace hexant::tracer {

// The light through a dispersive surface for a ray of every colour, given
// `behind(eta, reflected)`: the light that comes through along a ratio of
// indices eta (refracted, or reflected inside where eta cannot bend it).
// While a band's light is traced, state.band is that band.
template <typename Behind>
glm::dvec3 dispersed(const Inside::Ratio& ratio, Behind&& behind, ThreadState& state) {
    const int bands = ratio.dispersion_samples;
    const SpectralBand every = state.band;
    const SampleIndex& s = state.sample;
    glm::dvec3 sum(0.0);
    bool reflected = false;
    if (s.jitter && state.radiosity.depth == 0) {
        const double u = joint_dimension(s.seed, s.index, s.count, kWavelength, true);
        state.band = SpectralBand::of(std::min(bands - 1, static_cast<int>(u * bands)), bands);
        sum = state.band.hue() * behind(state.band.ior(ratio.ior, ratio.dispersion), reflected);
        ++state.counters.dispersed_rays;
    } else {
        for (int i = 0; i < bands; ++i) {
            state.band = SpectralBand::of(i, bands);
            sum +=
                state.band.hue() * behind(state.band.ior(ratio.ior, ratio.dispersion), reflected);
        }
        sum /= static_cast<double>(bands);
        state.counters.dispersed_rays += static_cast<std::uint64_t>(bands);
    }
    state.band = every;
    return sum;
}

}  // namespace hexant::tracer
