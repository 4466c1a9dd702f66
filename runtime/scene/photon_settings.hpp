// Photon mapping as POV-Ray 3.7 reads it (parser.cpp: Parse_Global_Settings'
// photons { }, Parse_Object_Mods' and Parse_Light_Source's photons blocks;
// defaults from there). The tracer shoots photons from each light at each
// target (tracer/photon_shooting.hpp), keeps those that land on surfaces
// after a reflection or refraction in a map (tracer/photon_map.hpp) and
// adds their light at every surface it shades: caustics.
#pragma once

#include <cstdint>
#include <string>

namespace hexant::runtime {

struct PhotonSettings {
    bool enabled = false;  // a photons { } block with gather's maximum above 0
    // spacing: the distance between photons at the target (times its
    // `target` factor), or, with `count` (above 0), chosen so that about
    // that many photons are shot (POV-Ray's PhotonEstimationTask).
    double spacing = 1.0;
    long long count = 0;
    int gather_min = 20, gather_max = 100;  // photons a gather looks for
    double jitter = 0.4;                    // of a photon's direction, in its cell
    int max_trace_level = -1;               // below 0: global_settings' max_trace_level
    double adc_bailout = -1.0;              // below 0: the scene's (1/255)
    double autostop = 0.5;                  // a fraction of the target's angular radius
    // expand_thresholds: a gather that found fewer than gather_min photons
    // grows its radius once when the density changes less than
    // expand_tolerance or it finds fewer than expand_min.
    double expand_tolerance = 0.2;
    int expand_min = 35;
    // radius: the gather's radius (below 0: from the map's density), its
    // factor, and the media map's.
    double radius = -1.0, radius_factor = 1.0;
    double media_radius = -1.0, media_radius_factor = 1.0;
    // media MAX_STEPS, FACTOR: photons left in media along their way, at
    // most MAX_STEPS an interval, FACTOR times the surface spacing apart
    // (0: none).
    int media_max_steps = 0;
    double media_spacing_factor = 1.0;
};

// An object's photons { } (its members take it, as POV-Ray's
// Post_Process promotes the flags to a CSG's children).
struct ObjectPhotons {
    double target = 0.0;  // spacing factor; 0: not a target
    // refraction and reflection on (1), off (-1) or not said (0): a
    // photon follows them where the target or its light says on and
    // neither says off.
    std::int8_t refraction = 0, reflection = 0;
    bool collect = true;        // photons landing on it are kept
    bool pass_through = false;  // photons go on through it unchanged
    bool operator==(const ObjectPhotons&) const = default;
};

// A light's photons { }.
struct LightPhotons {
    std::int8_t refraction = 0, reflection = 0;
    bool area_light = false;  // shoot from the area light's grid (warned: from its centre)
    bool operator==(const LightPhotons&) const = default;
};

}  // namespace hexant::runtime
