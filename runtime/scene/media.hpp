// POV-Ray's participating media, media { }: a volume that absorbs, emits
// and scatters light, inside an object's interior { } or, written at the
// top of the scene, everywhere outside non-hollow objects (the atmosphere).
// Its numbers and sampling rules are POV-Ray 3.7's (media.cpp, the parser's
// Parse_Media); the tracer integrates it (tracer/media.hpp). Colours may be
// functions of time, and the densities move with clock as pigments do.
#pragma once

#include <vector>

#include "runtime/motion/transform.hpp"
#include "runtime/time/vector_function.hpp"

namespace hexant::runtime {

struct Pigment;  // runtime/texture/material.hpp, which holds media in its Interior

struct Media {
    // scattering { TYPE, ... }: POV-Ray's phase functions.
    enum class Scattering : int {
        Isotropic = 1,
        MieHazy = 2,
        MieMurky = 3,
        Rayleigh = 4,
        HenyeyGreenstein = 5,
    };
    // Sampling, by POV-Ray 3.5's defaults (method 3, one interval, 10
    // samples); a scene of #version below 3.5 gets the older ones
    // (legacy()).
    int method = 3;     // 1 random, 2 jittered even, 3 adaptive
    int intervals = 1;  // at least 1
    int min_samples = 10, max_samples = 10;
    double jitter = 0.0;
    double aa_threshold = 0.1;
    int aa_level = 3;
    double confidence = 0.9, variance = 1.0 / 128.0, ratio = 0.9;
    // Per unit of length: absorption and emission, and the scattering
    // colour with its phase function; extinction scales the scattering's
    // share of the extinction (POV-Ray's sc_ext).
    ColourFunction absorption{}, emission{}, scattering{};
    Scattering type = Scattering::Isotropic;
    TimeFunction eccentricity = 0.0;  // Henyey-Greenstein only
    TimeFunction extinction = 1.0;
    // density { }: patterns whose colours multiply the coefficients,
    // multiplied together (POV-Ray's Evaluate_Density_Pigment); none is a
    // constant density of 1. Each maps its space to the media's.
    std::vector<Pigment> density;
    bool collect = true;  // whether photons passing are left in it (media photons)

    // POV-Ray's defaults before 3.5 (method 1, 10 intervals, 1 sample).
    // (Out of line: a Media made here, where Pigment is incomplete, is an
    // error for clang with libstdc++ 12, whose vector is constexpr.)
    static Media legacy();
    // Moves the densities written so far (POV-Ray's Transform_Density: a
    // density written after a transformation is not moved by it).
    void transform_by(const TransformStep& step);
    void transform_by(const Transform& step);
    bool depends_on_time() const;
};

}  // namespace hexant::runtime
