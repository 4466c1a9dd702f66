// global_settings { radiosity { } } as POV-Ray 3.7 reads it (parser.cpp,
// Parse_Global_Settings; defaults from its SceneRadiositySettings). The
// tracer's irradiance cache (tracer/radiosity_cache.hpp) and its gathering
// (tracer/radiosity.cpp) use these.
#pragma once

namespace hexant::runtime {

struct RadiositySettings {
    bool enabled = false;  // a radiosity { } block was read
    double brightness = 1.0;
    int count = 35;             // rays a sample gathers with (halved per bounce, at least 5)
    int direction_pool = 1600;  // count's second value: the directions drawn from
    double error_bound = 1.8;
    double gray_threshold = 0.0;
    double low_error_factor = 0.5;  // the error bound's factor during the pretrace
    double minimum_reuse = 0.015;   // fractions of the distance to the eye
    double maximum_reuse = 0.2;
    bool minimum_reuse_set = false, maximum_reuse_set = false;
    int nearest_count = 5;
    int nearest_count_pretrace = 0;  // nearest_count's second value (adaptive pretrace)
    int recursion_limit = 2;
    double max_sample = -1.0;  // below 0: a gathered ray's colour is not limited
    double adc_bailout = 0.01;
    bool normal = false;           // gather about the perturbed normal
    bool media = false;            // gathering rays see media, fog and rainbows
    double pretrace_start = 0.08;  // pretrace block sizes, fractions of the image's larger side
    double pretrace_end = 0.04;
    bool always_sample = false;
    bool subsurface = false;
    bool brilliance = false;
    double default_importance = 1.0;  // #default { radiosity { importance } }

    // The most bounces a radiosity sample gathers (POV-Ray's DEPTH_MAX).
    static constexpr int kMostRecursion = 20;
    static constexpr int kMostNearestCount = 20;
};

}  // namespace hexant::runtime
