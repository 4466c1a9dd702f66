#include "tracer/shader.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

#include <glm/geometric.hpp>

#include "runtime/geometry/offset_ray.hpp"
#include "tracer/dispersion.hpp"
#include "tracer/iridescence.hpp"
#include "tracer/reflectivity.hpp"
#include "tracer/sample_pattern.hpp"

namespace hexant::tracer {

namespace {

using runtime::Event;
using runtime::Ray4;

glm::dvec3 rgb(const runtime::ColourFunction& c, double t) {
    return {c.c[0](t), c.c[1](t), c.c[2](t)};
}

// POV-Ray stops following rays whose contribution falls below its
// adc_bailout (1/255).
constexpr double kBailout = 1.0 / 255.0;
// The part of a shadow ray's length next to the light where nothing blocks.
constexpr double kLightTolerance = 1e-9;
}  // namespace

// The relative ior a layer's reflectivity reads: only Fresnel reads it, and
// only then is the refraction list (and, for a camera ray leaving an
// unknown interior, an inside test) consulted.
double Shader::fresnel_ior(const Hit& h, const runtime::MaterialSample& m) {
    return m.reflection_fresnel ? h.relative_ior(m.ior) : 1.0;
}

namespace {

// POV-Ray's EPSILON, on a ratio of iors near 1.
constexpr double kEpsilon = 1e-10;
// The straight passes one path may make at one trace level (ThreadState::
// straight_passes): POV-Ray's weight bailout ends a run through surfaces
// that filter or transmit less than all within about 50; only wholly clear
// ones go on, and each costs a frame of the thread's stack.
constexpr int kMostStraightPasses = 128;

}  // namespace

Shader::Shader(const runtime::SceneDescription& scene, const RayQuery& query, LightTravel travel,
               bool filtering)
    : query_(query),
      travel_(travel),
      filtering_(filtering),
      background_(scene.background),
      ambient_light_(scene.global.ambient_light),
      max_trace_level_(std::max(1, scene.global.max_trace_level)),
      irid_wavelength_(scene.global.irid_wavelength),
      legacy_sky_(scene.global.legacy_sky),
      legacy_opacity_(scene.global.legacy_opacity) {
    for (const auto& l : scene.lights) {
        lights_.emplace_back(l);
        light_group_of_.push_back(l.light_group);
    }
    for (const auto& g : scene.light_groups) group_parent_.push_back(g.parent);
    still_ambient_ = !ambient_light_.depends_on_time();
    fixed_ambient_ = rgb(ambient_light_, 0.0);
    if (scene.sky_sphere) {
        // A pigment is evaluated at the direction taken through the sky's
        // transform: a texture whose transform is the sky's.
        for (auto p = scene.sky_sphere->pigments.rbegin(); p != scene.sky_sphere->pigments.rend();
             ++p) {
            runtime::Texture layer;
            layer.pigment = *p;
            layer.transform = scene.sky_sphere->transform;
            sky_layers_.emplace_back(layer, std::nullopt);
        }
        sky_emission_ = scene.sky_sphere->emission;
    }
    fogs_ = scene.fogs;
    rainbows_ = scene.rainbows;
    // (A density pattern hexant lacks throws, naming its place.)
    if (!scene.atmosphere.empty())
        atmosphere_ = std::make_shared<const runtime::MediaVolume>(scene.atmosphere);
    noise_generator_ = scene.global.noise_generator;
    radiosity_ = scene.global.radiosity;
    photons_ = scene.global.photons;
    if (radiosity_.enabled) {
        // POV-Ray's GetRecursionSettings: per bounce, half the rays (at
        // least 5), fewer records to reuse, twice the error bound and
        // reuse distances, a deeper trace level and less weight.
        ambient_lights_ = scene.global.language_version < 3.7;
        for (int d = 0; d < radiosity_.recursion_limit; ++d) {
            RadiosityLevel level;
            level.rays = std::max(5, static_cast<int>(radiosity_.count * std::pow(0.5, d)));
            level.reuse_count = d == 0   ? radiosity_.nearest_count
                                : d == 1 ? std::min(2, radiosity_.nearest_count)
                                         : 1;
            level.factor = std::pow(2.0, d);
            level.trace_level = static_cast<int>(1.5 * (d + 1.0));
            level.weight = std::max(radiosity_.adc_bailout + 1e-10,
                                    std::pow(0.5 * radiosity_.brightness, d + 1.0));
            radiosity_levels_.push_back(level);
        }
    }
}

inline void Shader::place(const ShadedLight& light, const Hit& h,
                          ShadingScratch::Light& known) const {
    known.state = ShadingScratch::Light::State::Dark;
    if (!light.shines_at(h.time)) return;
    // POV-Ray's ComputeOneLightRay: the ray toward the light's centre from
    // the hit, its colour attenuated along it (a spotlight's cone, fade);
    // the shadow ray starts off the surface and looks as far as the light
    // (a parallel light: the plane through it).
    const LightRay ray = light.ray_from(h.point, h.time);
    if (ray.direction == glm::dvec3(0.0)) return;
    const double attenuation = light.attenuation(h.point, ray, h.time);
    if (!(attenuation > 0.0)) return;
    known.state = ShadingScratch::Light::State::Placed;
    known.to_light = ray.direction;
    known.reach = light.ray_from(h.start, h.time).depth;
    known.colour = light.colour_at(h.time) * attenuation;
}

inline std::optional<runtime::ObjectHit> Shader::nearest(const Ray4& ray, Ray4& on,
                                                         ThreadState& state, std::uint8_t sight,
                                                         double s_max) const {
    state.sight = sight;
    if (ray.direction.w == 0.0) return query_.first_hit(ray, 0.0, s_max, state);
    ++state.counters.travelling_rays;
    const double s_floor = LightTravel::floor_parameter(ray, travel_.floor);
    if (auto hit = query_.first_hit(ray, 0.0, std::min(s_max, s_floor), state)) return hit;
    if (s_floor >= s_max) return std::nullopt;
    on = LightTravel::held_piece(ray, s_floor, travel_.floor);
    return query_.first_hit(on, 0.0, s_max - s_floor, state);
}

std::optional<runtime::ObjectHit> Shader::nearest_hit(const Ray4& ray, Ray4& on, ThreadState& state,
                                                      std::uint8_t sight) const {
    return nearest(ray, on, state, sight);
}

inline bool Shader::blocked(const Ray4& ray, double reach, ThreadState& state) const {
    if (ray.direction.w == 0.0) return query_.occluded(ray, 0.0, reach, state);
    ++state.counters.travelling_rays;
    const double s_floor = LightTravel::floor_parameter(ray, travel_.floor);
    if (s_floor >= reach) return query_.occluded(ray, 0.0, reach, state);
    if (query_.occluded(ray, 0.0, s_floor, state)) return true;
    const Ray4 held = LightTravel::held_piece(ray, s_floor, travel_.floor);
    return query_.occluded(held, 0.0, reach - s_floor, state);
}

inline glm::dvec3 Shader::shadow_filter(std::size_t index, const Hit& h,
                                        const ShadingScratch::Light& known, ThreadState& state,
                                        bool behind) const {
    const ShadedLight& light = lights_[index];
    glm::dvec3 direction = known.to_light;
    double reach = known.reach;
    // (A light behind a double_illuminate surface: the shadow ray leaves
    // from that side, so that the surface does not shadow itself.)
    // (So too for a light that shows through from behind: `behind`.)
    glm::dvec3 start = h.start;
    bool from_back = false;
    if ((h.double_lit || behind) && glm::dot(h.geometric, direction) < 0.0) {
        start = h.double_lit ? h.back_start
                             : runtime::geometry::offset_ray(h.point, h.p.error, -h.geometric);
        from_back = true;
    }
    // (Radiosity's gathering rays light by an area light's centre, as
    // POV-Ray's radiosity quality flags have it.)
    if (light.is_area() && state.radiosity.depth == 0) {
        // One point of the grid per sample: over a pixel's samples the
        // shadow averages the grid, as POV-Ray's fully subdivided one.
        const SampleIndex& s = state.sample;
        const auto u = sample_pair(
            s.seed, s.index, s.count,
            static_cast<std::uint32_t>(index + lights_.size() * std::size_t(h.depth)), s.jitter);
        const glm::dvec3 offset =
            light.area_offset({u[0], u[1]}, LightRay{known.to_light, 0.0}, h.time);
        const LightRay toward = light.ray_from(start, h.time, offset);
        if (toward.direction == glm::dvec3(0.0)) return glm::dvec3(1.0);
        direction = toward.direction;
        reach = toward.depth;
    }
    if (!(reach > 0.0)) return glm::dvec3(1.0);
    // (A surface through the light itself does not shadow it: POV-Ray
    // counts blockers only short of the light, by its SHADOW_TOLERANCE;
    // here by a part of the distance far above the hit's rounding, so
    // that a light set on a ceiling (cornell.pov's) lights the room.)
    reach *= 1.0 - kLightTolerance;
    const Ray4 ray = travel_.ray(start, h.time, direction);
    if (!projected(light, ray, reach)) return glm::dvec3(0.0);
    if (light.shadowless()) return glm::dvec3(1.0);
    ++state.counters.shadow_rays;
    // A flat surface cannot shadow its own point from a light on the side
    // the ray starts, nor a convex solid from a light outside it (the ray
    // starts outside: hit from outside, h.back false, and not sent from the
    // back): the walk passes it by. Only for a ray at one instant (a moving
    // surface may meet a ray that travels in time), and not within 2^-20
    // of grazing, far above the normal's rounding.
    const double away = glm::dot(from_back ? -h.geometric : h.geometric, direction);
    state.leaving = ray.direction.w == 0.0 && away > 0x1p-20 * glm::length(direction) &&
                            (h.object->flat() || (!h.back && !from_back && h.object->convex()))
                        ? h.object
                        : nullptr;
    // (Objects that may let light through do not block: `blocked` passes
    // them by, and they filter what it lets pass.)
    const bool dark = blocked(ray, reach, state);
    state.leaving = nullptr;
    if (dark) return glm::dvec3(0.0);
    if (!filtering_) return glm::dvec3(1.0);
    const bool photon_rule = photon_map_ != nullptr && h.object->flags().photon_collect;
    return filtered(ray, reach, h.depth, h.around, state,
                    photon_rule ? static_cast<std::ptrdiff_t>(index) : -1);
}

bool Shader::projected(const ShadedLight& light, const Ray4& ray, double& reach) {
    const runtime::IntelligentObject* projector = light.projector();
    if (projector == nullptr) return true;
    // POV-Ray's TraceShadowRay: dark unless the ray meets the object before
    // the light; then only what lies before the meeting shadows (the
    // object itself and its twin in the scene do not).
    const auto hit = projector->intersect(ray, 0.0, reach);
    if (!hit) return false;
    // (Short of the meeting by a part in 10^7 of its distance: POV-Ray's
    // SMALL_TOLERANCE, made relative so that it holds at any scale.)
    reach = hit->s * (1.0 - 1.0e-7);
    return true;
}

glm::dvec3 Shader::filtered(Ray4 ray, double reach, int depth, Inside around, ThreadState& state,
                            std::ptrdiff_t photon_light) const {
    // (No count in POV-Ray; this one only stops a walk that cannot end.)
    constexpr int kMostSurfaces = 1 << 16;
    const glm::dvec3 d = glm::dvec3(ray.direction) / glm::length(glm::dvec3(ray.direction));
    glm::dvec3 through(1.0);
    for (int crossed = 0; crossed < kMostSurfaces; ++crossed) {
        Ray4 on = ray;
        const auto hit = nearest(ray, on, state, runtime::kSightAll, reach);
        if (!hit) return through;
        const runtime::SurfacePoint p = hit->object->complete(on, *hit);
        // (A no_shadow object is passed by, as POV-Ray's precondition.)
        if (hit->object->casts_shadow()) {
            if (photon_light >= 0 &&
                photon_shadow(*hit->object, static_cast<std::size_t>(photon_light)))
                return glm::dvec3(0.0);
            ++state.counters.filtered_surfaces;
            through *= transmittance(p, d, depth, state);
            const double way = glm::distance(glm::dvec3(p.event), glm::dvec3(ray.origin));
            // Leaving an object whose interior fades light: by the way
            // inside (POV-Ray's ComputeShadowTexture, which wants a power
            // above 0 too).
            if (glm::dot(p.geometric_normal, d) > 0.0)
                if (const auto fade = p.texture->fade_at(p.event.w); fade && fade->power > 0.0)
                    through *= fade->through(way);
            // The media of the interiors the ray is in, on the way here
            // (ComputeShadowColour), then in or out of this one: out when
            // the list holds it, else in (ComputeShadowMedia's rule).
            if (around.has_media() && around.hollow())
                through = shadow_media(through, ray, way, around);
            const runtime::MediaVolume* media = p.texture->media();
            const Inside::Entry met{
                media ? static_cast<const void*>(media) : static_cast<const void*>(hit->object),
                media, hit->object->flags().hollow};
            if (around.contains(met.key))
                around = around.without(met.key);
            else if (media || !met.hollow)
                around = around.with(met);
            // POV-Ray's full shadow: below its EPSILON in every channel.
            if (std::max({std::fabs(through.x), std::fabs(through.y), std::fabs(through.z)}) <
                1.0e-10)
                return glm::dvec3(0.0);
        }
        // On from just past the surface, as far as is left to the light.
        glm::dvec3 n = p.geometric_normal;
        if (glm::dot(n, d) < 0.0) n = -n;
        const glm::dvec3 from = runtime::geometry::offset_ray(glm::dvec3(p.event), p.error, n);
        reach -= glm::dot(from - glm::dvec3(ray.origin), d);
        if (!(reach > 0.0)) return through;
        ray = travel_.ray(from, p.event.w, d);
        ++state.counters.shadow_rays;
    }
    return through;
}

glm::dvec3 Shader::transmittance(const runtime::SurfacePoint& p, const glm::dvec3& d, int depth,
                                 ThreadState& state) const {
    const glm::dvec3 point(p.event);
    const double t = p.event.w;
    // Faked caustics (interior's caustics): each layer lets through more
    // where the light crosses it head-on, by its own normal.
    const double caustics = p.texture->caustics_at(t);
    // (The normal faces back along the shadow ray, as POV-Ray's
    // ComputeShadowColour turns it, before the layers perturb it.)
    const glm::dvec3 facing =
        glm::dot(p.shading_normal, d) > 0.0 ? -p.shading_normal : p.shading_normal;
    const auto filter = [&](const runtime::TextureSample::Layer& layer) {
        const runtime::MaterialSample& m = layer.material;
        glm::dvec3 passed = m.colour * m.filter + glm::dvec3(m.transmit);
        if (caustics != 0.0)
            passed *= 1.0 + std::pow(std::fabs(glm::dot(layer.normal, d)), caustics);
        return passed;
    };
    if (!p.blended && p.texture->single_layer()) {
        runtime::TextureSample::Layer layer;
        p.texture->sample_layer(point, p.uv, t, facing, layer);
        return filter(layer);
    }
    // (The hit being lit holds depth's scratch; the recursion's next one
    // is free until this returns.)
    runtime::TextureSample& sample = state.shading_at(depth + 1).texture;
    sample.clear();
    if (p.blended)
        for (const auto& b : p.blend) b.texture->sample(point, p.uv, t, facing, sample, b.weight);
    else
        p.texture->sample(point, p.uv, t, facing, sample);
    glm::dvec3 sum(0.0);
    for (const runtime::TextureSample::Plain& plain : sample.plains) {
        glm::dvec3 product(1.0);
        for (std::size_t i = plain.first; i < plain.first + plain.count; ++i)
            product *= filter(sample.layers[i]);
        sum += plain.weight * product;
    }
    return sum;
}

bool Shader::matters_to_camera(const runtime::SceneDescription& scene,
                               const runtime::IntelligentObject& object, bool refracting) {
    if (refracting || object.interior_media()) return true;
    return !object.flags().hollow && (!scene.fogs.empty() || !scene.atmosphere.empty());
}

Inside Shader::inside_at(const runtime::Event& event) const {
    Inside around;
    const bool volumes = !fogs_.empty() || atmosphere_ != nullptr;
    for (const runtime::IntelligentObject* o : camera_interiors_) {
        if (!o->inside(event)) continue;
        const runtime::MediaVolume* media = o->interior_media();
        if (media || (volumes && !o->flags().hollow))
            around =
                around.with({media ? static_cast<const void*>(media) : static_cast<const void*>(o),
                             media, o->flags().hollow});
        if (const auto r = o->refractive_interior(event.w); r.key)
            around = around.entered(r.key, {r.ior, r.dispersion, r.dispersion_samples}, r.once);
    }
    return around;
}

void Shader::describe(Hit& h, const runtime::IntelligentObject& object, const Ray4& ray,
                      const Inside& inside) const {
    h.double_lit = object.flags().double_illuminate;
    h.light_group = object.flags().light_group;
    h.no_global_lights = object.flags().no_global_lights;
    h.d = glm::normalize(glm::dvec3(ray.direction));
    h.point = glm::dvec3(h.p.event);
    h.time = h.p.event.w;
    // Lighting uses the normal on the viewer's side, as POV-Ray does: each
    // normal turned to face the ray by its own sign (POV-Ray's trace.cpp
    // flips the shading normal it lights with, a smooth triangle's
    // interpolated one included, whichever way the triangle winds).
    h.raw = h.p.shading_normal;
    h.geometric = h.p.geometric_normal;
    h.back = glm::dot(h.geometric, h.d) > 0.0;
    if (h.back) h.geometric = -h.geometric;
    if (glm::dot(h.raw, h.d) > 0.0) h.raw = -h.raw;
    h.start = runtime::geometry::offset_ray(h.point, h.p.error, h.geometric);
    if (h.double_lit)
        h.back_start = runtime::geometry::offset_ray(h.point, h.p.error, -h.geometric);
    // The object as an interior: its media's volume (shared by the members
    // of the object that wrote it), or itself (on this segment only).
    // Leaving it, the ray was in it all along, even where that was not
    // known (a camera inside).
    const runtime::MediaVolume* media = h.p.texture->media();
    h.entry = {media ? static_cast<const void*>(media) : static_cast<const void*>(&object), media,
               object.flags().hollow};
    h.object = &object;
    h.interior = h.p.texture->interior_key() ? h.p.texture->interior_key()
                                             : static_cast<const void*>(&object);
    // (A ray that leaves an object it was not known to be in was inside it
    // from its start (a camera inside) when its origin is; else it came in
    // through an opening (clipped_by) and is in the open, as POV-Ray has it.)
    // (A solid without media matters only to the atmosphere, fog and the
    // media of interiors around it, which it blocks (hollow2.pov's glass
    // ball in a glowing one): its inside test is not paid on every ray
    // leaving glass otherwise.)
    const bool volumes = !fogs_.empty() || atmosphere_ != nullptr || inside.has_media();
    h.around = h.back && (media || (!h.entry.hollow && volumes)) &&
                       (inside.contains(h.entry.key) || object.inside(ray.origin))
                   ? inside.with(h.entry)
                   : inside;
}

glm::dvec3 Shader::radiance(const Ray4& ray, int depth, double weight, std::uint8_t sight,
                            const Inside& inside, ThreadState& state, double* distance) const {
    const double t = ray.origin.w;
    Ray4 on = ray;
    // (Radiosity's gathering rays see media, fog and rainbows only with
    // its `media on`, as POV-Ray's radiosity quality flags.)
    const bool volumes_seen = state.radiosity.depth == 0 || radiosity_.media;
    const auto hit = nearest(
        ray, on, state, state.radiosity.depth > 0 ? std::uint8_t(runtime::kSightRadiosity) : sight);
    // (A ray that hits nothing goes POV-Ray's BOUND_HUGE, 2e10, through
    // media and fog.)
    if (!hit) {
        const glm::dvec3 seen = sky(glm::normalize(glm::dvec3(ray.direction)), t);
        return volumes_seen ? through_volume(seen, ray, 2.0e10, inside, depth, state) : seen;
    }
    const runtime::SurfacePoint p = hit->object->complete(on, *hit);
    if (distance) *distance = glm::distance(glm::dvec3(p.event), glm::dvec3(ray.origin));
    Hit h{on, p, depth, weight};
    h.sight = sight;
    describe(h, *hit->object, ray, inside);

    // What the texture shows here: the plain textures its patterns pick,
    // their layers, each layer's normal perturbed after the turn (as
    // POV-Ray perturbs the viewer-facing normal). A texture of one plain
    // layer, the usual, is lit straight from the stack: each light is
    // asked about once anyway.
    glm::dvec3 colour(0.0);
    if (!p.blended && p.texture->single_layer()) {
        runtime::TextureSample::Layer layer;
        p.texture->sample_layer(h.point, p.uv, h.time, h.raw, layer);
        colour = lit(h, &layer, 1, nullptr, state);
    } else {
        ShadingScratch& scratch = state.shading_at(depth);
        scratch.texture.clear();
        // A blob's blend: each texture's plains at its share (POV-Ray lights
        // each weighted texture on its own and sums them).
        if (p.blended)
            for (const auto& b : p.blend)
                b.texture->sample(h.point, p.uv, h.time, h.raw, scratch.texture, b.weight);
        else
            p.texture->sample(h.point, p.uv, h.time, h.raw, scratch.texture);
        scratch.lights.assign(lights_.size(), ShadingScratch::Light{});
        for (const runtime::TextureSample::Plain& plain : scratch.texture.plains)
            colour += plain.weight * lit(h, scratch.texture.layers.data() + plain.first,
                                         plain.count, &scratch.lights, state);
    }

    if (!volumes_seen) return colour;
    return through_volume(colour, ray, glm::distance(h.point, glm::dvec3(ray.origin)), h.around,
                          depth, state);
}

glm::dvec3 Shader::media_light(std::size_t index, const glm::dvec3& point, double t, int level,
                               const Inside& around, bool collects, glm::dvec3& to_light,
                               ThreadState& state) const {
    // POV-Ray's TestShadow from the sample: the light's ray, its
    // attenuation, and its shadow ray (a shadowless light casts none).
    const ShadedLight& light = lights_[index];
    const LightRay ray = light.ray_from(point, t);
    if (ray.direction == glm::dvec3(0.0)) return glm::dvec3(0.0);
    const double attenuation = light.attenuation(point, ray, t);
    if (!(attenuation > 0.0)) return glm::dvec3(0.0);
    to_light = ray.direction;
    glm::dvec3 colour = light.colour_at(t) * attenuation;
    glm::dvec3 direction = ray.direction;
    double reach = ray.depth;
    if (light.is_area()) {
        const SampleIndex& s = state.sample;
        const auto u = sample_pair(
            s.seed, s.index, s.count,
            static_cast<std::uint32_t>(index + lights_.size() * std::size_t(level + 64)), s.jitter);
        const LightRay toward = light.ray_from(
            point, t, light.area_offset({u[0], u[1]}, LightRay{ray.direction, 0.0}, t));
        if (toward.direction != glm::dvec3(0.0)) {
            direction = toward.direction;
            reach = toward.depth;
        }
    }
    const Ray4 shadow = travel_.ray(point, t, direction);
    if (!projected(light, shadow, reach)) return glm::dvec3(0.0);
    if (!light.shadowless() && reach > 0.0) {
        ++state.counters.shadow_rays;
        if (blocked(shadow, reach, state)) return glm::dvec3(0.0);
        if (filtering_)
            colour *= filtered(
                shadow, reach, level, around, state,
                photon_map_ != nullptr && collects ? static_cast<std::ptrdiff_t>(index) : -1);
    }
    if (light.media_attenuation() && reach > 0.0) {
        if (atmosphere_) colour = shadow_media(colour, shadow, reach, *atmosphere_);
        if (!fogs_.empty()) colour = fogged(colour, shadow, reach, true);
    }
    return colour;
}

glm::dvec3 Shader::lit(const Hit& h, const runtime::TextureSample::Layer* layers, std::size_t count,
                       std::vector<ShadingScratch::Light>* seen, ThreadState& state) const {
    // POV-Ray 3.7's ComputeLightedTexture: each layer, top first, adds its
    // ambient, emission and lights, seen through the layers above it
    // (filtered by their filter and transmit), until too little shows
    // through; then what lies behind, through every layer; then each
    // layer's reflection.
    const glm::dvec3 ambient = still_ambient_ ? fixed_ambient_ : rgb(ambient_light_, h.time);
    glm::dvec3 colour(0.0);
    glm::dvec3 through(1.0);  // POV-Ray's filCol
    double trans = 1.0;
    std::size_t used = 0;
    // (POV-Ray's radiosity_needed: radiosity on, its bounces not all
    // taken; the ray's bailout is radiosity's own on a gathering path.)
    const bool radiosity_needed = (radiosity_cache_ != nullptr || radiosity_path_) &&
                                  radiosity_.enabled &&
                                  state.radiosity.depth < radiosity_.recursion_limit;
    const double radiosity_bailout = state.radiosity.depth > 0 ? radiosity_.adc_bailout : kBailout;
    bool radiosity_done = false, radiosity_back_done = false;
    glm::dvec3 radiosity_light(0.0), radiosity_back_light(0.0);
    // (Photons land on objects that collect them.)
    const bool photons = photon_map_ != nullptr && h.object->flags().photon_collect;
    PhotonGather photon_gather;
    for (; used < count && trans > kBailout; ++used) {
        const runtime::TextureSample::Layer& layer = layers[used];
        const runtime::MaterialSample& m = layer.material;
        const glm::dvec3& n = layer.normal;
        // (POV-Ray 3.7's opacity, unclamped: filter and transmit above 1
        // take light away, as there; a legacy scene's by 3.6's formula.)
        const double opaque =
            legacy_opacity_
                ? 1.0 - (m.filter * std::max({m.colour.x, m.colour.y, m.colour.z}) + m.transmit)
                : 1.0 - m.filter - m.transmit;
        glm::dvec3 own =
            m.colour * (ambient_lights_ ? m.ambient * ambient + m.emission : m.emission) * opaque;
        // Radiosity's light, gathered once for the hit (about the first
        // layer that needs it) and lit by each layer's diffuse.
        if (radiosity_needed && m.diffuse != 0.0) {
            const double diffuse = m.diffuse;
            if (!radiosity_done) {
                const glm::dvec3 most = through * m.colour;
                const double contribution =
                    (0.297 * most.x + 0.589 * most.y + 0.114 * most.z) * opaque * diffuse;
                if (contribution > radiosity_bailout) {
                    radiosity_light =
                        radiosity_path_
                            ? radiosity_path(h, n, m.brilliance, state)
                            : radiosity_ambient(h, n, m.brilliance, h.weight * contribution, state);
                    radiosity_done = true;
                }
            }
            own += m.colour * radiosity_light * (opaque * diffuse);
        }
        // diffuse's second value: radiosity's light from behind, gathered
        // about the reversed normals (POV-Ray's ambBackCol).
        if (radiosity_needed && m.diffuse_back != 0.0) {
            if (!radiosity_back_done) {
                const glm::dvec3 most = through * m.colour;
                const double contribution =
                    (0.297 * most.x + 0.589 * most.y + 0.114 * most.z) * opaque * m.diffuse_back;
                if (contribution > radiosity_bailout) {
                    Hit back = h;
                    back.raw = -h.raw;
                    back.geometric = -h.geometric;
                    back.start = runtime::geometry::offset_ray(h.point, h.p.error, -h.geometric);
                    radiosity_back_light = radiosity_path_
                                               ? radiosity_path(back, -n, m.brilliance, state)
                                               : radiosity_ambient(back, -n, m.brilliance,
                                                                   h.weight * contribution, state);
                    radiosity_back_done = true;
                }
            }
            own += m.colour * radiosity_back_light * (opaque * m.diffuse_back);
        }
        for (std::size_t i = 0; i < lights_.size(); ++i) {
            if (!lights_object(i, h)) continue;
            const ShadedLight& light = lights_[i];
            ShadingScratch::Light alone;
            ShadingScratch::Light& known = seen ? (*seen)[i] : alone;
            if (known.state == ShadingScratch::Light::State::Unknown) place(light, h, known);
            if (known.state == ShadingScratch::Light::State::Dark) continue;
            double cosine = glm::dot(n, known.to_light);
            // (double_illuminate: a light behind the surface lights it as
            // one in front, POV-Ray's fabs of the cosine. diffuse's second
            // value: it shows through the surface, diffusely, without
            // highlights (POV-Ray's backside).)
            if (h.double_lit) cosine = std::fabs(cosine);
            bool backside = false;
            if (cosine <= 0.0) {
                if (h.double_lit || m.diffuse_back == 0.0) continue;
                backside = true;
                cosine = -cosine;
                if (!(cosine > 0.0)) continue;
            }
            if (known.state == ShadingScratch::Light::State::Placed) {
                known.state = ShadingScratch::Light::State::Seen;
                if (!light.shadowless() || light.projector()) {
                    const glm::dvec3 passed = shadow_filter(i, h, known, state, backside);
                    if (passed == glm::dvec3(0.0))
                        known.state = ShadingScratch::Light::State::Shadowed;
                    else if (passed != glm::dvec3(1.0))
                        known.colour *= passed;
                }
                // media_attenuation: the atmosphere's media and the fog
                // between here and the light dim it (ComputeShadowMedia).
                if (light.media_attenuation() &&
                    known.state != ShadingScratch::Light::State::Shadowed && known.reach > 0.0) {
                    const Ray4 toward = travel_.ray(h.start, h.time, known.to_light);
                    if (atmosphere_ && light.media_interaction())
                        known.colour =
                            shadow_media(known.colour, toward, known.reach, *atmosphere_);
                    if (!fogs_.empty())
                        known.colour = fogged(known.colour, toward, known.reach, true);
                }
            }
            if (known.state == ShadingScratch::Light::State::Shadowed) continue;
            // (POV-Ray's default brilliance 1 needs no pow.)
            const double shade = m.brilliance == 1.0 ? cosine : std::pow(cosine, m.brilliance);
            const double diffuse = backside ? m.diffuse_back : m.diffuse;
            double intensity = diffuse * shade * opaque;
            // crand: less a uniform random fraction, a draw of its own per
            // sample and light (POV-Ray's ComputeDiffuseColour, after the
            // layer's opacity; only where there is diffuse light).
            if (m.crand > 0.0 && diffuse > 0.0) {
                const SampleIndex& s = state.sample;
                const auto u = sample_pair(
                    s.seed, s.index, s.count,
                    0x80000000u |
                        static_cast<std::uint32_t>(i + lights_.size() * std::size_t(h.depth)),
                    s.jitter);
                intensity -= u[0] * m.crand;
            }
            glm::dvec3 lit = intensity * m.colour;
            // POV-Ray's shadowless lights are fill lights: no highlights.
            // A metallic finish tints them by the pigment.
            // (No highlights on radiosity's gathering rays: POV-Ray leaves
            // them out there, against splotches.)
            if (!light.shadowless() && state.radiosity.depth == 0 && !backside)
                lit += highlights(m, h.d, n, known.to_light, cosine);
            if (m.irid > 0.0)
                lit *= iridescence(m, known.to_light, h.d, n, h.point, irid_wavelength_,
                                   noise_generator_);
            own += lit * known.colour;
        }
        if (photons) {
            own += photon_light(h, m, n, opaque, photon_gather, state);
            // (The photon map's noise where the camera sees it.)
            if (h.depth == 1 && state.radiosity.depth == 0) {
                const glm::dvec3 v = photon_gather.variance * through * through;
                state.photon_variance += (v.x + v.y + v.z) / 3.0;
            }
        }
        colour += own * through;
        through *= m.filter * m.colour + glm::dvec3(m.transmit);
        // conserve_energy: less passes through by what the layer reflects.
        if (m.conserve_energy && reflects(m))
            through *= glm::min(
                glm::dvec3(1.0),
                glm::dvec3(1.0) - reflectivity(m, -glm::dot(h.d, n), fresnel_ior(h, m)).colour);
        trans = std::min(1.0, std::fabs(0.297 * through.x + 0.589 * through.y + 0.114 * through.z));
    }
    if (h.depth - state.straight_passes >= max_trace_level_) return colour;

    // What lies behind, through every layer, refracted by the top one's
    // ior (POV-Ray: when enough shows through and the ray's weight is
    // above the bailout; total internal reflection is not filtered).
    const runtime::MaterialSample& top = layers[0].material;
    bool total_internal_reflection = false;
    // (POV-Ray's w1: the largest magnitude; a negative transmit gives a
    // negative share, as there.)
    const double through_weight =
        h.weight * std::max({std::fabs(through.x), std::fabs(through.y), std::fabs(through.z)});
    if (trans > kBailout && through_weight >= kBailout) {
        // POV-Ray's ComputeRefraction and TraceRefractionRay, about the top
        // layer's normal: the ratio of iors as the interiors the ray passed
        // say (not the side of the surface it meets: a ray that came in
        // through an open side enters where it meets a back face), the
        // normal taken to the ray's side. A camera ray starts in the
        // interiors that hold the eye (POV-Ray's InitRayContainerState): one
        // it leaves that it was not known to be in held it from the start.
        const glm::dvec3& normal = layers[0].normal;
        Inside passed;
        const auto dispersion = h.p.texture->dispersion_at(h.time);
        const Inside::Ratio ratio =
            h.around.refract(h.interior, {top.ior, dispersion.value, dispersion.samples},
                             h.started_inside(), passed);
        const bool disperses = std::fabs(ratio.dispersion - 1.0) >= kEpsilon;
        // (The same ior on both sides: the ray goes on straight, at the
        // same trace level, as POV-Ray continues it, up to
        // kMostStraightPasses on one path: past that, as a new level, so
        // that clear surfaces in a row cannot take the stack.)
        const bool straight = std::fabs(ratio.ior - 1.0) < kEpsilon && !disperses;
        const bool continued = straight && state.straight_passes < kMostStraightPasses;
        // Light that crossed the object's inside to get here fades with
        // the distance it went (fade_distance; POV-Ray's attCol), when the
        // ray was in it (its list holds it).
        glm::dvec3 faded(1.0);
        if (h.around.holds(h.interior) || h.started_inside())
            if (const auto fade = h.p.texture->fade_at(h.time))
                faded = fade->through(glm::distance(h.point, glm::dvec3(h.ray.origin)));
        // What comes through along ratio `eta`: a refracted ray, or one
        // reflected inside (not filtered by the layers).
        const auto behind = [&](double eta, bool& reflected) {
            glm::dvec3 out;
            reflected = !refraction(h.d, normal, eta, straight, out);
            if (reflected) out = reflect(h.d, normal, h.raw);
            const glm::dvec3 from =
                !reflected ? runtime::geometry::offset_ray(h.point, h.p.error, -h.geometric)
                           : h.start;
            ++state.counters.refracted_rays;
            const Ray4 next = travel_.ray(from, h.time, out);
            // (POV-Ray's SetFlags: a ray refracted keeps its kind; reflected
            // back inside, it is a reflection ray.)
            state.straight_passes += continued;
            const glm::dvec3 light =
                radiance(next, h.depth + 1, through_weight,
                         reflected ? std::uint8_t(runtime::kSightReflection) : h.sight,
                         reflected ? h.carried() : h.refracted(passed), state);
            state.straight_passes -= continued;
            return reflected ? faded * light : faded * light * through;
        };
        if (!disperses || state.band.monochromatic()) {
            // (A ray that took a band bends by that band's ior.)
            colour += behind(disperses ? state.band.ior(ratio.ior, ratio.dispersion) : ratio.ior,
                             total_internal_reflection);
        } else {
            colour += dispersed(ratio, behind, state);
        }
    }
    // Each layer's reflection (after total internal reflection, not along
    // the top layer's normal, which that already followed).
    for (std::size_t i = 0; i < used; ++i) {
        const runtime::TextureSample::Layer& layer = layers[i];
        const runtime::MaterialSample& m = layer.material;
        if (!reflects(m)) continue;
        if (total_internal_reflection && layer.normal == layers[0].normal) continue;
        const Reflectivity r = reflectivity(m, -glm::dot(h.d, layer.normal), fresnel_ior(h, m));
        if (r.colour == glm::dvec3(0.0)) continue;
        // (The weight of the layer: what shows through the ones above it;
        // POV-Ray's, untinted by metallic.)
        const double reflect_weight = h.weight * layer_trans(layers, i) * r.weight;
        if (reflect_weight < kBailout) continue;
        ++state.counters.reflected_rays;
        const glm::dvec3 out = reflect(h.d, layer.normal, h.raw);
        const Ray4 reflected = travel_.ray(h.start, h.time, out);
        glm::dvec3 from_there = radiance(reflected, h.depth + 1, reflect_weight,
                                         runtime::kSightReflection, h.carried(), state);
        if (m.irid > 0.0)
            from_there *=
                iridescence(m, out, h.d, layer.normal, h.point, irid_wavelength_, noise_generator_);
        colour += r.colour * raised(from_there, m.reflection_power);
    }
    return colour;
}

double Shader::layer_trans(const runtime::TextureSample::Layer* layers, std::size_t index) {
    glm::dvec3 through(1.0);
    double trans = 1.0;
    for (std::size_t i = 0; i < index; ++i) {
        const runtime::MaterialSample& m = layers[i].material;
        through *= m.filter * m.colour + glm::dvec3(m.transmit);
        trans = std::min(1.0, std::fabs(0.297 * through.x + 0.589 * through.y + 0.114 * through.z));
    }
    return trans;
}

glm::dvec3 Shader::reflect(const glm::dvec3& d, const glm::dvec3& normal, const glm::dvec3& raw) {
    glm::dvec3 r = d - 2.0 * glm::dot(d, normal) * normal;
    // POV-Ray's ComputeReflection: a perturbed normal may send the ray
    // under the surface; then it is reflected about the raw normal instead
    // (when it went in along the perturbed one too), or reflected about it
    // once more.
    if (normal != raw) {
        const double n = glm::dot(r, raw);
        if (n < 0.0) {
            if (glm::dot(r, normal) < 0.0)
                r = d - 2.0 * glm::dot(d, raw) * raw;
            else
                r += -2.0 * n * raw;
        }
        r = glm::normalize(r);
    }
    return r;
}

}  // namespace hexant::tracer
