// The kinds' value functions, by family file; registry.cpp ties each to
// its name and defaults.
#pragma once

#include "runtime/pattern/pattern.hpp"

namespace hexant::runtime::pattern {

// noise_patterns.cpp
double noise_value(const glm::dvec3& p, const Values& v);
double dents_value(const glm::dvec3& p, const Values& v);
double wrinkles_value(const glm::dvec3& p, const Values& v);
double granite_value(const glm::dvec3& p, const Values& v);
double agate_value(const glm::dvec3& p, const Values& v);
// shape_patterns.cpp
double planar_value(const glm::dvec3& p, const Values& v);
double spherical_value(const glm::dvec3& p, const Values& v);
double cylindrical_value(const glm::dvec3& p, const Values& v);
double boxed_value(const glm::dvec3& p, const Values& v);
double gradient_value(const glm::dvec3& p, const Values& v);
double onion_value(const glm::dvec3& p, const Values& v);
double radial_value(const glm::dvec3& p, const Values& v);
double leopard_value(const glm::dvec3& p, const Values& v);
double quilted_value(const glm::dvec3& p, const Values& v);
double spiral1_value(const glm::dvec3& p, const Values& v);
double spiral2_value(const glm::dvec3& p, const Values& v);
double marble_value(const glm::dvec3& p, const Values& v);
double wood_value(const glm::dvec3& p, const Values& v);
double waves_value(const glm::dvec3& p, const Values& v);
double ripples_value(const glm::dvec3& p, const Values& v);
// block_patterns.cpp
double checker_value(const glm::dvec3& p, const Values& v);
double brick_value(const glm::dvec3& p, const Values& v);
double hexagon_value(const glm::dvec3& p, const Values& v);
// fractal_patterns.cpp
double mandel_value(const glm::dvec3& p, const Values& v);

}  // namespace hexant::runtime::pattern
