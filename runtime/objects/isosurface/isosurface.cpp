#include "runtime/objects/isosurface/isosurface.hpp"

#include <cmath>
#include <string>

namespace hexant::runtime {

namespace {

// A setting that must be a positive finite constant (accuracy, max_gradient).
double positive_setting(const objects::ShapeArguments& value, const std::string& name) {
    value.need(1, 1, "a number");
    const double x = value.constant(0, "isosurface's " + name);
    if (!(x > 0.0) || !std::isfinite(x))
        value.fail("an isosurface's " + name + " must be a positive number, not " +
                   std::to_string(x));
    return x;
}

}  // namespace

void Isosurface::set(std::string_view setting, const objects::ShapeArguments& value) {
    if (setting == "threshold") {
        value.need(1, 1, "a threshold");
        threshold = value.number(0, "isosurface's threshold");
    } else if (setting == "accuracy") {
        accuracy = positive_setting(value, "accuracy");
    } else if (setting == "open") {
        open = objects::flag(value);
    } else if (setting == "max_gradient") {
        max_gradient = positive_setting(value, "max_gradient");
    } else if (setting == "max_trace") {
        // POV-Ray's search needs it; hexant's search finds every hit.
        value.need(1, 1, "a number");
        (void)value.constant(0, "isosurface's " + std::string(setting));
    } else if (setting == "all_intersections") {
        value.need(0, 0, "no value");
    }
}

}  // namespace hexant::runtime
