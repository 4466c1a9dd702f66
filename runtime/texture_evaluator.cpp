#include "runtime/texture_evaluator.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>

#include "runtime/object_error.hpp"

namespace hexant::runtime {

namespace {

Transform pattern_transform(const Texture& texture) {
    Transform t = texture.pigment.transform;
    t.append(texture.transform);
    return t;
}

}  // namespace

TextureEvaluator::CompiledColour TextureEvaluator::compile(const ColourFunction& colour) {
    CompiledColour out;
    for (int i = 0; i < 5; ++i) out.c[i] = CompiledScalar(colour.c[i]);
    return out;
}

std::shared_ptr<const TextureEvaluator::CompiledFinish> TextureEvaluator::compile(
    const Finish& f, const std::optional<Interior>& interior) {
    const auto make = [&] {
        return std::make_shared<const CompiledFinish>(CompiledFinish{
            CompiledScalar(f.ambient), CompiledScalar(f.diffuse), CompiledScalar(f.brilliance),
            CompiledScalar(f.phong), CompiledScalar(f.phong_size), CompiledScalar(f.specular),
            CompiledScalar(f.roughness), CompiledScalar(f.emission),
            interior ? CompiledScalar(interior->ior) : CompiledScalar(1.0),
            {CompiledScalar(f.reflection.c[0]), CompiledScalar(f.reflection.c[1]),
             CompiledScalar(f.reflection.c[2])}});
    };
    using Key = std::array<double, 12>;
    Key key{};
    std::size_t n = 0;
    for (const TimeFunction* value :
         {&f.ambient, &f.diffuse, &f.brilliance, &f.phong, &f.phong_size, &f.specular,
          &f.roughness, &f.emission, &f.reflection.c[0], &f.reflection.c[1], &f.reflection.c[2]}) {
        if (!value->is_constant()) return make();
        key[n++] = value->constant();
    }
    if (interior && !interior->ior.is_constant()) return make();
    key[n] = interior ? interior->ior.constant() : 1.0;
    // Finishes of constants, shared while some texture holds them. Objects
    // are made on several threads at once in tests, so the table is locked
    // (once per object, while the scene is being set up).
    static std::mutex mutex;
    static std::map<Key, std::weak_ptr<const CompiledFinish>> shared;
    const std::lock_guard lock(mutex);
    auto& slot = shared[key];
    if (auto kept = slot.lock()) return kept;
    static std::size_t prune_at = 64;
    if (shared.size() > prune_at) {  // forget finishes no texture holds any more
        std::erase_if(shared, [](const auto& entry) { return entry.second.expired(); });
        prune_at = std::max<std::size_t>(64, 2 * shared.size());  // amortized: linear in all
    }
    auto made = make();
    shared[key] = made;
    return made;
}

TextureEvaluator::TextureEvaluator(const Texture& texture, const std::optional<Interior>& interior)
    : pattern_(texture.pigment.pattern),
      pattern_to_world_(pattern_ == Pigment::Pattern::Checker
                            ? std::make_shared<const Motion>(pattern_transform(texture))
                            : nullptr),
      finish_(compile(texture.finish, interior)) {
    if (pattern_ == Pigment::Pattern::Unsupported)
        throw ObjectError(texture.pigment.unsupported_place,
                          "pigment pattern '" + texture.pigment.unsupported_name +
                              "' is not supported by hexant's tracer");
    const std::size_t needed = pattern_ == Pigment::Pattern::Checker ? 2 : 1;
    if (texture.pigment.colours.size() < needed)
        throw std::logic_error("TextureEvaluator: pigment without its colours");
    for (const auto& colour : texture.pigment.colours) {
        colours_.push_back(compile(colour));
        depends_on_time_ = depends_on_time_ || colour.depends_on_time();
    }
    const Finish& f = texture.finish;
    for (const TimeFunction* value :
         {&f.ambient, &f.diffuse, &f.brilliance, &f.phong, &f.phong_size, &f.specular,
          &f.roughness, &f.emission, &f.reflection.c[0], &f.reflection.c[1], &f.reflection.c[2]})
        depends_on_time_ = depends_on_time_ || value->depends_on_time();
    if (interior) depends_on_time_ = depends_on_time_ || interior->ior.depends_on_time();
    if (pattern_ == Pigment::Pattern::Checker)
        depends_on_time_ = depends_on_time_ || !pattern_to_world_->is_static();
}

int checker_index(const glm::dvec3& p) {
    // POV-Ray 3.7's rule for a point on a cell's boundary (CheckerPattern::
    // Evaluate in source/core/material/pattern.cpp): each coordinate is
    // floored after adding EPSILON = 1e-10 (configcore.h), so a face lying
    // on a boundary in pattern space (a plane at an integer height, the
    // common idiom) takes the upper cell whichever way its points rounded.
    // The margin is in the pattern's own units (one cell), so it holds at
    // every world scale the pattern is scaled with.
    constexpr double kBoundary = 1.0e-10;
    const double sum = std::floor(p.x + kBoundary) + std::floor(p.y + kBoundary) +
                       std::floor(p.z + kBoundary);
    // fmod of an integer-valued double is exact; no int overflow far away.
    return std::fabs(std::fmod(sum, 2.0)) == 1.0 ? 1 : 0;
}

MaterialSample TextureEvaluator::at(const glm::dvec3& world_point, double t) const {
    std::size_t which = 0;
    if (pattern_ == Pigment::Pattern::Checker) {
        const auto p = pattern_to_world_->to_object<double>({world_point.x, world_point.y,
                                                            world_point.z}, t);
        which = static_cast<std::size_t>(checker_index({p[0], p[1], p[2]}));
    }
    const CompiledColour& colour = colours_[which];
    MaterialSample m;
    m.colour = {colour.c[0].at(t), colour.c[1].at(t), colour.c[2].at(t)};
    m.filter = colour.c[3].at(t);
    m.transmit = colour.c[4].at(t);
    const CompiledFinish& f = *finish_;
    m.ambient = f.ambient.at(t);
    m.diffuse = f.diffuse.at(t);
    m.brilliance = f.brilliance.at(t);
    m.phong = f.phong.at(t);
    m.phong_size = f.phong_size.at(t);
    m.specular = f.specular.at(t);
    m.roughness = f.roughness.at(t);
    m.reflection = {f.reflection[0].at(t), f.reflection[1].at(t), f.reflection[2].at(t)};
    m.emission = f.emission.at(t);
    m.ior = f.ior.at(t);
    return m;
}

}  // namespace hexant::runtime
