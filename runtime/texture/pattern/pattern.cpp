#include "runtime/texture/pattern/pattern.hpp"

#include <cmath>

#include "runtime/texture/pattern/image_map.hpp"
#include "runtime/texture/pattern/kinds/mandel.hpp"

namespace hexant::runtime::pattern {

bool Turbulence::depends_on_time() const {
    return amount.depends_on_time() || octaves.depends_on_time() || omega.depends_on_time() ||
           lambda.depends_on_time();
}

Pattern Pattern::of(const Kind& kind) {
    Pattern p;
    p.kind = &kind;
    p.vector = Vector3Function{{kind.vector.x, kind.vector.y, kind.vector.z}};
    p.number = {kind.number[0], kind.number[1]};
    for (std::size_t i = 0; i < p.more.size(); ++i) p.more[i] = kind.more[i];
    p.wave = kind.wave;
    p.frequency = kind.frequency ? 1.0 : 0.0;
    return p;
}

const std::vector<MapEntry>& default_map(const Pattern& pattern) {
    // POV-Ray's Post_Pigment: mandel's map is its own at exponent 2 only;
    // its other exponents are other patterns there (MANDEL3_PATTERN...),
    // given the grey map.
    static const std::vector<MapEntry> grey(kGrayMap.begin(), kGrayMap.end());
    const TimeFunction& exponent = pattern.number[kinds::Mandel::kExponent];
    if (pattern.kind->name == kinds::Mandel::keyword && exponent.constant() != 2.0) return grey;
    return pattern.kind->default_map;
}

bool Pattern::depends_on_time() const {
    if (vector.depends_on_time() || number[0].depends_on_time() || number[1].depends_on_time() ||
        frequency.depends_on_time() || phase.depends_on_time() || exponent.depends_on_time() ||
        vector2.depends_on_time())
        return true;
    for (const TimeFunction& n : more)
        if (n.depends_on_time()) return true;
    if (turbulence && turbulence->depends_on_time()) return true;
    if (function && function->depends_on_time()) return true;
    if (image && image->images.size() > 1) return true;  // an image sequence
    for (const Warp& w : warps)
        if (w.transform ? w.transform->depends_on_time()
            : w.point   ? pattern::depends_on_time(*w.point)
                        : w.turbulence.depends_on_time())
            return true;
    return false;
}

double evaluate(const Kind& kind, const glm::dvec3& point, const Values& values, Wave wave,
                double exponent) {
    double value = kind.value(point, values);
    // POV-Ray's fmod by 1.00001, not 1: a value of exactly 1 stays 1.
    if (values.frequency != 0.0)
        value = std::fmod(value * values.frequency + values.phase, 1.00001);
    if (value < 0.0) value -= std::floor(value);
    switch (wave) {
        case Wave::Ramp:
            break;
        case Wave::Sine:
            value = (1.0 + cycloidal(value)) * 0.5;
            break;
        case Wave::Triangle:
            value = triangle_wave(value);
            break;
        case Wave::Scallop:
            value = std::fabs(cycloidal(value * 0.5));
            break;
        case Wave::Cubic:
            value = value * value * ((-2.0 * value) + 3.0);
            break;
        case Wave::Poly:
            value = std::pow(value, exponent);
            break;
    }
    return value;
}

glm::dvec3 apply_turbulence(const glm::dvec3& point, const glm::dvec3& amount, const Octaves& o) {
    if (amount.x == 0.0 && amount.y == 0.0 && amount.z == 0.0) return point;
    const glm::dvec3 d = dturbulence(point, o);
    return {point.x + d.x * amount.x, point.y + d.y * amount.y, point.z + d.z * amount.z};
}

std::array<double, 5> map_colour(const std::vector<MapEntry>& map, double value) {
    if (map.empty()) return {};
    const BlendPick pick =
        search_blend_map(value, map.size(), [&](std::size_t i) { return map[i].value; });
    if (pick.prev == pick.cur) return map[pick.cur].colour;
    const auto& a = map[pick.prev].colour;
    const auto& b = map[pick.cur].colour;
    std::array<double, 5> c;
    for (std::size_t i = 0; i < 5; ++i) c[i] = a[i] + pick.f * (b[i] - a[i]);
    return c;
}

}  // namespace hexant::runtime::pattern
