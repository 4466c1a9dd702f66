#include "runtime/scene/media_volume.hpp"

namespace hexant::runtime {

namespace {

glm::dvec3 rgb(const ColourFunction& c, double t) {
    return {c.c[0](t), c.c[1](t), c.c[2](t)};
}

}  // namespace

MediaVolume::MediaVolume(std::vector<Media> media) {
    media_.reserve(media.size());
    for (Media& m : media) {
        One one;
        for (const Pigment& d : m.density) {
            Texture holder;
            holder.pigment = d;
            one.density.emplace_back(holder, std::nullopt);
        }
        one.still = !(m.absorption.depends_on_time() || m.emission.depends_on_time() ||
                      m.scattering.depends_on_time() || m.eccentricity.depends_on_time() ||
                      m.extinction.depends_on_time());
        one.record = std::move(m);
        if (one.still) {
            const One::At a = one.evaluate(0.0);
            one.absorption = a.absorption;
            one.emission = a.emission;
            one.scattering = a.scattering;
            one.eccentricity = a.eccentricity;
            one.extinction = a.extinction;
        }
        media_.push_back(std::move(one));
    }
}

MediaVolume::One::At MediaVolume::One::at(double t) const {
    if (still) return {absorption, emission, scattering, eccentricity, extinction};
    return evaluate(t);
}

MediaVolume::One::At MediaVolume::One::evaluate(double t) const {
    return {rgb(record.absorption, t), rgb(record.emission, t), rgb(record.scattering, t),
            record.eccentricity(t), record.extinction(t)};
}

glm::dvec3 MediaVolume::One::density_at(const glm::dvec3& point, double t) const {
    glm::dvec3 product(1.0);
    for (const TextureEvaluator& d : density) product *= d.at(point, glm::dvec2(0.0), t).colour;
    return product;
}

}  // namespace hexant::runtime
