// Radiosity at a surface, as POV-Ray 3.7 computes it (core/lighting/
// radiosity.cpp: RadiosityFunction::ComputeAmbient and GatherLight, and
// SceneRadiositySettings::GetRecursionSettings for what changes with each
// bounce): the light arriving at a point from every direction above it,
// cosine-weighted, reused from the frame's irradiance cache where records
// lie near enough (tracer/radiosity_cache.hpp) and gathered with rays
// where they do not.
//
// Gathering directions: POV-Ray draws them from a fixed table of 1,600
// cosine-weighted directions, continuing the table from sample to sample;
// hexant maps an Owen-scrambled Sobol' (0, 2)-sequence of the sample's own
// (its seed a hash of the point and the bounce) to the hemisphere by
// Malley's method, so that a sample is the same whatever the threads and
// whichever sample came before.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <numbers>

#include <glm/geometric.hpp>

#include "runtime/geometry/offset_ray.hpp"
#include "tracer/sample_pattern.hpp"
#include "tracer/shader.hpp"

namespace hexant::tracer {

namespace {

// POV-Ray's WEIGHT_ERROR_BOUND_OFFSET: a ray that matters less than this
// reuses with a wider bound.
constexpr double kWeightErrorBoundOffset = 0.25;
// The pair key of gathering directions (sample_pair): none of the lights'.
constexpr std::uint32_t kGatherPair = 0x40000000u;

std::uint32_t point_seed(const glm::dvec3& p, int depth) {
    using sobol_detail::hash;
    std::uint32_t h = hash(static_cast<std::uint32_t>(depth) + 0x51ed270bu);
    for (int k = 0; k < 3; ++k) {
        std::uint64_t bits;
        std::memcpy(&bits, &p[k], sizeof bits);
        h = hash(h ^ static_cast<std::uint32_t>(bits) ^
                 hash(static_cast<std::uint32_t>(bits >> 32)));
    }
    return h;
}

// Malley's method: a point u of the unit square, uniform on the disc, lifted
// to the hemisphere about `axis` (u_axis, v_axis across it): cosine-
// weighted; `tweak` (radiosity's brilliance on) narrows it as POV-Ray's
// SampleDirectionGenerator does.
glm::dvec3 hemisphere(const std::array<double, 2>& u, const glm::dvec3& axis,
                      const glm::dvec3& u_axis, const glm::dvec3& v_axis, double tweak) {
    double up2 = 1.0 - u[0];
    if (tweak != 1.0) up2 = std::pow(up2, 2.0 / (1.0 + tweak));
    const double r = std::sqrt(std::max(0.0, 1.0 - up2));
    const double phi = 2.0 * std::numbers::pi * u[1];
    return r * std::cos(phi) * u_axis + std::sqrt(up2) * axis + r * std::sin(phi) * v_axis;
}

// Two unit vectors across `axis` (POV-Ray's frame: off the z axis unless
// near it).
void across(const glm::dvec3& axis, glm::dvec3& u_axis, glm::dvec3& v_axis) {
    const glm::dvec3 off = std::fabs(axis.z) > 0.9 ? glm::dvec3(0, 1, 0) : glm::dvec3(0, 0, 1);
    u_axis = glm::normalize(glm::cross(axis, off));
    v_axis = glm::cross(u_axis, axis);
}

// The gathered light as ComputeAmbient returns it: grey by gray_threshold,
// times brightness.
glm::dvec3 finished(glm::dvec3 ambient, const runtime::RadiositySettings& settings) {
    if (settings.gray_threshold > 0.0) {
        const double grey = 0.297 * ambient.x + 0.589 * ambient.y + 0.114 * ambient.z;
        ambient = ambient * (1.0 - settings.gray_threshold) + settings.gray_threshold * grey;
    }
    return ambient * settings.brightness;
}

glm::dvec3 limited(glm::dvec3 seen, double max_sample) {
    const double brightest = std::max({seen.x, seen.y, seen.z});
    if (max_sample > 0.0 && brightest > max_sample) seen *= max_sample / brightest;
    return seen;
}

}  // namespace

glm::dvec3 Shader::radiosity_path(const Hit& h, const glm::dvec3& layer_normal, double brilliance,
                                  ThreadState& state) const {
    const int depth = state.radiosity.depth;
    const RadiosityLevel& level = radiosity_levels_[std::size_t(depth)];
    const SampleIndex& s = state.sample;
    const auto u = sample_pair(s.seed, s.index, s.count,
                               kGatherPair + static_cast<std::uint32_t>(depth), s.jitter);
    const double tweak = radiosity_.brilliance ? brilliance : 1.0;
    glm::dvec3 axis = radiosity_.normal ? layer_normal : h.raw;
    glm::dvec3 u_axis, v_axis;
    across(axis, u_axis, v_axis);
    glm::dvec3 direction = hemisphere(u, axis, u_axis, v_axis, tweak);
    // (Below the raw surface: the same point about the raw normal.)
    if (glm::dot(direction, h.raw) <= 0.0) {
        axis = h.raw;
        across(axis, u_axis, v_axis);
        direction = hemisphere(u, axis, u_axis, v_axis, tweak);
    }
    ++state.counters.radiosity_rays;
    ++state.radiosity.depth;
    const glm::dvec3 seen = radiance(travel_.ray(h.start, h.time, direction), level.trace_level + 1,
                                     level.weight, runtime::kSightRadiosity, h.carried(), state);
    --state.radiosity.depth;
    return finished(limited(seen, radiosity_.max_sample), radiosity_);
}

std::vector<double> Shader::radiosity_reach() const {
    std::vector<double> reach;
    const double pretrace = std::max(1.0, radiosity_.low_error_factor);
    for (const RadiosityLevel& level : radiosity_levels_)
        reach.push_back((radiosity_.error_bound * pretrace + kWeightErrorBoundOffset) *
                        level.factor);
    return reach;
}

glm::dvec3 Shader::radiosity_ambient(const Hit& h, const glm::dvec3& layer_normal,
                                     double brilliance, double weight, ThreadState& state) const {
    const int depth = state.radiosity.depth;
    const RadiosityLevel& level = radiosity_levels_[std::size_t(depth)];
    const bool pretrace = state.radiosity.pretrace;
    double bound = radiosity_.error_bound * (pretrace ? radiosity_.low_error_factor : 1.0);
    if (weight < kWeightErrorBoundOffset) bound += kWeightErrorBoundOffset - weight;
    const glm::dvec3 normal = radiosity_.normal ? layer_normal : h.raw;
    const RadiosityQuery query{
        h.point, normal,   radiosity_.brilliance ? brilliance : 1.0, bound * level.factor,
        depth,   !pretrace};
    RadiosityReuse reuse;
    if (radiosity_cache_) radiosity_cache_->gather(query, reuse);
    if (state.radiosity.kept)
        for (const RadiosityRecord& r : *state.radiosity.kept) reuse.add(r, query);
    glm::dvec3 ambient = reuse.weight > 0.0 ? reuse.weighted / reuse.weight : glm::dvec3(0.0);
    // (The final trace takes any reuse unless always_sample: more samples
    // there would be made tile by tile.)
    if (reuse.weight * 4.0 >= level.reuse_count ||
        (!pretrace && !radiosity_.always_sample && reuse.weight > 0.0)) {
        ++state.counters.radiosity_reuses;
    } else {
        glm::dvec3 gathered(0.0);
        const double quality = gather(h, layer_normal, brilliance, gathered, state);
        ambient = reuse.weight > 0.0
                      ? (ambient * reuse.weight + gathered * quality) / (reuse.weight + quality)
                      : gathered;
    }
    return finished(ambient, radiosity_);
}

double Shader::gather(const Hit& h, const glm::dvec3& layer_normal, double brilliance,
                      glm::dvec3& illuminance, ThreadState& state) const {
    const int depth = state.radiosity.depth;
    const RadiosityLevel& level = radiosity_levels_[std::size_t(depth)];
    const double to_eye = glm::distance(radiosity_eye_, h.point);
    const double reuse_least = to_eye * radiosity_.minimum_reuse * level.factor;
    const double reuse_most = to_eye * radiosity_.maximum_reuse * level.factor;
    const int rays = std::min(level.rays, radiosity_.direction_pool);
    ++state.counters.radiosity_samples;

    // Directions about the layer's normal, none below the raw one (then,
    // out of good ones, about the raw normal).
    bool raw_mode = glm::distance(h.raw, layer_normal) < 1e-9 || !radiosity_.normal;
    glm::dvec3 axis = raw_mode ? h.raw : layer_normal;
    const std::uint32_t seed = point_seed(h.point, depth);
    const double tweak = radiosity_.brilliance ? brilliance : 1.0;
    std::uint32_t drawn = 0;
    std::uint32_t tries = raw_mode ? std::uint32_t(radiosity_.direction_pool)
                                   : std::uint32_t(std::min(rays * 5, radiosity_.direction_pool));
    glm::dvec3 u_axis, v_axis;
    const auto frame = [&] { across(axis, u_axis, v_axis); };
    frame();
    const auto next_direction = [&](glm::dvec3& out) {
        while (tries > 0) {
            --tries;
            const auto u = sample_pair(seed, drawn, static_cast<std::uint32_t>(rays),
                                       kGatherPair + static_cast<std::uint32_t>(depth), true);
            ++drawn;
            out = hemisphere(u, axis, u_axis, v_axis, tweak);
            if (raw_mode || glm::dot(out, h.raw) > 0.0) return true;
        }
        return false;
    };

    glm::dvec3 sums(0.0);
    double inverse_sum = 0.0, smallest = std::numeric_limits<double>::infinity();
    glm::dvec3 nearest_direction = axis;
    int made = 0, made_raw = 0;
    double quality_sum = 0.0;
    ++state.radiosity.depth;
    std::vector<RadiosityRecord> own;
    std::vector<RadiosityRecord>* const kept = state.radiosity.kept;
    // (A final-trace gather keeps its deeper records for its own rays.)
    if (!kept) state.radiosity.kept = &own;
    for (int i = 0; i < rays; ++i) {
        glm::dvec3 direction;
        bool ok = next_direction(direction);
        if (!ok && !raw_mode) {
            raw_mode = true;
            axis = h.raw;
            frame();
            tries = std::uint32_t(radiosity_.direction_pool);
            ok = next_direction(direction);
        }
        if (!ok) break;
        ++made;
        made_raw += raw_mode;
        ++state.counters.radiosity_rays;
        double distance = std::numeric_limits<double>::infinity();
        glm::dvec3 seen =
            radiance(travel_.ray(h.start, h.time, direction), level.trace_level + 1, level.weight,
                     runtime::kSightRadiosity, h.carried(), state, &distance);
        sums += limited(seen, radiosity_.max_sample);
        quality_sum += 1.0;
        if (distance < smallest) {
            smallest = distance;
            nearest_direction = direction;
        }
        inverse_sum += 1.0 / distance;
    }
    --state.radiosity.depth;
    state.radiosity.kept = kept;
    illuminance = quality_sum > 0.0 ? sums / quality_sum : sums;
    if (made == 0) return 0.0;
    const double quality = quality_sum / made;
    // The record's reach: the harmonic mean distance of what its rays met,
    // kept within the reuse limits; none when two surfaces almost touch
    // here (its rays are not to be trusted).
    double mean = inverse_sum > 0.0 ? made / inverse_sum : std::numeric_limits<double>::infinity();
    const bool keep = kept != nullptr || depth > 0;
    if (smallest > reuse_most * 0.0001 && keep && state.radiosity.kept) {
        mean = std::clamp(mean, reuse_least, reuse_most);
        RadiosityRecord record;
        record.point = h.point;
        record.normal = made_raw * 2 > made ? h.raw : layer_normal;
        record.to_nearest = nearest_direction;
        record.illuminance = illuminance;
        record.harmonic_mean = mean;
        record.nearest = smallest;
        record.quality = quality;
        record.brilliance = radiosity_.brilliance ? brilliance : 1.0;
        record.depth = depth;
        state.radiosity.kept->push_back(record);
    }
    return quality;
}

}  // namespace hexant::tracer
