#include "runtime/objects/prism/prism.hpp"

#include <string>

namespace hexant::runtime {

// POV-Ray 3.7's Parse_Prism (parse.cpp): the sweep and spline words may come
// in any number and order, the last of each counts; the count is truncated
// to an integer and checked per spline kind with POV-Ray's messages; a
// prism whose points POV-Ray refuses (an outline that does not close where
// its kind needs it to, prism_outline.hpp) is refused here, at its place.
// Points that move with clock cannot be checked while the scene is read:
// at an instant where POV-Ray would refuse or ignore them the prism is
// empty.
Prism Prism::read(const objects::ShapeArguments& a) {
    using geometry::PrismSpline;
    using geometry::PrismSweep;
    Prism prism;
    for (const auto& word : a.options()) {
        if (word == "linear_sweep")
            prism.sweep = PrismSweep::linear;
        else if (word == "conic_sweep")
            prism.sweep = PrismSweep::conic;
        else if (word == "linear_spline")
            prism.spline = PrismSpline::linear;
        else if (word == "quadratic_spline")
            prism.spline = PrismSpline::quadratic;
        else if (word == "cubic_spline")
            prism.spline = PrismSpline::cubic;
        else if (word == "bezier_spline")
            prism.spline = PrismSpline::bezier;
        else
            a.fail("prism takes no '" + word + "'");
    }
    if (a.size() < 3) a.need(3, 3, "two heights, a point count and the points");
    prism.height1 = a.number(0, "prism's first height");
    prism.height2 = a.number(1, "prism's second height");
    const long long n = a.count(2, "prism's point count", -100'000'000, 100'000'000);
    if (const std::string error = geometry::prism_count_error(prism.spline, n); !error.empty())
        a.fail(error);
    if (a.size() != static_cast<std::size_t>(n) + 3)
        a.fail("prism says it has " + std::to_string(n) + " points but lists " +
               std::to_string(a.size() - 3));
    prism.points.reserve(a.size() - 3);
    bool constant = true;
    for (std::size_t i = 3; i < a.size(); ++i) {
        prism.points.push_back(a.vector2(i, "a prism point"));
        for (const TimeFunction& c : prism.points.back().c) constant = constant && c.is_constant();
    }
    if (constant) {
        std::vector<glm::dvec2> points;
        points.reserve(prism.points.size());
        for (const auto& p : prism.points)
            points.emplace_back(p.c[0].constant(), p.c[1].constant());
        const geometry::PrismOutline outline = geometry::prism_outline(prism.spline, points);
        if (!outline.error.empty()) a.fail(outline.error);
    }
    return prism;
}

}  // namespace hexant::runtime
