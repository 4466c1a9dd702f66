#include "runtime/objects/flat_face.hpp"

#include <cmath>
#include <utility>

#include <glm/glm.hpp>

#include "runtime/geometry/orthonormal_basis.hpp"

namespace hexant::runtime::objects {

void add_circle_face(std::vector<FlatFace>& faces, const glm::dvec3& center,
                     const glm::dvec3& normal, double radius, bool two_sided) {
    constexpr int kCorners = 16;
    constexpr double kTwoPi = 6.28318530717958647692;
    const double length = glm::length(normal);
    if (!(length > 0.0) || !(radius > 0.0) || !std::isfinite(radius)) return;
    FlatFace face{normal, center, {}, two_sided};
    const auto basis = geometry::orthonormal_basis(normal / length);
    face.corners.reserve(kCorners);
    for (int i = 0; i < kCorners; ++i) {
        const double angle = kTwoPi * i / kCorners;
        face.corners.push_back(center +
                               radius * (std::cos(angle) * basis.t1 + std::sin(angle) * basis.t2));
    }
    faces.push_back(std::move(face));
}

}  // namespace hexant::runtime::objects
