#include "runtime/bounds/slab_bound.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace hexant::runtime {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

std::array<Event, kSlabCount> make_normals() {
    std::array<Event, kSlabCount> n{};
    for (int i = 0; i < 4; ++i) {
        n[i] = Event(0.0);
        n[i][i] = 1.0;
    }
    for (int k = 0; k < 8; ++k) {
        n[4 + k] = Event(0.5, (k & 4) ? -0.5 : 0.5, (k & 2) ? -0.5 : 0.5, (k & 1) ? -0.5 : 0.5);
    }
    return n;
}

// The range of n · e over a box, rounded outward. Each product takes the
// box end that its sign picks; the products by 0 and ±0.5 are exact (short
// of underflow, at most half the smallest subnormal each), and the three
// sums are each within half an ulp of a partial sum no larger than
// m = sum |n_i| max(|lo_i|, |hi_i|), so widening both ends by 4 ulps of m,
// plus the underflow, holds the exact range.
Interval dot_range(const Event& n, const Event& lo, const Event& hi) {
    double a = 0.0, b = 0.0, m = 0.0;
    for (int i = 0; i < 4; ++i) {
        if (n[i] > 0.0) {
            a += n[i] * lo[i];
            b += n[i] * hi[i];
        } else if (n[i] < 0.0) {
            a += n[i] * hi[i];
            b += n[i] * lo[i];
        } else {
            continue;
        }
        m += std::fabs(n[i]) * std::max(std::fabs(lo[i]), std::fabs(hi[i]));
    }
    constexpr double kUlp = std::numeric_limits<double>::epsilon();  // 2 units of roundoff
    const double e = 4.0 * kUlp * m + 4.0 * std::numeric_limits<double>::denorm_min();
    return {a - e, b + e};
}

}  // namespace

const std::array<Event, kSlabCount>& slab_normals() {
    static const std::array<Event, kSlabCount> normals = make_normals();
    return normals;
}

SlabBound SlabBound::empty() {
    SlabBound b;
    b.lo.fill(kInf);
    b.hi.fill(-kInf);
    return b;
}

SlabBound SlabBound::of_box(const Box4& box) {
    SlabBound b = empty();
    b.add(box);
    return b;
}

bool SlabBound::is_empty() const {
    for (int k = 0; k < kSlabCount; ++k)
        if (!(lo[k] <= hi[k])) return true;
    return false;
}

void SlabBound::add(const Box4& box) {
    if (box.is_empty()) return;
    const auto& normals = slab_normals();
    for (int k = 0; k < 4; ++k) {
        lo[k] = std::min(lo[k], box.lo[k]);
        hi[k] = std::max(hi[k], box.hi[k]);
    }
    for (int k = 4; k < kSlabCount; ++k) {
        const Interval r = dot_range(normals[k], box.lo, box.hi);
        lo[k] = std::min(lo[k], r.lo);
        hi[k] = std::max(hi[k], r.hi);
    }
}

void SlabBound::add(const Event& event) {
    add(Box4::of_point(event));
}

void SlabBound::add(const SlabBound& other) {
    for (int k = 0; k < kSlabCount; ++k) {
        lo[k] = std::min(lo[k], other.lo[k]);
        hi[k] = std::max(hi[k], other.hi[k]);
    }
}

void SlabBound::clip(const Box4& box) {
    const SlabBound b = of_box(box);
    for (int k = 0; k < kSlabCount; ++k) {
        lo[k] = std::max(lo[k], b.lo[k]);
        hi[k] = std::min(hi[k], b.hi[k]);
    }
}

bool SlabBound::contains(const Event& event) const {
    const auto& normals = slab_normals();
    for (int k = 0; k < kSlabCount; ++k) {
        const Interval r = dot_range(normals[k], event, event);
        if (r.hi < lo[k] || r.lo > hi[k]) return false;
    }
    return true;
}

Box4 SlabBound::box() const {
    Box4 b;
    for (int k = 0; k < 4; ++k) {
        b.lo[k] = lo[k];
        b.hi[k] = hi[k];
    }
    return b;
}

}  // namespace hexant::runtime
