// What a ray sees of the open and the volumes it crosses: fog (POV-Ray 3.7's
// ComputeFog), the sky sphere over the background (ComputeSky), and the
// media of the interiors it is in and of the atmosphere (ComputeMedia,
// through tracer/media.hpp), along the ray and along shadow rays.
#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "tracer/shader.hpp"

namespace hexant::tracer {

namespace {

using runtime::Ray4;

glm::dvec3 rgb(const runtime::ColourFunction& c, double t) {
    return {c.c[0](t), c.c[1](t), c.c[2](t)};
}

}  // namespace

glm::dvec3 Shader::fogged(const glm::dvec3& colour, const Ray4& ray, double depth,
                          bool shadow) const {
    // POV-Ray 3.7's ComputeFog: each fog attenuates by att (at least its
    // transmit), filtered by its colour, and adds (1 - att) of its colour.
    glm::dvec3 sum_att(1.0), sum_col(0.0);
    const double t = ray.origin.w;
    const glm::dvec3 origin(ray.origin), direction(ray.direction);
    for (const runtime::Fog& fog : fogs_) {
        const double distance = fog.distance(t);
        if (!(std::fabs(distance) > 1.0e-10)) continue;  // POV-Ray's EPSILON
        double width = depth;
        const auto& c = fog.colour;
        const double r = c.c[0](t), g = c.c[1](t), b = c.c[2](t), filter = c.c[3](t),
                     transmit = c.c[4](t);
        double density = 1.0;
        glm::dvec3 middle = origin + direction * (width / 2.0);
        if (fog.type == 2) {
            glm::dvec3 up(fog.up.c[0](t), fog.up.c[1](t), fog.up.c[2](t));
            if (!fog.up_transform.empty()) up = glm::dmat3(fog.up_transform.matrix_at(t)) * up;
            up = glm::normalize(up);
            const glm::dvec3 p1 = origin, p2 = origin + direction * width;
            const double alt = fog.alt(t), offset = fog.offset(t);
            const double start = (glm::dot(p1, up) - offset) / alt,
                         end = (glm::dot(p2, up) - offset) / alt;
            // Density 1 below the offset, 1 / (1 + y^2) above: its mean
            // along the ray from the integral atan(y).
            if (start <= 0.0)
                density = end <= 0.0 ? 1.0 : (std::atan(end) - start) / (end - start);
            else if (end <= 0.0)
                density = (std::atan(start) - end) / (start - end);
            else if (std::fabs(start - end) > 1.0e-10)
                density = (std::atan(start) - std::atan(end)) / (start - end);
            else
                density = 1.0 / (start * start + 1.0);
            middle = (p1 + p2) * 0.5;
        }
        if (fog.turbulence) {
            const runtime::pattern::Turbulence& turb = *fog.turbulence;
            const glm::dvec3 p =
                middle * glm::dvec3(turb.amount.c[0](t), turb.amount.c[1](t), turb.amount.c[2](t));
            const double k = std::exp(-width / distance);
            const auto octaves =
                runtime::pattern::octaves_of(turb.octaves(t), turb.omega(t), turb.lambda(t));
            width *=
                1.0 - k * std::min(1.0, runtime::pattern::turbulence(p, octaves, noise_generator_) *
                                            fog.turb_depth(t));
        }
        double att = std::exp(-width * density / distance);
        if (att < transmit) att = transmit;
        sum_att *= att * ((1.0 - filter) + filter * glm::dvec3(r, g, b));
        // (A shadow ray is only dimmed: ComputeFog adds no fog colour to
        // a shadow test ray.)
        if (!shadow) sum_col += (1.0 - att) * glm::dvec3(r, g, b);
    }
    return sum_col + sum_att * colour;
}

glm::dvec3 Shader::sky(const glm::dvec3& direction, double t) const {
    const glm::dvec3 background = rgb(background_, t);
    if (sky_layers_.empty()) return background;
    // POV-Ray 3.7's ComputeSky: each layer adds its colour times its
    // opacity (1 - filter - transmit) and what the layers above let
    // through, and lets through its colour times filter, plus transmit;
    // the background is one more layer, opaque.
    glm::dvec3 colour(0.0), through(1.0);
    const glm::dvec3 emission = rgb(sky_emission_, t);
    if (legacy_sky_) {
        // POV-Ray 3.6's rule: a layer shows by what the product of the
        // filters and transmits above it lets through (their sum), and the
        // background by that product's colour times its filter, plus its
        // transmit.
        glm::dvec3 product(1.0);
        double filter = 1.0, transmit = 1.0, trans = 1.0;
        for (const auto& layer : sky_layers_) {
            const runtime::MaterialSample m = layer.at(direction, glm::dvec2(0.0), t);
            colour += m.colour * (trans * (1.0 - m.filter - m.transmit));
            product *= m.colour;
            filter *= m.filter;
            transmit *= m.transmit;
            trans = std::fabs(filter) + std::fabs(transmit);
        }
        return colour * emission + background * (product * filter + glm::dvec3(transmit));
    }
    for (const auto& layer : sky_layers_) {
        const runtime::MaterialSample m =
            layer.at(direction, glm::dvec2(0.0), t);  // (no uv: refused on a sky)
        const double opacity = 1.0 - m.filter - m.transmit;
        colour += m.colour * opacity * through * emission;
        through *= m.colour * m.filter + glm::dvec3(m.transmit);
    }
    return colour + background * through;
}

glm::dvec3 Shader::through_volume(const glm::dvec3& colour, const Ray4& ray, double depth,
                                  const Inside& around, int level, ThreadState& state) const {
    // POV-Ray fogs and fills with media only rays outside non-hollow
    // objects (IsHollowRay): the interiors' media first
    // (ComputeTextureColour), then the atmosphere's and fog (TraceRay).
    if (!around.hollow()) return colour;
    glm::dvec3 seen = colour;
    const bool interiors = around.has_media();
    // (Rainbows after the interiors' media and before the atmosphere's, as
    // TraceRay orders them; their jitter from the sample's own numbers.)
    const auto rainbows = [&] {
        if (rainbows_.empty()) return;
        const SampleIndex& s = state.sample;
        const glm::dvec3 d = glm::normalize(glm::dvec3(ray.direction));
        std::uint64_t bits = 0;
        std::memcpy(&bits, &d.x, sizeof bits);
        MediaRandom random(((std::uint64_t(s.seed) << 32) ^ s.index ^ bits) + 0x5261696eull);
        seen = runtime::through_rainbows(rainbows_, seen, d, depth, [&] { return random.next(); });
    };
    if (!interiors) rainbows();
    if (interiors || atmosphere_) {
        MediaRay m;
        m.origin = glm::dvec3(ray.origin);
        m.direction = glm::normalize(glm::dvec3(ray.direction));
        m.depth = depth;
        m.time = ray.origin.w;
        // The lights media scatter, each over the stretch it reaches.
        std::vector<MediaLight> lights;
        for (std::size_t i = 0; i < lights_.size(); ++i) {
            const ShadedLight& light = lights_[i];
            if (!light.media_interaction() || !light.shines_at(m.time)) continue;
            // (A light_group's lights light its members' surfaces only; a
            // shadowless one, POV-Ray's fill light, lights no media: its
            // ComputeOneMediaLightInterval takes point, spot and cylinder
            // lights only.)
            if (light_group_of_[i] >= 0 || light.shadowless()) continue;
            double s0 = 0.0, s1 = 0.0;
            if (!light.media_interval(m.origin, m.direction, m.time, s0, s1)) continue;
            // (POV-Ray's SMALL_TOLERANCE: a beam that ends at the eye.)
            if (!(s0 < depth && s1 > 1.0e-3)) continue;
            lights.push_back({i, std::max(s0, 0.0), std::min(s1, depth)});
        }
        // Each sample's own numbers, from the pixel sample and the ray.
        const SampleIndex& s = state.sample;
        std::uint64_t seed = (std::uint64_t(s.seed) << 32) ^ s.index ^ (std::uint64_t(level) << 48);
        std::uint64_t bits = 0;
        std::memcpy(&bits, &m.direction.x, sizeof bits);
        seed ^= bits;
        MediaRandom random(seed);
        bool collects = false;  // the media being sampled's
        const MediaLightFn light_at = [&](std::size_t i, const glm::dvec3& point,
                                          glm::dvec3& to_light) {
            return media_light(i, point, m.time, level, around, collects, to_light, state);
        };
        const auto collecting = [](const std::vector<const runtime::MediaVolume::One*>& media) {
            return std::any_of(media.begin(), media.end(),
                               [](const auto* one) { return one->record.collect; });
        };
        if (interiors) {
            std::vector<const runtime::MediaVolume::One*> media;
            for (int i = 0; i < around.count; ++i)
                if (const runtime::MediaVolume* v = around.entries[std::size_t(i)].media)
                    for (const auto& one : v->media()) media.push_back(&one);
            collects = collecting(media);
            seen = through_media(media, m, lights, random, light_at, seen, media_photon_map_);
            rainbows();
        }
        if (atmosphere_) {
            std::vector<const runtime::MediaVolume::One*> media;
            for (const auto& one : atmosphere_->media()) media.push_back(&one);
            collects = collecting(media);
            seen = through_media(media, m, lights, random, light_at, seen, media_photon_map_);
        }
    }
    return fogs_.empty() ? seen : fogged(seen, ray, depth);
}

glm::dvec3 Shader::shadow_media(const glm::dvec3& light, const Ray4& ray, double depth,
                                const runtime::MediaVolume& volume) const {
    std::vector<const runtime::MediaVolume::One*> media;
    for (const auto& one : volume.media()) media.push_back(&one);
    return shadow_media(light, ray, depth, std::move(media));
}

glm::dvec3 Shader::shadow_media(const glm::dvec3& light, const Ray4& ray, double depth,
                                const Inside& around) const {
    std::vector<const runtime::MediaVolume::One*> media;
    for (int i = 0; i < around.count; ++i)
        if (const runtime::MediaVolume* v = around.entries[std::size_t(i)].media)
            for (const auto& one : v->media()) media.push_back(&one);
    return shadow_media(light, ray, depth, std::move(media));
}

glm::dvec3 Shader::shadow_media(const glm::dvec3& light, const Ray4& ray, double depth,
                                std::vector<const runtime::MediaVolume::One*> media) const {
    MediaRay m;
    m.origin = glm::dvec3(ray.origin);
    m.direction = glm::normalize(glm::dvec3(ray.direction));
    m.depth = depth;
    m.time = ray.origin.w;
    m.shadow = true;
    // (A shadow ray gathers no light, so it draws no numbers but jitter's.)
    MediaRandom random(std::uint64_t(depth * 1.0e6));
    return through_media(media, m, {}, random, {}, light);
}

}  // namespace hexant::tracer
