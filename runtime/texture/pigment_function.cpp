#include "runtime/texture/pigment_function.hpp"

#include "runtime/texture/texture_evaluator.hpp"

namespace hexant::runtime {

namespace {

Texture texture_of(const Pigment& pigment) {
    Texture texture;
    texture.pigment = pigment;
    return texture;
}

}  // namespace

PigmentFunction::PigmentFunction(const Pigment& pigment, std::string name)
    : evaluator_(std::make_unique<const TextureEvaluator>(texture_of(pigment), std::nullopt)),
      depends_on_time_(pigment.depends_on_time()),
      name_(std::move(name)) {}

PigmentFunction::~PigmentFunction() = default;

double PigmentFunction::at(int component, const glm::dvec3& p, double t) const {
    const MaterialSample m = evaluator_->at(p, glm::dvec2(0.0), t);
    switch (component) {
        case 0:
        case 1:
        case 2:
            return m.colour[component];
        case 3:
            return m.filter;
        default:
            return m.transmit;
    }
}

}  // namespace hexant::runtime
