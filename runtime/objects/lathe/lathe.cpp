#include "runtime/objects/lathe/lathe.hpp"

#include <string>

namespace hexant::runtime {

// POV-Ray 3.7's Parse_Lathe (parse.cpp): the spline words may come in any
// number, the last one counts; the count is truncated to an integer; its
// rules and messages are POV-Ray's (the cubic one says "Prism", as
// POV-Ray's does); interior points (all but the first and the last) must
// have a radius >= 0 ("Incorrect point in lathe."). A negative radius in a
// time function is not checked (it cannot be while the scene is read): the
// surface then lies at |radius|, as POV-Ray's squared equation puts it.
Lathe Lathe::read(const objects::ShapeArguments& a) {
    using geometry::LatheSpline;
    Lathe lathe;
    for (const auto& word : a.options()) {
        if (word == "linear_spline")
            lathe.spline = LatheSpline::linear;
        else if (word == "quadratic_spline")
            lathe.spline = LatheSpline::quadratic;
        else if (word == "cubic_spline")
            lathe.spline = LatheSpline::cubic;
        else if (word == "bezier_spline")
            lathe.spline = LatheSpline::bezier;
        else
            a.fail("lathe takes no '" + word + "'");
    }
    if (a.size() < 1) a.need(1, 1, "a point count and the points");
    const long long n = a.count(0, "lathe's point count", -100'000'000, 100'000'000);
    switch (lathe.spline) {
        case LatheSpline::linear:
            if (n < 2) a.fail("Lathe with linear splines must have at least two points.");
            break;
        case LatheSpline::quadratic:
            if (n < 3) a.fail("Lathe with quadratic splines must have at least three points.");
            break;
        case LatheSpline::cubic:
            if (n < 4) a.fail("Prism with cubic splines must have at least four points.");
            break;
        case LatheSpline::bezier:
            // (POV-Ray lets 0 through, and then has no segments.)
            if ((n & 3) != 0 || n <= 0)
                a.fail("Lathe with Bezier splines must have four points per segment.");
            break;
    }
    if (a.size() != static_cast<std::size_t>(n) + 1)
        a.fail("lathe says it has " + std::to_string(n) + " points but lists " +
               std::to_string(a.size() - 1));
    lathe.points.reserve(static_cast<std::size_t>(n));
    for (std::size_t i = 1; i < a.size(); ++i) {
        lathe.points.push_back(a.vector2(i, "a lathe point"));
        const bool interior = i > 1 && i < a.size() - 1;
        const TimeFunction& radius = lathe.points.back().c[0];
        if (interior && radius.is_constant() && radius.constant() < 0.0)
            a.fail("Incorrect point in lathe.");
    }
    return lathe;
}

}  // namespace hexant::runtime
