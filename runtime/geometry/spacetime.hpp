// Events, rays and boxes in 4D spacetime (x, y, z, t), after Glassner's
// "Spacetime ray tracing for animation" (IEEE CG&A, 1988). They live in the
// runtime because an intelligent object's bound() and intersect() speak them;
// the tracer builds its hierarchy of Box4 cells from them.
#pragma once

#include <algorithm>
#include <limits>

#include <glm/vec4.hpp>

#include "runtime/time/interval.hpp"

namespace hexant::runtime {

// A point of spacetime: where (x, y, z) and when (w).
using Event = glm::dvec4;

// A 4D ray: events origin + s direction. A ray with direction.w = 0 lives at
// one instant (infinite speed of light); a non-zero w makes time run along it.
struct Ray4 {
    Event origin{0.0};
    Event direction{0.0};

    Event at(double s) const { return origin + s * direction; }
};

// An axis-aligned box of spacetime, closed. An empty box has some lo > hi.
struct Box4 {
    Event lo{std::numeric_limits<double>::infinity()};
    Event hi{-std::numeric_limits<double>::infinity()};

    static Box4 empty() { return {}; }
    static Box4 of_point(const Event& e) { return {e, e}; }

    bool is_empty() const {
        for (int i = 0; i < 4; ++i)
            if (!(lo[i] <= hi[i])) return true;
        return false;
    }
    bool contains(const Event& e) const {
        for (int i = 0; i < 4; ++i)
            if (!(lo[i] <= e[i] && e[i] <= hi[i])) return false;
        return true;
    }
    void extend(const Event& e) {
        for (int i = 0; i < 4; ++i) {
            lo[i] = std::min(lo[i], e[i]);
            hi[i] = std::max(hi[i], e[i]);
        }
    }
    void extend(const Box4& b) {
        if (b.is_empty()) return;
        extend(b.lo);
        extend(b.hi);
    }
    Box4 intersection(const Box4& b) const {
        Box4 r;
        for (int i = 0; i < 4; ++i) {
            r.lo[i] = std::max(lo[i], b.lo[i]);
            r.hi[i] = std::min(hi[i], b.hi[i]);
        }
        return r;
    }
    Event extent() const { return is_empty() ? Event(0.0) : hi - lo; }
    // Halves first, so that huge ends do not overflow.
    Event center() const { return 0.5 * lo + 0.5 * hi; }
    // The 4D volume (0 for an empty or flat box).
    double volume() const {
        if (is_empty()) return 0.0;
        const Event e = hi - lo;
        return e.x * e.y * e.z * e.w;
    }
    Interval time() const { return {lo.w, hi.w}; }

    // One of the 16 cells of halving every axis: bit 0 picks the upper half
    // in x, bit 1 in y, bit 2 in z, bit 3 in t.
    Box4 child(int index) const {
        const Event m = center();
        Box4 c;
        for (int i = 0; i < 4; ++i) {
            const bool upper = (index >> i) & 1;
            c.lo[i] = upper ? m[i] : lo[i];
            c.hi[i] = upper ? hi[i] : m[i];
        }
        return c;
    }
};

}  // namespace hexant::runtime
