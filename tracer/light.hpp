// A light as the shader reads it: POV-Ray 3.7's light_source at one time.
// Where it is and its colour (a still light's evaluated once), the ray from
// a lit point toward it (ComputeOneWhiteLightRay: point, spotlight and area
// lights aim at their centre, parallel and cylinder lights run along their
// axis), how much of it reaches the point (Attenuate_Light: the spotlight's
// cone, the cylinder's beam, fade_distance and fade_power), and for an area
// light the point of its grid a shadow ray aims at (TraceAreaLightShadowRay:
// the grid, jitter, circular, orient). Sources: POV-Ray 3.7's
// source/backend/lighting/point.cpp and render/trace.cpp.
#pragma once

#include <cmath>
#include <memory>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "runtime/objects/intelligent_object.hpp"
#include "runtime/scene/light.hpp"

namespace hexant::tracer {

// From a point toward a light: the unit direction the light comes from and
// POV-Ray's light source depth (the distance to it; to the plane through
// it across a parallel light's axis).
struct LightRay {
    glm::dvec3 direction{0.0};
    double depth = 0.0;
};

class ShadedLight {
  public:
    explicit ShadedLight(const runtime::LightRecord& record);

    bool shines_at(double t) const { return lifetime_.is_always() || lifetime_.contains(t); }
    bool shadowless() const { return shadowless_; }
    // projected_through's object (runtime::LightRecord), null without.
    const runtime::IntelligentObject* projector() const { return projector_.get(); }
    // media_attenuation (runtime::LightRecord): fogged on its way.
    bool media_attenuation() const { return media_attenuation_; }
    // media_interaction (runtime::LightRecord): media scatter it.
    bool media_interaction() const { return media_interaction_; }
    // The stretch [s0, s1] of the ray origin + s direction (unit) that the
    // light can reach, for sampling media (POV-Ray's
    // ComputeOneMediaLightInterval): all of it for point lights; the part
    // inside a spotlight's cone or a cylinder's beam. False when none.
    bool media_interval(const glm::dvec3& origin, const glm::dvec3& direction, double t, double& s0,
                        double& s1) const;
    bool is_area() const { return area_.has_value(); }
    // For photon shooting (tracer/photon_shooting.hpp): the light's
    // photons { }, whether its rays run parallel along its axis (the unit
    // axis from the light toward point_at), POV-Ray's computeAttenuation
    // of a photon leaving `origin` along unit `direction` (a spotlight's
    // cone, a cylinder's beam; 1 for others) and the fade over `depth`
    // (2 / (1 + (depth / fade_distance)^fade_power), or 1).
    const runtime::LightPhotons& photons() const { return photons_; }
    bool parallel() const { return parallel_; }
    glm::dvec3 axis(double t) const { return axis_at(t); }
    double beam(const glm::dvec3& origin, const glm::dvec3& direction, double t) const;
    double fade(double depth, double t) const;
    // (The common light's answers inline: a scene of point lights pays
    // nothing for the other kinds.)
    glm::dvec3 position_at(double t) const {
        return still_position_ ? fixed_position_ : moving_position(t);
    }
    glm::dvec3 colour_at(double t) const {
        return still_colour_ ? fixed_colour_ : moving_colour(t);
    }

    // The ray from `point` toward the light's centre moved by `offset` (an
    // area light's grid point; zero otherwise). A zero direction when the
    // point is the light's place, or a parallel light's point_at is.
    LightRay ray_from(const glm::dvec3& point, double t,
                      const glm::dvec3& offset = glm::dvec3(0.0)) const {
        if (!toward_centre_) return shaped_ray_from(point, t, offset);
        const glm::dvec3 to = position_at(t) + offset - point;
        const double depth = std::sqrt(to.x * to.x + to.y * to.y + to.z * to.z);
        if (!(depth > 0.0)) return {};
        return {to / depth, depth};
    }
    // What reaches `point` of the light's colour along `ray` (its centre's
    // ray from the point): 1 for a plain light, 0 outside a spotlight's
    // cone or a cylinder's beam (POV-Ray's Attenuate_Light).
    double attenuation(const glm::dvec3& point, const LightRay& ray, double t) const {
        return plain_ ? 1.0 : shaped_attenuation(point, ray, t);
    }
    // An area light's grid point for the sample `u` in [0, 1)^2 (each
    // coordinate picks a row of the grid and, with jitter, a place in its
    // cell), as an offset from the light's centre; `centre` is the centre's
    // ray from the lit point (orient turns the axes to face it).
    glm::dvec3 area_offset(glm::dvec2 u, const LightRay& centre, double t) const;

  private:
    glm::dvec3 moving_position(double t) const;
    glm::dvec3 moving_colour(double t) const;
    LightRay shaped_ray_from(const glm::dvec3& point, double t, const glm::dvec3& offset) const;
    double shaped_attenuation(const glm::dvec3& point, const LightRay& ray, double t) const;
    glm::dvec3 point_at(double t) const;
    // The unit axis from the light toward point_at (POV-Ray's Direction;
    // zero when point_at is the light's own place).
    glm::dvec3 axis_at(double t) const;
    static double cubic_spline(double low, double high, double pos);
    // Where sample s in [0, 1) falls on an axis of the grid: the row (by
    // the axis' cumulative weights) plus, with jitter, a place in its cell.
    double grid_row(double s, const std::vector<double>& cumulative) const;

    runtime::Vector3Function position_, point_at_;
    runtime::ColourFunction colour_;
    runtime::Transform transform_;
    runtime::Lifetime lifetime_;
    runtime::LightKind kind_;
    bool shadowless_, parallel_;
    bool media_attenuation_ = false, media_interaction_ = true;
    std::shared_ptr<const runtime::IntelligentObject> projector_;
    bool still_position_ = false, still_colour_ = false;
    glm::dvec3 fixed_position_{0.0}, fixed_colour_{0.0};
    runtime::TimeFunction radius_, falloff_, tightness_, fade_distance_, fade_power_;
    std::optional<runtime::AreaLight> area_;
    bool jitter_, circular_, orient_;
    runtime::LightPhotons photons_;
    // Per axis of the grid, the cumulative weights of its rows: POV-Ray's
    // TraceAreaLightSubsetShadowRay, subdividing the grid fully, averages
    // each quarter's corners, so a row shared by two quarters counts
    // twice (odd sizes weigh the rows as the trapezoid rule; even sizes
    // alike). hexant draws rows by these weights: its mean is POV-Ray's
    // fully subdivided shadow.
    std::vector<double> rows1_, rows2_;
    // A point light that never fades: attenuation 1 without asking (the
    // common light pays nothing for the others).
    bool plain_ = false;
    // Rays run straight to the centre (not parallel, not a cylinder).
    bool toward_centre_ = false;
};

}  // namespace hexant::tracer
