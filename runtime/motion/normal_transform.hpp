// Carrying a surface normal through a linear map L (an affine transform's
// linear part, or a deformation's Jacobian): the normal transforms by the
// inverse transpose of L. The cofactor matrix equals det(L) times that
// inverse transpose, so using it (and the sign of det) gives the same
// direction without a division: a map that flattens an object (a zero
// scale) yields a zero vector here, never Inf or NaN.
#pragma once

#include <cmath>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>

namespace hexant::runtime {

// A linear map's action on normals, formed once: the rows of its cofactor
// matrix and the sign of its determinant. An object that never moves keeps
// one, so that each hit it shades pays three products, not the cofactors.
struct NormalMap {
    glm::dvec3 r0{1, 0, 0}, r1{0, 1, 0}, r2{0, 0, 1};
    bool flip = false;  // det(L) < 0

    NormalMap() = default;
    explicit NormalMap(const glm::dmat3& linear) {
        const glm::dvec3 c0 = linear[0], c1 = linear[1], c2 = linear[2];
        r0 = glm::cross(c1, c2);
        r1 = glm::cross(c2, c0);
        r2 = glm::cross(c0, c1);
        flip = glm::dot(c0, r0) < 0.0;  // det(L) = c0 . (c1 x c2)
    }

    // The unit normal after the map; `fallback` (unit) when the map leaves
    // no direction (a degenerate map).
    glm::dvec3 apply(const glm::dvec3& normal, const glm::dvec3& fallback) const {
        // L's inverse has rows r0, r1, r2 over det(L), so its transpose has
        // them as columns: det(L) L^-T n = r0 n.x + r1 n.y + r2 n.z.
        glm::dvec3 out = r0 * normal.x + r1 * normal.y + r2 * normal.z;
        if (flip) out = -out;
        const double length = glm::length(out);
        if (!(length > 0.0) || !std::isfinite(length)) return fallback;
        return out / length;
    }
};

// The unit normal after the map; `fallback` (unit) when the map leaves no
// direction (a degenerate map).
inline glm::dvec3 transform_normal(const glm::dmat3& linear, const glm::dvec3& normal,
                                   const glm::dvec3& fallback) {
    return NormalMap(linear).apply(normal, fallback);
}

}  // namespace hexant::runtime
