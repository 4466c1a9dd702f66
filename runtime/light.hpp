// A light source record after POV-Ray's light_source.
#pragma once

#include "runtime/lifetime.hpp"
#include "runtime/transform.hpp"
#include "runtime/vector_function.hpp"

namespace hexant::runtime {

struct LightRecord {
    Vector3Function position;
    ColourFunction colour;
    bool shadowless = false;
    bool spotlight = false;   // parsed; rendered as a point light for now
    bool area_light = false;  // parsed; rendered as a point light for now
    // parallel: its rays all run from `position` toward `point_at`, and a
    // shadow reaches back to the plane through `position` across them
    // (POV-Ray's ComputeOneWhiteLightRay).
    bool parallel = false;
    Vector3Function point_at{{0.0, 0.0, 1.0}};  // POV-Ray's default
    TimeFunction radius = 30.0, falloff = 45.0, tightness = 0.0;
    Transform transform;
    // When it shines: always, or the pieces of time of the clock-dependent
    // branches it was made under.
    Lifetime lifetime;

    bool depends_on_time() const { return !lifetime.is_always() || position.depends_on_time() || colour.depends_on_time() ||
                                          transform.depends_on_time(); }
};

}  // namespace hexant::runtime
