// An object's bins (linear_bound.hpp, TimeBins) packed to 16 bits a
// coordinate, for the leaf builder to keep beside each object while it
// groups a large leaf: 98 bytes instead of 196, so that a leaf of 10^5
// objects holds its bins in 10 MB, not 20, and none is computed twice.
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
    // Per bin: lower x, y, z, then upper x, y, z.
    std::array<std::array<std::uint16_t, 6>, kMaxBins> q{};
    std::uint8_t count = 0;
    std::uint8_t empty = 0;  // bit b: bin b holds nothing

    static constexpr int kTop = 65535;

    // `hull` must hold every bin (TimeBins::hull()).
    static PackedBins pack(const TimeBins& bins, const BinBox& hull) {
        PackedBins p;
        p.count = static_cast<std::uint8_t>(bins.count);
        for (int b = 0; b < bins.count; ++b) {
            if (bins.bin[b].is_empty()) {
                p.empty |= static_cast<std::uint8_t>(1u << b);
                continue;
            }
            for (int a = 0; a < 3; ++a) {
                const Axis axis(hull, a);
                p.q[b][a] = axis.down(bins.bin[b].lo[a]);
                p.q[b][3 + a] = axis.up(bins.bin[b].hi[a]);
            }
        }
        return p;
    }

    // Bins that hold the packed ones (the same `hull` as pack's).
    TimeBins unpack(const BinBox& hull) const {
        TimeBins bins = TimeBins::empty(count);
        for (int b = 0; b < count; ++b) {
            if (empty & (1u << b)) continue;
            for (int a = 0; a < 3; ++a) {
                const Axis axis(hull, a);
                bins.bin[b].lo[a] = float_down(axis.decode(q[b][a]));
                bins.bin[b].hi[a] = float_up(axis.decode(q[b][3 + a]));
            }
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
