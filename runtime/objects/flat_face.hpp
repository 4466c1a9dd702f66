// A flat piece of an object's surface, in object space, for the check that
// finds coincident surfaces (runtime/scene/coincident_faces.hpp). A kind
// whose surface has flat pieces lists them with
//
//   std::vector<objects::FlatFace> flat_faces(double t) const;
//
// (box: its six faces; cylinder and cone: their caps; disc, triangle,
// plane). Kinds without it take part in no such check.
#pragma once

#include <vector>

#include <glm/glm.hpp>

namespace hexant::runtime::objects {

struct FlatFace {
    // The side the surface faces (a solid's outward normal), any length > 0.
    glm::dvec3 normal{0.0, 1.0, 0.0};
    // A point of its plane.
    glm::dvec3 point{0.0};
    // A convex polygon in that plane, its corners in order around it; empty
    // for the whole plane (a plane object).
    std::vector<glm::dvec3> corners;
    // Seen alike from both sides (a disc, a triangle): no inside hides it.
    bool two_sided = false;
};

// Adds a circle of `radius` about `center` in the plane normal to `normal`,
// as the convex polygon inscribed in it (16 corners: inside the circle, so
// two faces found to overlap do overlap); nothing for a radius <= 0 or a
// zero normal.
void add_circle_face(std::vector<FlatFace>& faces, const glm::dvec3& center,
                     const glm::dvec3& normal, double radius, bool two_sided);

}  // namespace hexant::runtime::objects
