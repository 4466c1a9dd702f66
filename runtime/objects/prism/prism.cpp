#include "runtime/objects/prism/prism.hpp"

#include <string>

namespace hexant::runtime {

Prism Prism::read(const objects::ShapeArguments& a) {
    // The last sweep and the last spline written count (POV-Ray's parser
    // reads them in any order and keeps the last of each).
    std::string sweep = "linear_sweep", spline = "linear_spline";
    for (const auto& word : a.options())
        (word.find("sweep") != std::string::npos ? sweep : spline) = word;
    Prism prism;
    if (a.size() < 3) a.need(3, 3, "two heights, a point count and the points");
    prism.height1 = a.number(0, "prism's first height");
    prism.height2 = a.number(1, "prism's second height");
    if (sweep != "linear_sweep" || spline != "linear_spline") {
        prism.lacking = "prism with " + sweep + " and " + spline;
        return prism;
    }
    const long long n = a.count(2, "prism's point count", 3, 100'000'000);
    if (a.size() != static_cast<std::size_t>(n) + 3)
        a.fail("prism says it has " + std::to_string(n) + " points but lists " +
               std::to_string(a.size() - 3));
    prism.points.reserve(a.size() - 3);
    for (std::size_t i = 3; i < a.size(); ++i)
        prism.points.push_back(a.vector2(i, "a prism point"));
    return prism;
}

}  // namespace hexant::runtime
