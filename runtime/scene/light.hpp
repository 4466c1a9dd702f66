// A light source record after POV-Ray's light_source.
#pragma once

#include <memory>
#include <optional>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "runtime/motion/transform.hpp"
#include "runtime/scene/photon_settings.hpp"
#include "runtime/time/lifetime.hpp"
#include "runtime/time/vector_function.hpp"

namespace hexant::runtime {

// POV-Ray 3.7's area_light: a grid of size1 by size2 point lights spread
// along axis1 and axis2 about the light's position, each shadow ray aimed
// at one of them (jittered within its cell with `jitter`; the grid's
// squares mapped to a disc with `circular`; the axes turned to face each
// lit point with `orient`). POV-Ray's `adaptive` is its shortcut to the
// grid's average (it samples corners and subdivides where they differ);
// hexant samples the whole grid, so it is read and changes nothing.
struct AreaLight {
    Vector3Function axis1, axis2;
    int size1 = 1, size2 = 1;
};

enum class LightKind { Point, Spotlight, Cylinder };

struct ObjectRecord;

// A point a light's record gives (its position, its point_at) in the world
// at time t: carried by the light's transforms (POV-Ray's
// Transform_Light), none leaving it as written.
inline glm::dvec3 light_point(const Vector3Function& point, const Transform& transform, double t) {
    const glm::dvec3 p = point(t);
    if (transform.empty()) return p;
    return glm::dvec3(transform.matrix_at(t) * glm::dvec4(p, 1.0));
}

struct LightRecord {
    Vector3Function position;
    // looks_like { OBJECT }: what the light looks like, as POV-Ray places
    // it: at the light's position, then through the light's transforms,
    // casting no shadow (language/interpreter.cpp adds it to the scene
    // with the light).
    std::shared_ptr<const ObjectRecord> looks_like;
    // projected_through { OBJECT }: the light reaches only points whose ray
    // toward it meets the object, and only what lies before that meeting
    // shadows them (POV-Ray's TraceShadowRay); in the world once the
    // scene is read.
    std::shared_ptr<const ObjectRecord> projected_through;
    ColourFunction colour;
    // POV-Ray's fill light: no shadow, no highlights.
    bool shadowless = false;
    // media_attenuation: its light is dimmed (and coloured) by the fog on
    // its way, and by the atmosphere's media, as POV-Ray's
    // ComputeShadowMedia does (with media_interaction on).
    bool media_attenuation = false;
    // media_interaction: media scatter its light (off: it passes media by,
    // neither scattered nor dimmed by the atmosphere).
    bool media_interaction = true;
    // spotlight: a cone from `position` toward point_at; cylinder: a
    // parallel beam about the line through them. radius and falloff are
    // the cone's half angles (degrees) or the beam's radii (scene units),
    // tightness the power of the cosine or of the beam's fall; the
    // keyword sets POV-Ray's defaults for its kind (spotlight 30, 45, 0;
    // cylinder 0.75, 1, 0).
    LightKind kind = LightKind::Point;
    // parallel: its rays all run from `position` toward `point_at`, and a
    // shadow reaches back to the plane through `position` across them
    // (POV-Ray's ComputeOneWhiteLightRay). A cylinder light is parallel.
    bool parallel = false;
    Vector3Function point_at{{0.0, 0.0, 1.0}};  // POV-Ray's default
    TimeFunction radius = 30.0, falloff = 45.0, tightness = 0.0;
    // Light falls by 2 / (1 + (d / fade_distance)^fade_power) at distance d
    // when both are given (fade_power > 0, fade_distance not 0).
    TimeFunction fade_distance = 0.0, fade_power = 0.0;
    std::optional<AreaLight> area;
    bool jitter = false, circular = false, orient = false;  // (area lights')
    Transform transform;
    // The light_group whose members alone it lights (an index in the
    // scene's light_groups), or -1: a light of the whole scene.
    int light_group = -1;
    LightPhotons photons;  // its photons { }
    // When it shines: always, or the pieces of time of the clock-dependent
    // branches it was made under.
    Lifetime lifetime;

    // Where it is in the world at time t.
    glm::dvec3 world_position(double t) const { return light_point(position, transform, t); }

    bool depends_on_time() const { return !lifetime.is_always() || moves(); }
    // Whether anything of it but its lifetime changes with time.
    bool moves() const {
        return position.depends_on_time() || colour.depends_on_time() ||
               transform.depends_on_time() || point_at.depends_on_time() ||
               radius.depends_on_time() || falloff.depends_on_time() ||
               tightness.depends_on_time() || fade_distance.depends_on_time() ||
               fade_power.depends_on_time() ||
               (area && (area->axis1.depends_on_time() || area->axis2.depends_on_time()));
    }
};

}  // namespace hexant::runtime
