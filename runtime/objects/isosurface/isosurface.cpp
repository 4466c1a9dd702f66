#include "runtime/objects/isosurface/isosurface.hpp"

#include <cmath>

namespace hexant::runtime {

void Isosurface::set(std::string_view setting, const objects::ShapeArguments& value) {
    if (setting == "threshold") {
        value.need(1, 1, "a threshold");
        threshold = value.number(0, "isosurface's threshold");
    } else if (setting == "accuracy") {
        value.need(1, 1, "an accuracy");
        const double a = value.constant(0, "isosurface's accuracy");
        if (!(a > 0.0) || !std::isfinite(a))
            value.fail("an isosurface's accuracy must be a positive number, not " +
                       std::to_string(a));
        accuracy = a;
    } else if (setting == "open") {
        open = objects::flag(value);
    } else if (setting == "max_gradient") {
        value.need(1, 1, "a number");
        const double g = value.constant(0, "isosurface's max_gradient");
        if (!(g > 0.0) || !std::isfinite(g))
            value.fail("an isosurface's max_gradient must be a positive number, not " +
                       std::to_string(g));
        max_gradient = g;
    } else if (setting == "max_trace") {
        // POV-Ray's search needs it; hexant's search finds every hit.
        value.need(1, 1, "a number");
        (void)value.constant(0, "isosurface's " + std::string(setting));
    } else if (setting == "all_intersections") {
        value.need(0, 0, "no value");
    }
}

}  // namespace hexant::runtime
