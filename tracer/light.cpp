#include "tracer/light.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>

#include "runtime/objects/object_factory.hpp"

namespace hexant::tracer {

namespace {

// POV-Ray's EPSILON (frame.h): below it a fade distance counts as none.
constexpr double kEpsilon = 1.0e-10;

glm::dvec3 rgb(const runtime::ColourFunction& c, double t) {
    return {c.c[0](t), c.c[1](t), c.c[2](t)};
}

// POV-Ray's subdivision of rows a..b (TraceAreaLightSubsetShadowRay): the
// two ends each half when they are neighbours (or the one row whole),
// else half to each of a..floor(middle) and ceil(middle)..b.
void subdivide(int a, int b, double weight, std::vector<double>& rows) {
    if (b - a <= 1) {
        rows[std::size_t(a)] += weight / 2.0;
        rows[std::size_t(b)] += weight / 2.0;
        return;
    }
    const double middle = (a + b) / 2.0;
    subdivide(a, int(std::floor(middle)), weight / 2.0, rows);
    subdivide(int(std::ceil(middle)), b, weight / 2.0, rows);
}

// The cumulative weights of n rows. (Beyond 2^16 rows the weights differ
// from equal ones by far less than the samples resolve: equal.)
std::vector<double> cumulative_rows(int n) {
    std::vector<double> rows(std::size_t(n), 1.0 / n);
    if (n <= (1 << 16)) {
        std::fill(rows.begin(), rows.end(), 0.0);
        subdivide(0, n - 1, 1.0, rows);
    }
    for (std::size_t i = 1; i < rows.size(); ++i) rows[i] += rows[i - 1];
    rows.back() = 1.0;
    return rows;
}

}  // namespace

ShadedLight::ShadedLight(const runtime::LightRecord& r)
    : position_(r.position),
      point_at_(r.point_at),
      colour_(r.colour),
      transform_(r.transform),
      lifetime_(r.lifetime),
      kind_(r.kind),
      shadowless_(r.shadowless),
      parallel_(r.parallel),
      radius_(r.radius),
      falloff_(r.falloff),
      tightness_(r.tightness),
      fade_distance_(r.fade_distance),
      fade_power_(r.fade_power),
      area_(r.area),
      jitter_(r.jitter),
      // (orient alone makes the grid circular: POV-Ray warns "This area
      // light is now circular"; a row of one light stays square.)
      circular_(r.area && (r.circular || r.orient) && r.area->size1 > 1 && r.area->size2 > 1),
      orient_(r.orient) {
    media_attenuation_ = r.media_attenuation;
    media_interaction_ = r.media_interaction;
    photons_ = r.photons;
    // (An object hexant cannot build throws ObjectError, naming its place.)
    if (r.projected_through) projector_ = runtime::make_intelligent_object(*r.projected_through);
    fixed_position_ = moving_position(0.0);
    still_position_ = !r.position.depends_on_time() && !r.transform.depends_on_time();
    fixed_colour_ = rgb(r.colour, 0.0);
    still_colour_ = !r.colour.depends_on_time();
    toward_centre_ = kind_ != runtime::LightKind::Cylinder && !parallel_;
    plain_ = kind_ == runtime::LightKind::Point && r.fade_power.is_constant() &&
             !(r.fade_power.constant() > 0.0);
    if (area_) {
        rows1_ = cumulative_rows(area_->size1);
        rows2_ = cumulative_rows(area_->size2);
    }
}

double ShadedLight::grid_row(double s, const std::vector<double>& cumulative) const {
    const auto at = std::upper_bound(cumulative.begin(), cumulative.end(), s);
    const std::size_t row = std::min(std::size_t(at - cumulative.begin()), cumulative.size() - 1);
    if (!jitter_) return double(row);
    // (The place within the row's share of [0, 1) is uniform: the cell's.)
    const double from = row ? cumulative[row - 1] : 0.0, width = cumulative[row] - from;
    const double place = width > 0.0 ? std::clamp((s - from) / width, 0.0, 1.0) : 0.5;
    return double(row) + place - 0.5;
}

glm::dvec3 ShadedLight::moving_position(double t) const {
    return runtime::light_point(position_, transform_, t);
}

glm::dvec3 ShadedLight::point_at(double t) const {
    return runtime::light_point(point_at_, transform_, t);
}

glm::dvec3 ShadedLight::axis_at(double t) const {
    const glm::dvec3 d = point_at(t) - position_at(t);
    const double l = glm::length(d);
    // (point_at within POV-Ray's EPSILON of the light: it leaves the
    // direction unscaled, about zero, and the light lights nothing. An
    // absolute 1e-10, POV-Ray's rule, kept so that images agree.)
    return l > kEpsilon ? d / l : glm::dvec3(0.0);
}

glm::dvec3 ShadedLight::moving_colour(double t) const {
    return rgb(colour_, t);
}

LightRay ShadedLight::shaped_ray_from(const glm::dvec3& point, double t,
                                      const glm::dvec3& offset) const {
    const glm::dvec3 centre = position_at(t) + offset;
    LightRay ray;
    if (kind_ == runtime::LightKind::Cylinder) {
        // Along the beam: from point_at toward the light, as deep as the
        // point lies below the light along it.
        const glm::dvec3 back = centre - point_at(t);
        const double length = glm::length(back);
        if (!(length > 0.0)) return ray;
        ray.direction = back / length;
        ray.depth = glm::dot(centre - point, ray.direction);
    } else {
        const glm::dvec3 to = centre - point;
        ray.depth = glm::length(to);
        if (!(ray.depth > 0.0)) return {};
        ray.direction = to / ray.depth;
    }
    if (parallel_) {
        if (area_) {
            // Each grid point shines along its own line to point_at.
            const glm::dvec3 v = centre - point_at(t);
            const double l = glm::length(v);
            if (!(l > 0.0)) return {};
            const glm::dvec3 v1 = v / l;
            ray.depth *= glm::dot(v1, ray.direction);
            ray.direction = v1;
        } else {
            const glm::dvec3 axis = axis_at(t);
            ray.depth *= -glm::dot(axis, ray.direction);
            ray.direction = -axis;
        }
    }
    return ray;
}

double ShadedLight::cubic_spline(double low, double high, double pos) {
    // POV-Ray's cubic_spline: 0 below low, 1 from high, a smooth step
    // between (its tests in this order, so low >= high is a step at low).
    if (pos < low) return 0.0;
    if (pos >= high) return 1.0;
    pos = (pos - low) / (high - low);
    return (3.0 - 2.0 * pos) * pos * pos;
}

double ShadedLight::shaped_attenuation(const glm::dvec3& point, const LightRay& ray,
                                       double t) const {
    double a = 1.0;
    switch (kind_) {
        case runtime::LightKind::Spotlight: {
            // The cosine of the angle off the axis at the light; radius and
            // falloff are half angles in degrees (POV-Ray keeps their
            // cosines).
            const double cosine = -glm::dot(ray.direction, axis_at(t));
            if (!(cosine > 0.0)) return 0.0;
            a = std::pow(cosine, tightness_(t));
            const double radius = std::cos(radius_(t) * std::numbers::pi / 180.0);
            if (radius > 0.0 && cosine < radius)
                a *= cubic_spline(std::cos(falloff_(t) * std::numbers::pi / 180.0), radius, cosine);
            break;
        }
        case runtime::LightKind::Cylinder: {
            // How far off the beam's axis, for points ahead of the light.
            const glm::dvec3 axis = axis_at(t);
            const glm::dvec3 v = point - position_at(t);
            const double k = glm::dot(v, axis);
            if (!(k > 0.0)) return 0.0;
            const double off = glm::length(v - k * axis);
            const double falloff = falloff_(t), radius = radius_(t);
            if (!(off < falloff)) return 0.0;
            const double d = 1.0 - off / falloff;
            a = std::pow(d, tightness_(t));
            if (radius > 0.0 && off > radius) a *= cubic_spline(0.0, 1.0 - radius / falloff, d);
            break;
        }
        case runtime::LightKind::Point:
            break;
    }
    if (a > 0.0) {
        const double power = fade_power_(t), distance = fade_distance_(t);
        if (power > 0.0 && std::fabs(distance) > kEpsilon)
            a *= 2.0 / (1.0 + std::pow(ray.depth / distance, power));
    }
    // (No NaN leaves: a cosine power of a NaN tightness, say, lights nothing.)
    return std::isfinite(a) ? a : 0.0;
}

double ShadedLight::beam(const glm::dvec3& origin, const glm::dvec3& direction, double t) const {
    // (A spotlight's by the direction, a cylinder's by how far off its
    // axis the photon starts, as shaped_attenuation without the fade.)
    if (kind_ == runtime::LightKind::Point) return 1.0;
    double a = 1.0;
    if (kind_ == runtime::LightKind::Spotlight) {
        const double cosine = glm::dot(direction, axis_at(t));
        if (!(cosine > 0.0)) return 0.0;
        a = std::pow(cosine, tightness_(t));
        const double radius = std::cos(radius_(t) * std::numbers::pi / 180.0);
        if (radius > 0.0 && cosine < radius)
            a *= cubic_spline(std::cos(falloff_(t) * std::numbers::pi / 180.0), radius, cosine);
    } else {
        const glm::dvec3 axis = axis_at(t);
        if (!(glm::dot(direction, axis) > 0.0)) return 0.0;
        const glm::dvec3 v = origin - position_at(t);
        const double off = glm::length(v - glm::dot(v, axis) * axis);
        const double falloff = falloff_(t), radius = radius_(t);
        if (!(off < falloff)) return 0.0;
        const double d = 1.0 - off / falloff;
        a = std::pow(d, tightness_(t));
        if (radius > 0.0 && off > radius) a *= cubic_spline(0.0, 1.0 - radius / falloff, d);
    }
    return std::isfinite(a) ? a : 0.0;
}

double ShadedLight::fade(double depth, double t) const {
    const double power = fade_power_(t), distance = fade_distance_(t);
    if (!(power > 0.0 && std::fabs(distance) > kEpsilon)) return 1.0;
    const double a = 2.0 / (1.0 + std::pow(depth / distance, power));
    return std::isfinite(a) ? a : 0.0;
}

glm::dvec3 ShadedLight::area_offset(glm::dvec2 u, const LightRay& centre, double t) const {
    const runtime::AreaLight& area = *area_;
    glm::dvec3 axis1 = area.axis1(t), axis2 = area.axis2(t);
    if (!transform_.empty()) {
        const glm::dmat3 m(transform_.matrix_at(t));
        axis1 = m * axis1;
        axis2 = m * axis2;
    }
    if (orient_) {
        // Square, facing the lit point: both axes across the ray, as long
        // as axis1.
        const double length = glm::length(axis1);
        const glm::dvec3 d = centre.direction;
        const glm::dvec3 helper =
            std::fabs(std::fabs(d.z) - 1.0) < 0.01 ? glm::dvec3(0, 1, 0) : glm::dvec3(0, 0, 1);
        const glm::dvec3 a1 = glm::cross(d, helper);
        const double l1 = glm::length(a1);
        if (l1 > 0.0) {
            axis1 = a1 / l1;
            axis2 = glm::normalize(glm::cross(d, axis1));
            axis1 *= length;
            axis2 *= length;
        }
    }
    // Row along each axis: POV-Ray's grid point (i, j), moved within its
    // cell by jitter.
    double gu = grid_row(u.x, rows1_), gv = grid_row(u.y, rows2_);
    if (circular_) {
        // The square's shells mapped to rings (sizes above 1, checked when
        // read).
        gu = gu / (area.size1 - 1) - 0.5 + 0.001;
        gv = gv / (area.size2 - 1) - 0.5 + 0.001;
        const double r = std::sqrt(gu * gu + gv * gv);
        if (!(r > 0.0)) return glm::dvec3(0.0);
        const double scale = std::max(std::fabs(gu), std::fabs(gv)) / r;
        return axis1 * (gu * scale) + axis2 * (gv * scale);
    }
    glm::dvec3 offset(0.0);
    if (area.size1 > 1) offset += axis1 * (gu / (area.size1 - 1) - 0.5);
    if (area.size2 > 1) offset += axis2 * (gv / (area.size2 - 1) - 0.5);
    return offset;
}

bool ShadedLight::media_interval(const glm::dvec3& origin, const glm::dvec3& direction, double t,
                                 double& s0, double& s1) const {
    // POV-Ray's MAX_DISTANCE: as far as a beam reaches.
    constexpr double kFar = 1.0e7;
    s0 = 0.0;
    s1 = kFar;
    if (kind_ == runtime::LightKind::Point) return true;
    const glm::dvec3 centre = position_at(t), axis = axis_at(t);
    const glm::dvec3 v1 = origin - centre;
    const double k1 = glm::dot(direction, axis), k2 = glm::dot(v1, axis);
    if (k1 <= 0.0 && k2 < 0.0) return false;
    const double k3 = glm::dot(v1, direction), k4 = glm::dot(v1, v1);
    if (kind_ == runtime::LightKind::Cylinder) {
        // (ComputeCylinderLightInterval: the beam's falloff radius.)
        const double falloff = falloff_(t);
        const double a = 1.0 - k1 * k1;
        if (a == 0.0) return false;
        const double b = k3 - k1 * k2, c = k4 - k2 * k2 - falloff * falloff;
        double d = b * b - a * c;
        if (!(d > kEpsilon)) return false;
        d = std::sqrt(d);
        double t1 = (-b + d) / a, t2 = (-b - d) / a;
        if (t1 > t2) std::swap(t1, t2);
        const double l1 = k2 + t1 * k1, l2 = k2 + t2 * k1;
        if (l1 <= 0.0 && l2 <= 0.0) return false;
        if (l1 <= 0.0)
            t1 = 0.0;
        else if (l2 <= 0.0)
            t2 = (kFar - k2) / k1;
        s0 = t1;
        s1 = t2;
        return true;
    }
    // ComputeSpotLightInterval: the cone of the falloff angle (POV-Ray
    // keeps its cosine).
    const double cos_falloff = std::cos(falloff_(t) * std::numbers::pi / 180.0);
    const double m = 1.0 / (cos_falloff * cos_falloff);
    const double l = glm::length(v1);
    const bool in_cone = l > kEpsilon && k2 / l >= cos_falloff;
    const double a = 1.0 - k1 * k1 * m, b = k3 - k1 * k2 * m, c = k4 - k2 * k2 * m;
    if (a == 0.0) {
        if (!in_cone) return false;
        s0 = 0.0;
        s1 = -c / b;
        return true;
    }
    double d = b * b - a * c;
    if (d > kEpsilon) {
        d = std::sqrt(d);
        double t1 = (-b + d) / a, t2 = (-b - d) / a;
        if (t1 > t2) std::swap(t1, t2);
        const double l1 = k2 + t1 * k1, l2 = k2 + t2 * k1;
        if (l1 <= 0.0 && l2 <= 0.0) return false;
        if (l1 <= 0.0) {
            if (in_cone) {
                t1 = 0.0;
                t2 = t2 > 0.0 ? t2 : kFar;
            } else {
                t1 = t2;
                t2 = kFar;
            }
        } else if (l2 <= 0.0) {
            if (in_cone) {
                t2 = t1;
                t1 = 0.0;
            } else {
                t2 = kFar;
            }
        }
        s0 = t1;
        s1 = t2;
        return true;
    }
    if (d > -kEpsilon) {
        if (in_cone) {
            s0 = 0.0;
            s1 = -b / a;
        } else {
            s0 = -b / a;
            s1 = kFar;
        }
        return true;
    }
    return false;
}

}  // namespace hexant::tracer
