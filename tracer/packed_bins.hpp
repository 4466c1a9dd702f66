// An object's bins (linear_bound.hpp, TimeBins) packed to 16 bits a
// coordinate, for the leaf builder to keep beside each object while it
// groups a large leaf: 112 bytes instead of 412, so that a leaf of 10^5
// objects holds its bins in 11 MB, not 41, and none is computed twice.
//
// Each coordinate is a step of 1/65535 of the object's own hull (the box
// over its bins, the item's box), the lower ends rounded down and the
// upper ends up, each checked on the decoded value, and decoded through
// the same function; back in floats they are rounded outward again
// (float_down, float_up). So every unpacked bin holds its original, and is
// wider by at most 1/65535 of the hull per side (plus a float's rounding).
// An axis whose hull is not finite keeps the hull's ends: wider, never
// narrower.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>

#include "tracer/bound_rounding.hpp"
#include "tracer/linear_bound.hpp"

namespace hexant::tracer {

struct PackedBins {
    // Per bin: lower x, y, z, then upper x, y, z; where lined, per edge
    // (count + 1 rows) instead, the bins then being the boxes between
    // neighbouring edges (TimeBins's lines hold the contents; their boxes
    // over each bin hold them too).
    std::array<std::array<std::uint16_t, 6>, kMaxBins + 1> q{};
    std::uint8_t count = 0;
    std::uint8_t empty = 0;  // bit b: bin b holds nothing
    bool lined = false;

    static constexpr int kTop = 65535;

    // `hull` must hold every bin, and every edge where lined
    // (TimeBins::frame()).
    static PackedBins pack(const TimeBins& bins, const BinBox& hull) {
        PackedBins p;
        p.count = static_cast<std::uint8_t>(bins.count);
        p.lined = bins.lines();
        for (int b = 0; b < bins.count; ++b)
            if (bins.bin[b].is_empty()) p.empty |= static_cast<std::uint8_t>(1u << b);
        const int rows = p.lined ? bins.count + 1 : bins.count;
        for (int r = 0; r < rows; ++r) {
            const BinBox& box = p.lined ? bins.edge[r] : bins.bin[r];
            if (!p.lined && box.is_empty()) continue;
            for (int a = 0; a < 3; ++a) {
                const Axis axis(hull, a);
                p.q[r][a] = axis.down(box.lo[a]);
                p.q[r][3 + a] = axis.up(box.hi[a]);
            }
        }
        return p;
    }

    // Bins that hold the packed ones (the same `hull` as pack's); where
    // lined, each bin's box is its edges' clipped to `region` (the cell's,
    // which the packed bins were clipped to).
    TimeBins unpack(const BinBox& hull, const runtime::Box4& region) const {
        TimeBins bins = TimeBins::empty(count);
        bins.lined = lined;
        const auto decode = [&](int r, BinBox& box) {
            for (int a = 0; a < 3; ++a) {
                const Axis axis(hull, a);
                box.lo[a] = float_down(axis.decode(q[r][a]));
                box.hi[a] = float_up(axis.decode(q[r][3 + a]));
            }
        };
        if (lined)
            for (int r = 0; r <= count; ++r) decode(r, bins.edge[r]);
        for (int b = 0; b < count; ++b) {
            if (empty & (1u << b)) continue;
            if (!lined) {
                decode(b, bins.bin[b]);
                continue;
            }
            BinBox box = bins.edge[b];
            box.extend(bins.edge[b + 1]);
            const BinBox inside = box.clipped(region);
            // (Empty only through rounding at a face: the box then.)
            bins.bin[b] = inside.is_empty() ? box : inside;
        }
        return bins;
    }

  private:
    // One axis of the hull, cut into kTop steps.
    struct Axis {
        double lo, hi, step;
        Axis(const BinBox& hull, int a)
            : lo(hull.lo[a]), hi(hull.hi[a]), step((double(hull.hi[a]) - hull.lo[a]) / kTop) {}
        bool usable() const { return std::isfinite(step) && step > 0.0; }
        double decode(int s) const {
            return s == 0 ? lo : s == kTop || !usable() ? hi : lo + s * step;
        }
        std::uint16_t down(float v) const {
            if (!usable()) return 0;
            int s = static_cast<int>(std::clamp(std::floor((v - lo) / step), 0.0, double(kTop)));
            while (s > 0 && decode(s) > v) --s;
            return static_cast<std::uint16_t>(s);
        }
        std::uint16_t up(float v) const {
            if (!usable()) return kTop;
            int s = static_cast<int>(std::clamp(std::ceil((v - lo) / step), 0.0, double(kTop)));
            while (s < kTop && decode(s) < v) ++s;
            return static_cast<std::uint16_t>(s);
        }
    };
};

}  // namespace hexant::tracer
