// Property test of a sphere's placed box (SphereModel::placed_box, issue
// 43): computed in doubles with a margin for their rounding, it must hold
// the exact image of the sphere under the double map, over random spheres
// and maps of every scale, including translations that cancel the centre's
// image (where a relative margin on the result alone would be too small).
//
// The exact image is checked in __float128 (113-bit significands): a
// product of two doubles is exact there, and the sums of four of them err
// by about 2^-110 relative, where the box's margin is about 2^-50; the
// radius term is compared squared, with no root. Samples:
// HEXANT_PROPERTY_SAMPLES (10^5 in the suite).
#include <cmath>
#include <limits>

#include <catch2/catch.hpp>

#include "object_test_support.hpp"
#include "runtime/objects/sphere/sphere_model.hpp"

using namespace object_test;

namespace {

using Quad = __float128;
using hexant::runtime::AffineMap;
using hexant::runtime::IntervalBox;
using Geometry = hexant::runtime::objects::SphereModel::Geometry;

// A random double of magnitude 10^[lo, hi], either sign.
double magnitude(Random& random, double lo, double hi) {
    const double v = std::pow(10.0, random.uniform(lo, hi));
    return random.uniform() < 0.5 ? -v : v;
}

// Does [lo, hi] hold [C - H, C + H] along axis i of the exact image of g
// under m? (C - lo >= H, i.e. (C - lo)^2 >= r^2 |row|^2, with a factor
// 1 + 2^-100 against the quad arithmetic's own rounding.)
bool holds_exact(const Geometry& g, const AffineMap<double>& m, int i, double lo, double hi) {
    const double* row = m.m[i];
    const Quad c = Quad(row[0]) * Quad(g.center.x) + Quad(row[1]) * Quad(g.center.y) +
                   Quad(row[2]) * Quad(g.center.z) + Quad(row[3]);
    const Quad squares =
        Quad(row[0]) * Quad(row[0]) + Quad(row[1]) * Quad(row[1]) + Quad(row[2]) * Quad(row[2]);
    const Quad h2 = Quad(g.radius) * Quad(g.radius) * squares * (Quad(1) + Quad(0x1p-100));
    const Quad below = c - Quad(lo), above = Quad(hi) - c;
    return below >= 0 && above >= 0 && below * below >= h2 && above * above >= h2;
}

// A rotation (from a random unit quaternion) times random scales per
// axis, then a shear now and then.
AffineMap<double> random_map(Random& random, const Geometry& g) {
    const glm::dvec3 axis = random.unit_vector();
    const double angle = random.uniform(0.0, 2.0 * kPi);
    const double s = std::sin(0.5 * angle), c = std::cos(0.5 * angle);
    const double w = c, x = s * axis.x, y = s * axis.y, z = s * axis.z;
    const double rotation[3][3] = {
        {1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)},
        {2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)},
        {2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)}};
    AffineMap<double> m;
    const double scale = std::fabs(magnitude(random, -3.0, 3.0));
    for (int i = 0; i < 3; ++i) {
        const double row_scale =
            random.uniform() < 0.3 ? scale : std::fabs(magnitude(random, -3.0, 3.0));
        for (int j = 0; j < 3; ++j) m.m[i][j] = rotation[i][j] * row_scale;
        if (random.uniform() < 0.2) m.m[i][random.integer(0, 2)] += magnitude(random, -2.0, 2.0);
        const double image =
            m.m[i][0] * g.center.x + m.m[i][1] * g.center.y + m.m[i][2] * g.center.z;
        const double pick = random.uniform();
        // Translations that cancel the centre's image to the last bits, or
        // nearly, or are large beside it, or small.
        m.m[i][3] = pick < 0.3   ? -image
                    : pick < 0.5 ? -image * (1.0 + random.uniform(-1e-12, 1e-12))
                    : pick < 0.8 ? magnitude(random, -3.0, 7.0)
                                 : magnitude(random, -12.0, 0.0);
    }
    return m;
}

}  // namespace

TEST_CASE("a sphere's placed box in doubles holds its exact image", "[object][property]") {
    Random random(43);
    const long wanted = property_samples();
    long tight = 0;
    for (long n = 0; n < wanted; ++n) {
        Geometry g;
        g.center = glm::dvec3(magnitude(random, -3.0, 4.0), magnitude(random, -3.0, 4.0),
                              magnitude(random, -3.0, 4.0));
        if (random.uniform() < 0.1) g.center[random.integer(0, 2)] = 0.0;
        g.radius = std::pow(10.0, random.uniform(-5.0, 2.0));
        const AffineMap<double> m = random_map(random, g);
        const IntervalBox box = hexant::runtime::objects::SphereModel::placed_box(g, m);
        for (int i = 0; i < 3; ++i) {
            if (!holds_exact(g, m, i, box[i].lo, box[i].hi)) {
                INFO("sample " << n << " axis " << i << " centre " << g.center.x << ' '
                               << g.center.y << ' ' << g.center.z << " radius " << g.radius
                               << " box " << box[i].lo << ' ' << box[i].hi);
                FAIL("the exact image outside the placed box");
            }
            // And tight: wider than the exact extent 2H by a few ulps of
            // the terms' magnitudes at most.
            const double* row = m.m[i];
            const double s = std::fabs(row[0] * g.center.x) + std::fabs(row[1] * g.center.y) +
                             std::fabs(row[2] * g.center.z) + std::fabs(row[3]);
            const double h =
                g.radius * std::sqrt(row[0] * row[0] + row[1] * row[1] + row[2] * row[2]);
            const double slack = 32.0 * std::numeric_limits<double>::epsilon() * (s + h);
            if (box[i].hi - box[i].lo <= 2.0 * h + slack) ++tight;
        }
    }
    CHECK(tight == 3 * wanted);
}

TEST_CASE("a sphere's placed box: a NaN or infinite map gives an unbounded side", "[object]") {
    Geometry g;
    g.center = glm::dvec3(1.0, 2.0, 3.0);
    g.radius = 0.5;
    AffineMap<double> m = AffineMap<double>::identity();
    m.m[1][3] = std::numeric_limits<double>::quiet_NaN();
    m.m[2][0] = std::numeric_limits<double>::infinity();
    const IntervalBox box = hexant::runtime::objects::SphereModel::placed_box(g, m);
    CHECK(box[0].lo < 0.5);
    CHECK(box[0].hi > 1.5);
    CHECK(box[0].hi - box[0].lo < 1.0 + 1e-12);
    CHECK(box[1].lo == -std::numeric_limits<double>::infinity());
    CHECK(box[1].hi == std::numeric_limits<double>::infinity());
    CHECK(box[2].lo == -std::numeric_limits<double>::infinity());
    CHECK(box[2].hi == std::numeric_limits<double>::infinity());
}
