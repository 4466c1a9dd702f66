#include "runtime/objects/sor/sor.hpp"

#include <string>

namespace hexant::runtime {

// POV-Ray 3.7's Parse_Sor (parse.cpp): at least four points ("Surface of
// revolution must have at least four points."); every point's radius >= 0
// and the heights of P[2] .. P[N-2] each above the one before
// ("Incorrect point in surface of revolution."), checked here for the
// points that do not move (Compute_Sor's check that P[i+2].y - P[i].y is at
// least 1e-10 too); a moving point that breaks a rule makes the shape empty
// at those instants (sor_geometry.hpp).
Sor Sor::read(const objects::ShapeArguments& a) {
    a.no_options();
    if (a.size() < 1) a.need(1, 1, "a point count and the points");
    const long long n = a.count(0, "sor's point count", -100'000'000, 100'000'000);
    if (n < 4) a.fail("Surface of revolution must have at least four points.");
    if (a.size() != static_cast<std::size_t>(n) + 1)
        a.fail("sor says it has " + std::to_string(n) + " points but lists " +
               std::to_string(a.size() - 1));
    Sor sor;
    sor.points.reserve(static_cast<std::size_t>(n));
    auto known = [](const TimeFunction& f) { return f.is_constant(); };
    for (std::size_t i = 1; i < a.size(); ++i) {
        sor.points.push_back(a.vector2(i, "a sor point"));
        const std::size_t k = i - 1;  // POV-Ray's index
        const auto& p = sor.points.back().c;
        if (known(p[0]) && p[0].constant() < 0.0)
            a.fail("Incorrect point in surface of revolution.");
        if (k > 1 && k < static_cast<std::size_t>(n) - 1) {
            const auto& before = sor.points[k - 1].c;
            if (known(p[1]) && known(before[1]) && p[1].constant() <= before[1].constant())
                a.fail("Incorrect point in surface of revolution.");
        }
    }
    for (std::size_t i = 0; i + 3 < sor.points.size(); ++i) {
        const auto y = [&](std::size_t j) -> const TimeFunction& { return sor.points[j].c[1]; };
        for (const std::size_t j : {i, i + 1}) {
            if (known(y(j)) && known(y(j + 2)) &&
                std::fabs(y(j + 2).constant() - y(j).constant()) < 1e-10)
                a.fail("Incorrect point in surface of revolution.");
        }
    }
    return sor;
}

}  // namespace hexant::runtime
