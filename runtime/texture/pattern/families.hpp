// The kinds' value functions, by family file; registry.cpp ties each to
// its name and defaults.
#pragma once

#include <cstddef>
#include <vector>

#include "runtime/texture/pattern/pattern.hpp"

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
// crackle.cpp
double cells_value(const glm::dvec3& p, const Values& v);
double crackle_value(const glm::dvec3& p, const Values& v);
// POV-Ray's PatternRands: 32,768 doubles in [0, 1) (its black hole warp's
// WarpRands is the same sequence).
const std::vector<double>& pattern_rands();
// fractal_patterns.cpp
double mandel_value(const glm::dvec3& p, const Values& v);
double julia_value(const glm::dvec3& p, const Values& v);
double magnet_value(const glm::dvec3& p, const Values& v);
// normal_patterns.cpp: the normal-only patterns' perturbations
glm::dvec3 bumps_normal(const glm::dvec3& p, const Values& v, double amount, const glm::dvec3& n);
glm::dvec3 dents_normal(const glm::dvec3& p, const Values& v, double amount, const glm::dvec3& n);
glm::dvec3 wrinkles_normal(const glm::dvec3& p, const Values& v, double amount,
                           const glm::dvec3& n);
glm::dvec3 quilted_normal(const glm::dvec3& p, const Values& v, double amount, const glm::dvec3& n);
glm::dvec3 ripples_normal(const glm::dvec3& p, const Values& v, double amount, const glm::dvec3& n);
glm::dvec3 waves_normal(const glm::dvec3& p, const Values& v, double amount, const glm::dvec3& n);

// Shared by shape_patterns.cpp and normal_patterns.cpp: the wave sources
// of waves and ripples (POV-Ray's Initialize_Waves; they sum the first
// Values::number_of_waves), and quilted's cubic.
const glm::dvec3& wave_source(std::size_t i);
double wave_frequency(std::size_t i);
double quilt_shape(double t, double control0, double control1);

}  // namespace hexant::runtime::pattern
