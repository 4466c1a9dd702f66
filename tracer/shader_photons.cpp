// Photons (POV-Ray 3.7's PhotonTrace, source/core/lighting/photons.cpp, and
// Trace::ComputePhotonDiffuseLight, render/trace.cpp): a photon's path from
// its light through the targets that reflect or refract it, leaving a
// photon on each surface it lands on after the first; and the light of a
// frame's photons at a surface being shaded.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <numbers>

#include <glm/geometric.hpp>

#include "runtime/geometry/offset_ray.hpp"
#include "tracer/iridescence.hpp"
#include "tracer/media.hpp"
#include "tracer/reflectivity.hpp"
#include "tracer/shader.hpp"

namespace hexant::tracer {

using runtime::Ray4;

namespace {

constexpr double kBailout = 1.0 / 255.0;  // POV-Ray's default adc_bailout
constexpr double kEpsilon = 1.0e-10;

// A photon's ray: photons travel instantly, also under --light-speed
// (whose rays run back in time from the eye; a photon runs forward).
Ray4 instant_ray(const glm::dvec3& origin, double t, const glm::dvec3& direction) {
    return {runtime::Event(origin, t), runtime::Event(direction, 0.0)};
}

// A photon follows refraction (reflection) where the object or its light
// says on and the other does not say off (POV-Ray's doRefraction rule).
bool photon_on(std::int8_t object, std::int8_t light) {
    return (object == 1 && light != -1) || (object != -1 && light == 1);
}

}  // namespace

bool Shader::shoot_photon(const PhotonShot& shot, const Ray4& ray, const glm::dvec3& colour,
                          std::vector<Photon>& out, std::vector<Photon>& media_out,
                          ThreadState& state) const {
    PhotonPath path{&shot, &out, &media_out};
    const Inside inside = camera_interiors_.empty() ? Inside{} : inside_at(ray.origin);
    state.straight_passes = 0;
    state.band = {};
    trace_photon(ray, colour, 1.0, inside, path, state);
    return path.hit_target;
}

void Shader::trace_photon(const Ray4& ray, const glm::dvec3& colour, double weight,
                          const Inside& inside, PhotonPath& path, ThreadState& state) const {
    const int most = photons_.max_trace_level >= 0 ? photons_.max_trace_level : max_trace_level_;
    const double bailout = photons_.adc_bailout >= 0.0 ? photons_.adc_bailout : kBailout;
    if (path.level >= most || weight < bailout) return;
    ++state.counters.photon_rays;
    Ray4 on = ray;
    const auto hit = nearest_hit(ray, on, state, runtime::kSightPhoton);
    if (!hit) return;
    ++path.level;
    const runtime::ObjectFlags& f = hit->object->flags();
    // POV-Ray's passThruPrev / passThruThis: whether the surface before
    // this one let the photon through unchanged (pass_through), and this one.
    const bool old_prev = path.pass_prev;
    path.pass_prev = path.pass_this;
    const auto restore = [&] {
        path.pass_this = path.pass_prev;
        path.pass_prev = old_prev;
        --path.level;
    };
    // Until it meets its target, a photon goes on only through
    // pass_through objects; any other object ends it.
    if (path.level == 1 || path.pass_prev) {
        path.pass_this = false;
        if (f.photon_target > 0.0f && f.photon_group == path.shot->target) {
            path.hit_target = true;
        } else if (f.photon_pass_through) {
            path.pass_this = true;
        } else {
            restore();
            return;
        }
    }
    const runtime::SurfacePoint p = hit->object->complete(on, *hit);
    Hit h{on, p, path.level, weight};
    h.sight = runtime::kSightPhoton;
    describe(h, *hit->object, ray, inside);
    const double way = glm::distance(h.point, glm::dvec3(ray.origin));
    glm::dvec3 light = colour;
    // Through media on its way (POV-Ray: inside hollow interiors only).
    if (inside.has_media() && inside.hollow()) light = photon_media(ray, way, inside, light, path);
    // Light that crossed the object's inside fades (POV-Ray's attCol).
    if (h.around.holds(h.interior))
        if (const auto fade = p.texture->fade_at(h.time)) light *= fade->through(way);
    path.depth += way;
    const auto leave = [&] {
        path.depth -= way;
        restore();
    };

    // Kept where it lands after its first surface (addSurfacePhoton): the
    // light over the area a photon stands for, its fade taken back (POV-Ray
    // fades the estimate's light as any light's on the way to the eye).
    const ShadedLight& source = lights_[path.shot->light];
    if (path.level > 1 && !path.pass_prev && f.photon_collect) {
        double area = path.shot->spread * path.shot->spread;
        if (!source.parallel()) area *= path.depth * path.depth;
        const glm::dvec3 kept = light * (source.fade(path.depth, h.time) * area);
        if (std::isfinite(kept.x + kept.y + kept.z)) {
            Photon photon;
            photon.position = glm::vec3(h.point);
            photon.colour = glm::vec3(kept);
            photon.from = glm::vec3(-h.d);
            photon.time = static_cast<float>(h.time);
            path.out->push_back(photon);
        }
    }

    Inside passed;
    const auto dispersion = p.texture->dispersion_at(h.time);
    const Inside::Ratio ratio = h.around.refract(
        h.interior, {p.texture->ior_at(h.time), dispersion.value, dispersion.samples},
        h.started_inside(), passed);
    const bool disperses = std::fabs(ratio.dispersion - 1.0) >= kEpsilon;
    const glm::dvec3 through_start = runtime::geometry::offset_ray(h.point, p.error, -h.geometric);
    if (path.pass_this) {
        // (Through unchanged, the interiors kept right.)
        trace_photon(instant_ray(through_start, h.time, h.d), light, weight, h.refracted(passed),
                     path, state);
        leave();
        return;
    }

    // The layers, top first, as the shader sees them (a texture_map's
    // first plain texture): what passes through them all (POV-Ray's
    // FilCol), and how much still does (Trans).
    ShadingScratch& scratch = state.shading_at(path.level);
    scratch.texture.clear();
    if (p.blended)
        for (const auto& b : p.blend)
            b.texture->sample(h.point, p.uv, h.time, h.raw, scratch.texture, b.weight);
    else
        p.texture->sample(h.point, p.uv, h.time, h.raw, scratch.texture);
    if (scratch.texture.plains.empty()) {
        leave();
        return;
    }
    const runtime::TextureSample::Plain& plain = scratch.texture.plains.front();
    const runtime::TextureSample::Layer* layers = scratch.texture.layers.data() + plain.first;
    glm::dvec3 through(1.0);
    double trans = 1.0;
    std::size_t used = 0;
    for (; used < plain.count && trans > bailout; ++used) {
        const runtime::MaterialSample& m = layers[used].material;
        through *= m.filter * m.colour + glm::dvec3(m.transmit);
        if (m.conserve_energy && reflects(m))
            through *= glm::min(
                glm::dvec3(1.0),
                glm::dvec3(1.0) -
                    reflectivity(m, -glm::dot(h.d, layers[used].normal), fresnel_ior(h, m)).colour);
        trans = std::min(1.0, std::fabs(0.297 * through.x + 0.589 * through.y + 0.114 * through.z));
    }

    // Refracted, where the object or its light asks (caustics through glass).
    bool total_internal_reflection = false;
    const runtime::LightPhotons& asks = source.photons();
    if (photon_on(f.photon_refraction, asks.refraction) && trans > bailout) {
        const double w =
            weight * std::max({std::fabs(through.x), std::fabs(through.y), std::fabs(through.z)});
        const glm::dvec3& normal = layers[0].normal;
        const bool straight = std::fabs(ratio.ior - 1.0) < kEpsilon && !disperses;
        // A photon along ratio `eta` with light `carried`: refracted, or
        // reflected inside (unfiltered, as POV-Ray's ComputeReflection).
        const auto refracted = [&](double eta, const glm::dvec3& carried) {
            glm::dvec3 out;
            const bool reflected = !refraction(h.d, normal, eta, straight, out);
            if (reflected)
                trace_photon(instant_ray(h.start, h.time, reflect(h.d, normal, h.raw)), carried, w,
                             h.carried(), path, state);
            else
                trace_photon(instant_ray(through_start, h.time, out), carried * through, w,
                             h.refracted(passed), path, state);
            return reflected;
        };
        if (!disperses || state.band.monochromatic()) {
            total_internal_reflection = refracted(
                disperses ? state.band.ior(ratio.ior, ratio.dispersion) : ratio.ior, light);
        } else {
            // A photon of every colour splits into every band, each with
            // its share of the light (POV-Ray's PhotonTrace does so
            // whatever the render's sampling: a map holds every band).
            const SpectralBand every = state.band;
            const int bands = ratio.dispersion_samples;
            for (int i = 0; i < bands; ++i) {
                state.band = SpectralBand::of(i, bands);
                refracted(state.band.ior(ratio.ior, ratio.dispersion),
                          light * state.band.hue() / static_cast<double>(bands));
            }
            state.band = every;
        }
    }

    // Reflected by each layer (not along the top layer's normal after
    // total internal reflection, which that already followed).
    if (photon_on(f.photon_reflection, asks.reflection)) {
        for (std::size_t i = 0; i < used; ++i) {
            const runtime::TextureSample::Layer& layer = layers[i];
            const runtime::MaterialSample& m = layer.material;
            if (!reflects(m)) continue;
            if (total_internal_reflection && layer.normal == layers[0].normal) continue;
            const Reflectivity r = reflectivity(m, -glm::dot(h.d, layer.normal), fresnel_ior(h, m));
            if (r.colour == glm::dvec3(0.0)) continue;
            // (POV-Ray's photon weight takes the reflectivity twice:
            // ComputeReflectivity scales the layer's weight by it, and
            // the photon's weight is that times its largest channel
            // again. Photon paths through glass end a level sooner so.)
            const double w = weight * layer_trans(layers, i) * r.weight *
                             std::max({r.colour.x, r.colour.y, r.colour.z});
            trace_photon(instant_ray(h.start, h.time, reflect(h.d, layer.normal, h.raw)),
                         r.colour * raised(light, m.reflection_power), w, h.carried(), path, state);
        }
    }
    leave();
}

glm::dvec3 Shader::photon_light(const Hit& h, const runtime::MaterialSample& m, const glm::dvec3& n,
                                double opaque, PhotonGather& gather, ThreadState& state) const {
    gather.variance = glm::dvec3(0.0);
    if (m.diffuse == 0.0 && m.diffuse_back == 0.0 && m.specular == 0.0 && m.phong == 0.0)
        return glm::dvec3(0.0);
    // Gathered once for the hit, about the first layer's normal that asks
    // (POV-Ray's gatherer, kept for the hit's layers).
    if (!gather.done) {
        gather.done = true;
        ++state.counters.photon_gathers;
        gather.radius = photon_map_->gather(h.point, n, gather.photons);
    }
    if (gather.photons.empty() || !(gather.radius > 0.0)) return glm::dvec3(0.0);
    glm::dvec3 sum(0.0), squares(0.0);
    for (const auto& [distance2, photon] : gather.photons) {
        const glm::dvec3 from(photon->from);
        // (POV-Ray's Lambertian compensation, by the raw normal, at most
        // tenfold: the photon's own angle is in its density already.)
        const double compensation = 1.0 / std::clamp(glm::dot(h.raw, from), 0.1, 1.0);
        const glm::dvec3 arriving = glm::dvec3(photon->colour) * compensation;
        double cosine = glm::dot(n, from);
        if (h.double_lit) cosine = std::fabs(cosine);
        // (From behind the surface: diffuse's second value, no highlights.)
        const bool backside = cosine < kEpsilon;
        if (backside && m.diffuse_back == 0.0) continue;
        if (backside) cosine = std::fabs(cosine);
        const double shade = m.brilliance == 1.0 ? cosine : std::pow(cosine, m.brilliance);
        glm::dvec3 lit = (backside ? m.diffuse_back : m.diffuse) * shade * opaque * m.colour;
        if (state.radiosity.depth == 0 && !backside) lit += highlights(m, h.d, n, from, cosine);
        if (m.irid > 0.0)
            lit *= iridescence(m, from, h.d, n, h.point, irid_wavelength_, noise_generator_);
        sum += lit * arriving;
        squares += (lit * arriving) * (lit * arriving);
    }
    const double area = std::numbers::pi * gather.radius * gather.radius;
    gather.variance = squares / (area * area);
    return sum / area;
}

// POV-Ray's ComputeShadowColour: where photons carry a light through a
// refracting target, the target's filtered shadow of that light is dark
// (the caustic is the light that passes), unless the lit object ignores
// photons (collect off).
bool Shader::photon_shadow(const runtime::IntelligentObject& object, std::size_t light) const {
    const runtime::ObjectFlags& f = object.flags();
    const runtime::LightPhotons& asks = lights_[light].photons();
    return f.photon_target > 0.0f && f.photon_refraction != -1 && asks.refraction != -1 &&
           (f.photon_refraction == 1 || asks.refraction == 1);
}

glm::dvec3 Shader::photon_media(const Ray4& ray, double way, const Inside& inside,
                                const glm::dvec3& colour, PhotonPath& path) const {
    std::vector<const runtime::MediaVolume::One*> media;
    for (int i = 0; i < inside.count; ++i)
        if (const runtime::MediaVolume* v = inside.entries[std::size_t(i)].media)
            for (const auto& one : v->media()) media.push_back(&one);
    MediaRay m;
    m.origin = glm::dvec3(ray.origin);
    m.direction = glm::normalize(glm::dvec3(ray.direction));
    m.depth = way;
    m.time = ray.origin.w;
    // (Each photon's way its own numbers, from where it starts and goes:
    // a frame does not depend on the threads.)
    std::uint64_t seed = static_cast<std::uint64_t>(path.level);
    for (const double x : {m.origin.x, m.origin.y, m.origin.z, m.direction.x, m.direction.y}) {
        std::uint64_t bits = 0;
        std::memcpy(&bits, &x, sizeof bits);
        seed = (seed ^ bits) * 0x9E3779B97F4A7C15ull;
    }
    MediaRandom random(seed);
    if (path.level <= 1 || path.pass_prev || photons_.media_max_steps <= 0 || !path.media_out)
        return photon_through_media(media, m, random, nullptr, colour);
    const ShadedLight& source = lights_[path.shot->light];
    MediaPhotonDeposit deposit;
    deposit.spread = path.shot->spread;
    deposit.depth = path.depth;
    deposit.parallel = source.parallel();
    deposit.max_steps = photons_.media_max_steps;
    deposit.spacing_factor = photons_.media_spacing_factor;
    deposit.jitter = photons_.jitter;
    deposit.keep = [&](const glm::dvec3& point, double along, const glm::dvec3& light) {
        // (POV-Ray's addMediaPhoton: as a surface photon's, the spread
        // squared, the distance squared and the light's fade taken back.)
        const double depth = path.depth + along;
        double area = deposit.spread * deposit.spread;
        if (!deposit.parallel) area *= depth * depth;
        const glm::dvec3 kept = light * (source.fade(depth, m.time) * area);
        if (!std::isfinite(kept.x + kept.y + kept.z)) return;
        Photon photon;
        photon.position = glm::vec3(point);
        photon.colour = glm::vec3(kept);
        photon.from = glm::vec3(-m.direction);
        photon.time = static_cast<float>(m.time);
        path.media_out->push_back(photon);
    };
    return photon_through_media(media, m, random, &deposit, colour);
}

}  // namespace hexant::tracer
