#include "runtime/scene/media.hpp"

#include "runtime/texture/material.hpp"

namespace hexant::runtime {

Media Media::legacy() {
    Media m;
    m.method = 1;
    m.intervals = 10;
    m.min_samples = m.max_samples = 1;
    return m;
}

void Media::transform_by(const TransformStep& step) {
    for (Pigment& d : density) d.transform.append(step);
}

void Media::transform_by(const Transform& step) {
    for (Pigment& d : density) d.transform.append(step);
}

bool Media::depends_on_time() const {
    if (absorption.depends_on_time() || emission.depends_on_time() ||
        scattering.depends_on_time() || eccentricity.depends_on_time() ||
        extinction.depends_on_time())
        return true;
    for (const Pigment& d : density)
        if (d.depends_on_time()) return true;
    return false;
}

}  // namespace hexant::runtime
