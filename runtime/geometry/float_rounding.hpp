// Doubles to floats rounded outward, for bounds stored in single precision
// (a time sweep's boxes, a wide box tree's children): the float returned
// never lies on the wrong side of the double it stands for.
#pragma once

#include <cmath>
#include <limits>

namespace hexant::runtime::geometry {

// The float at or above x (+infinity past the floats' range or for NaN,
// which makes a bound read "anywhere").
inline float float_up(double x) {
    if (!(x <= double(std::numeric_limits<float>::max())))
        return std::numeric_limits<float>::infinity();
    // Below the floats' range (a conversion there is undefined): the lowest float is above x.
    if (x < -double(std::numeric_limits<float>::max())) return -std::numeric_limits<float>::max();
    float f = float(x);
    if (double(f) < x) f = std::nextafter(f, std::numeric_limits<float>::infinity());
    return f;
}

// The float at or below x (-infinity past the floats' range or for NaN).
inline float float_down(double x) {
    return -float_up(-x);
}

}  // namespace hexant::runtime::geometry
