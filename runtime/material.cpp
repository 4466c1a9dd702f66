#include "runtime/material.hpp"

namespace hexant::runtime {

bool ColourMap::depends_on_time() const {
    for (const auto& e : entries)
        if (e.value.depends_on_time() || e.colour.depends_on_time()) return true;
    return false;
}

bool Pigment::depends_on_time() const {
    if (pattern == Pattern::Solid) return colours.front().depends_on_time();
    if (pattern == Pattern::Unsupported) return false;
    if (patterned.depends_on_time() || colour_map.depends_on_time() || transform.depends_on_time()) return true;
    for (const auto& e : pigment_map)
        if (e.value.depends_on_time() || e.pigment->depends_on_time()) return true;
    return false;
}

bool Normal::depends_on_time() const {
    return patterned.depends_on_time() || amount.depends_on_time() || accuracy.depends_on_time() ||
           transform.depends_on_time();
}

}  // namespace hexant::runtime
