// f_noise3d as an isosurface reads it (runtime/texture/pattern/
// noise_function.hpp): its gradient against central differences of the
// noise itself, and its bound over boxes against the noise sampled inside
// them, for each generator, at random points and boxes (seeded), across
// lattice cells and negative coordinates. A gradient term with a wrong
// sign or corner is off by 0.1 or more; a slope bound that is too small
// lets a sample escape.
#include "runtime/texture/pattern/noise_function.hpp"

#include <array>
#include <cmath>
#include <random>

#include <catch2/catch.hpp>

namespace pt = hexant::runtime::pattern;
using hexant::runtime::Interval;

TEST_CASE("the noise's gradient is its derivative", "[runtime][pattern][function]") {
    std::mt19937 random(7);
    std::uniform_real_distribution<double> coordinate(-20.0, 20.0);
    for (int generator = 1; generator <= 3; ++generator) {
        INFO("generator " << generator);
        int compared = 0;
        for (int i = 0; i < 300; ++i) {
            const glm::dvec3 p(coordinate(random), coordinate(random), coordinate(random));
            // (Where the clamp bites the value is flat; skip those points,
            // and points within h of a cell face, where the difference
            // straddles two cells' polynomials.)
            const double v = pt::noise(p, generator);
            if (v <= 1e-6 || v >= 1 - 1e-6) continue;
            // (Perlin's noise reads p + 10000000.023157213: a difference
            // there loses 1e-9 per coordinate, so its step is wider.)
            const double h = generator == 3 ? 1e-3 : 1e-6;
            const double shift = generator == 3 ? 0.023157213 : 0.0;
            bool near_face = false;
            for (int k = 0; k < 3; ++k) {
                const double f = p[k] + shift - std::floor(p[k] + shift);
                near_face = near_face || f < 2 * h || f > 1 - 2 * h;
            }
            if (near_face) continue;
            const glm::dvec3 g = pt::noise_gradient(p, generator);
            for (int k = 0; k < 3; ++k) {
                glm::dvec3 a = p, b = p;
                a[k] -= h;
                b[k] += h;
                const double d = (pt::noise(b, generator) - pt::noise(a, generator)) / (2 * h);
                CHECK(g[k] == Approx(d).margin(generator == 3 ? 1e-4 : 1e-5));
            }
            ++compared;
        }
        CHECK(compared > 200);
    }
}

TEST_CASE("the noise's bound over a box holds every value inside", "[runtime][pattern][function]") {
    std::mt19937 random(11);
    std::uniform_real_distribution<double> coordinate(-6.0, 6.0);
    std::uniform_real_distribution<double> size(0.0, 1.5);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int generator = 1; generator <= 3; ++generator) {
        INFO("generator " << generator);
        const pt::NoiseFunction f(generator);
        double narrowest = 1.0;
        for (int i = 0; i < 200; ++i) {
            std::array<Interval, 3> box;
            for (auto& side : box) {
                const double lo = coordinate(random);
                side = Interval(lo, lo + size(random) * size(random));
            }
            const Interval range = f.over(0, box, Interval(0.0));
            narrowest = std::min(narrowest, range.hi - range.lo);
            for (int j = 0; j < 200; ++j) {
                const glm::dvec3 p(box[0].lo + unit(random) * (box[0].hi - box[0].lo),
                                   box[1].lo + unit(random) * (box[1].hi - box[1].lo),
                                   box[2].lo + unit(random) * (box[2].hi - box[2].lo));
                const double v = f.at(0, p, 0.0);
                REQUIRE(range.contains(v));
            }
        }
        // (Small boxes give narrow bounds, so the isosurface's halving
        // converges: sides of 1e-3 bound to within 0.05.)
        std::array<Interval, 3> small;
        for (auto& side : small) {
            const double lo = coordinate(random);
            side = Interval(lo, lo + 1e-3);
        }
        const Interval tight = f.over(0, small, Interval(0.0));
        CHECK(tight.hi - tight.lo < 0.05);
        (void)narrowest;
    }
}
