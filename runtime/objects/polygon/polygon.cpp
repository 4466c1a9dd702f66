#include "runtime/objects/polygon/polygon.hpp"

#include <string>

namespace hexant::runtime {

Polygon Polygon::read(const objects::ShapeArguments& a) {
    a.no_options();
    if (a.size() == 0) a.need(1, 1, "a point count and the points");
    const long long n = a.count(0, "polygon's point count", 3, 100'000'000);
    if (a.size() != static_cast<std::size_t>(n) + 1)
        a.fail("polygon says it has " + std::to_string(n) + " points but lists " +
               std::to_string(a.size() - 1));
    Polygon polygon;
    polygon.points.reserve(a.size() - 1);
    // A 2-vector point has z = 0 (POV-Ray pads it).
    for (std::size_t i = 1; i < a.size(); ++i)
        polygon.points.push_back(a.vector3(i, "a polygon point"));
    return polygon;
}

}  // namespace hexant::runtime
