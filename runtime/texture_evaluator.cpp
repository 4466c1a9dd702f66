#include "runtime/texture_evaluator.hpp"

#include <cmath>

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

TextureEvaluator::TextureEvaluator(const Texture& texture, const std::optional<Interior>& interior)
    : pattern_(texture.pigment.pattern),
      // Only a pattern reads its placement: a plain colour keeps none (a
      // moving object's motion compiled again is most of a kilobyte).
      pattern_to_world_(pattern_ == Pigment::Pattern::Checker ? Motion(pattern_transform(texture))
                                                              : Motion()),
      ambient_(texture.finish.ambient), diffuse_(texture.finish.diffuse),
      brilliance_(texture.finish.brilliance), phong_(texture.finish.phong),
      phong_size_(texture.finish.phong_size), specular_(texture.finish.specular),
      roughness_(texture.finish.roughness), emission_(texture.finish.emission),
      ior_(interior ? CompiledScalar(interior->ior) : CompiledScalar(1.0)) {
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
    for (int i = 0; i < 3; ++i) reflection_[i] = CompiledScalar(texture.finish.reflection.c[i]);
    const Finish& f = texture.finish;
    for (const TimeFunction* value :
         {&f.ambient, &f.diffuse, &f.brilliance, &f.phong, &f.phong_size, &f.specular,
          &f.roughness, &f.emission, &f.reflection.c[0], &f.reflection.c[1], &f.reflection.c[2]})
        depends_on_time_ = depends_on_time_ || value->depends_on_time();
    if (interior) depends_on_time_ = depends_on_time_ || interior->ior.depends_on_time();
    if (pattern_ == Pigment::Pattern::Checker)
        depends_on_time_ = depends_on_time_ || !pattern_to_world_.is_static();
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
        const auto p = pattern_to_world_.to_object<double>({world_point.x, world_point.y,
                                                            world_point.z}, t);
        which = static_cast<std::size_t>(checker_index({p[0], p[1], p[2]}));
    }
    const CompiledColour& colour = colours_[which];
    MaterialSample m;
    m.colour = {colour.c[0].at(t), colour.c[1].at(t), colour.c[2].at(t)};
    m.filter = colour.c[3].at(t);
    m.transmit = colour.c[4].at(t);
    m.ambient = ambient_.at(t);
    m.diffuse = diffuse_.at(t);
    m.brilliance = brilliance_.at(t);
    m.phong = phong_.at(t);
    m.phong_size = phong_size_.at(t);
    m.specular = specular_.at(t);
    m.roughness = roughness_.at(t);
    m.reflection = {reflection_[0].at(t), reflection_[1].at(t), reflection_[2].at(t)};
    m.emission = emission_.at(t);
    m.ior = ior_.at(t);
    return m;
}

}  // namespace hexant::runtime
