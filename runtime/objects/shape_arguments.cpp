#include "runtime/objects/shape_arguments.hpp"

#include <cmath>
#include <cstdio>

namespace hexant::runtime::objects {

long long ShapeArguments::count(std::size_t i, const std::string& what, long long lo,
                                long long hi) const {
    const double value = constant(i, what);
    if (!(value >= static_cast<double>(lo) && value <= static_cast<double>(hi))) {
        char shown[64];
        std::snprintf(shown, sizeof shown, "%.17g", value);
        if (!std::isfinite(value)) fail(what + " must be a finite number, not " + shown);
        fail(what + " " + shown + " is out of range " + std::to_string(lo) + " to " +
             std::to_string(hi));
    }
    return static_cast<long long>(value);
}

void ShapeArguments::need(std::size_t lo, std::size_t hi, const std::string& what) const {
    if (size() < lo || size() > hi)
        fail(keyword() + " needs " + what + ", but " + std::to_string(size()) + " value" +
             (size() == 1 ? " was" : "s were") + " given");
}

void ShapeArguments::no_options() const {
    if (!options().empty()) fail(keyword() + " takes no '" + options().front() + "'");
}

}  // namespace hexant::runtime::objects
