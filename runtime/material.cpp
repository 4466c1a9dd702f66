#include "runtime/material.hpp"

namespace hexant::runtime {

bool ColourMap::depends_on_time() const {
    for (const auto& e : entries)
        if (e.value.depends_on_time() || e.colour.depends_on_time()) return true;
    return false;
}

bool Pigment::depends_on_time() const {
    if (pattern == Pattern::Solid) return colours.front().depends_on_time();
    if (pattern == Pattern::Unsupported) return false;
    if (pattern == Pattern::Image)
        return patterned.depends_on_time() || transform.depends_on_time() || image_map->images.size() > 1 ||
               image_map->filter_all.depends_on_time() || image_map->transmit_all.depends_on_time();
    if (patterned.depends_on_time() || colour_map.depends_on_time() || transform.depends_on_time()) return true;
    for (const auto& e : pigment_map)
        if (e.value.depends_on_time() || e.pigment->depends_on_time()) return true;
    return false;
}

bool Normal::depends_on_time() const {
    if (patterned.depends_on_time() || amount.depends_on_time() || accuracy.depends_on_time() ||
        transform.depends_on_time())
        return true;
    for (const auto& e : normal_map)
        if (e.value.depends_on_time() || e.normal->depends_on_time()) return true;
    for (const auto& e : slope_map)
        if (e.value.depends_on_time() || e.height.depends_on_time() || e.slope.depends_on_time()) return true;
    return false;
}

void Texture::transform_by(const Transform& step) {
    transform.append(step);
    for (Texture& layer : below) layer.transform_by(step);
}

void Texture::transform_by(const TransformStep& step) {
    transform.append(step);
    for (Texture& layer : below) layer.transform_by(step);
}

bool Texture::depends_on_time() const {
    if (transform.depends_on_time()) return true;
    if (is_patterned()) {
        if (patterned.depends_on_time()) return true;
        for (const auto& e : texture_map)
            if (e.value.depends_on_time() || e.texture->depends_on_time()) return true;
        return false;
    }
    if (pigment.depends_on_time() || (normal && normal->depends_on_time())) return true;
    const Finish& f = finish;
    for (const TimeFunction* value : {&f.ambient, &f.diffuse, &f.brilliance, &f.phong, &f.phong_size, &f.specular,
                                      &f.roughness, &f.emission})
        if (value->depends_on_time()) return true;
    if (f.reflection.depends_on_time()) return true;
    for (const Texture& layer : below)
        if (layer.depends_on_time()) return true;
    return false;
}

}  // namespace hexant::runtime
