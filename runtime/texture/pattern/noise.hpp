// POV-Ray 3.7's solid noise, as its patterns and turbulence read it
// (source/backend/texture/texture.cpp: Noise, DNoise, Turbulence,
// DTurbulence, cycloidal, Triangle_Wave), so that a pattern built on it
// gives POV-Ray's value at every point, to rounding. The lattice hash and
// the Perlin gradients are made by POV-Ray's own generator; the gradient
// table was recorded from POV-Ray's output (noise_table.cpp).
#pragma once

#include <glm/vec3.hpp>

namespace hexant::runtime::pattern {

// global_settings { noise_generator N }: 1 the original (clamped to
// [0, 1]), 2 range-corrected (POV-Ray 3.7's default), 3 Perlin's improved
// solid noise.
inline constexpr int kDefaultNoiseGenerator = 2;

// The scalar noise at p: in [0, 1].
double noise(const glm::dvec3& p, int generator);
// The gradient of noise(p, generator), from the same terms (0 where the
// value is clamped).
glm::dvec3 noise_gradient(const glm::dvec3& p, int generator);
// A bound on |d noise / d axis| for each axis, anywhere: noise is
// continuous, and smooth within each lattice cell, so over a box of
// half-widths h around c it lies within noise(c) +- this * (hx + hy + hz).
// From the tables: each cell's weights' derivatives sum to at most
// 2 * max scurve' = 3 along an axis, each corner's linear term is at most
// max(|m1| + |m2| + |m4| + |m6|) there, and the weights sum to 1 over the
// corners' slopes.
double noise_slope_bound(int generator);
// The vector noise at p (each component about in [-1, 1]); POV-Ray has
// one generator for it.
glm::dvec3 dnoise(const glm::dvec3& p);

// Fractal sums of octaves: octave i (from 1) reads the noise at
// p * lambda^(i-1), weighted omega^(i-1). Octaves are 1 to 10 (POV-Ray
// clamps them so when it reads them).
struct Octaves {
    int octaves = 6;
    double omega = 0.5;
    double lambda = 2.0;
};
// v rounded to single precision, as POV-Ray 3.7 stores a pattern's
// frequency, phase, wave exponent, mortar, controls, agate_turb, colour
// map values, a normal's amount and accuracy (SNGL fields in its frame.h):
// a phase of 0.3 is 0.30000001192 there.
double single(double v);

// Octaves from a scene's numbers as POV-Ray keeps them: the count
// truncated and clamped to 1..10, omega and lambda stored in single
// precision (its TURB record's SNGL fields; an omega of 0.6 is
// 0.60000002384 there, which moves four octaves of turbulence by 1e-8).
Octaves octaves_of(double octaves, double omega, double lambda);
double turbulence(const glm::dvec3& p, const Octaves& o, int generator);
glm::dvec3 dturbulence(const glm::dvec3& p, const Octaves& o);

// POV-Ray's Hash3d: the lattice hash of three integers (each taken & 0xFFF).
int lattice_hash3(int a, int b, int c);

// sin(2 pi v) as POV-Ray computes it for its waves (the fraction rounded
// through 50000ths); and the triangle wave: 0 at integers, 1 halfway.
double cycloidal(double v);
double triangle_wave(double v);

}  // namespace hexant::runtime::pattern
