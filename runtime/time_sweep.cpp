#include "runtime/time_sweep.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "runtime/swept_bound.hpp"

namespace hexant::runtime {

namespace {

constexpr std::uint16_t kTop = 65535;

double largest_extent(const Box4& b) {
    if (b.is_empty()) return 0.0;
    return std::max({b.hi.x - b.lo.x, b.hi.y - b.lo.y, b.hi.z - b.lo.z});
}

}  // namespace

double TimeSweep::boundary(std::size_t i) const {
    return dyadic_time(time_, depth_, i);
}

Interval TimeSweep::piece_time(std::size_t i) const {
    return {boundary(i), boundary(i + 1)};
}

double TimeSweep::decode(int axis, std::uint16_t q) const {
    if (q == 0) return whole_.lo[axis];
    if (q == kTop) return whole_.hi[axis];
    return std::min(whole_.lo[axis] + double(q) * step_[axis], whole_.hi[axis]);
}

void TimeSweep::encode(std::size_t i, const Box4& box) {
    std::uint16_t* q = &steps_[6 * i];
    if (box.is_empty()) {
        for (int k = 0; k < 3; ++k) q[k] = kTop, q[3 + k] = 0;  // lo > hi: no surface
        return;
    }
    for (int k = 0; k < 3; ++k) {
        const double extent = whole_.hi[k] - whole_.lo[k];
        int lo = 0, hi = kTop;
        if (extent > 0.0 && std::isfinite(extent)) {
            const double scale = double(kTop) / extent;
            lo = std::clamp(int(std::floor((box.lo[k] - whole_.lo[k]) * scale)), 0, int(kTop));
            hi = std::clamp(int(std::ceil((box.hi[k] - whole_.lo[k]) * scale)), 0, int(kTop));
        }
        // Outward on the values decode() gives back, whatever the rounding.
        while (lo > 0 && decode(k, std::uint16_t(lo)) > box.lo[k]) --lo;
        while (hi < int(kTop) && decode(k, std::uint16_t(hi)) < box.hi[k]) ++hi;
        if (lo > hi) lo = 0, hi = kTop;  // only if decode were not monotone
        q[k] = std::uint16_t(lo);
        q[3 + k] = std::uint16_t(hi);
    }
}

Box4 TimeSweep::piece(std::size_t i) const {
    const Interval t = piece_time(i);
    if (depth_ == 0) {
        Box4 b = whole_;
        b.lo.w = t.lo;
        b.hi.w = t.hi;
        return b;
    }
    const std::uint16_t* q = &steps_[6 * i];
    if (q[0] > q[3]) return Box4::empty();
    Box4 b;
    for (int k = 0; k < 3; ++k) {
        b.lo[k] = decode(k, q[k]);
        b.hi[k] = decode(k, q[3 + k]);
    }
    b.lo.w = t.lo;
    b.hi.w = t.hi;
    return b;
}

void TimeSweep::pieces_meeting(const Interval& t, std::size_t& first, std::size_t& last) const {
    first = 1;
    last = 0;
    if (!(t.lo <= t.hi) || t.hi < time_.lo || t.lo > time_.hi) return;
    const std::size_t n = piece_count();
    const double width = time_.hi - time_.lo;
    const auto estimate = [&](double v) -> std::size_t {
        if (!(width > 0.0)) return 0;
        const double x = std::floor((v - time_.lo) / width * double(n));
        return x <= 0.0 ? 0 : std::min(n - 1, std::size_t(x));
    };
    // Piece i is [boundary(i), boundary(i + 1)], closed, so an instant on a
    // boundary lies in both neighbours and one of them is enough: the first
    // piece is the last one starting at or before t.lo, the last piece the
    // first one ending at or after t.hi. (Taking both neighbours would make
    // every cell whose time ends on a boundary look wider than its halves.)
    first = estimate(t.lo);
    while (first > 0 && boundary(first) > t.lo) --first;
    while (first + 1 < n && boundary(first + 1) <= t.lo) ++first;
    last = estimate(t.hi);
    while (last + 1 < n && boundary(last + 1) < t.hi) ++last;
    while (last > 0 && boundary(last) >= t.hi) --last;
    if (last < first) last = first;  // t is one instant on a boundary
}

Box4 TimeSweep::box_over_dyadic(int level, std::uint64_t index) const {
    const Interval t(dyadic_time(time_, level, index), dyadic_time(time_, level, index + 1));
    if (empty()) return Box4::empty();
    Box4 box = Box4::empty();
    if (depth_ == 0) {
        box = whole_;
    } else if (level >= depth_) {
        box = piece(std::size_t(index >> (level - depth_)));
    } else {
        const std::size_t count = std::size_t(1) << (depth_ - level);
        const std::size_t first = std::size_t(index) * count;
        for (std::size_t i = first; i < first + count; ++i) box.extend(piece(i));
    }
    if (box.is_empty()) return box;
    box.lo.w = t.lo;
    box.hi.w = t.hi;
    return box;
}

Box4 TimeSweep::box_over(const Interval& t) const {
    const Interval clipped(std::max(t.lo, time_.lo), std::min(t.hi, time_.hi));
    if (empty() || clipped.is_empty()) return Box4::empty();
    Box4 box = Box4::empty();
    if (depth_ == 0) {
        box = whole_;
    } else {
        std::size_t first, last;
        pieces_meeting(clipped, first, last);
        for (std::size_t i = first; i <= last && first <= last; ++i) box.extend(piece(i));
        if (box.is_empty()) return box;
    }
    box.lo.w = clipped.lo;
    box.hi.w = clipped.hi;
    return box;
}

TimeSweep TimeSweep::of(const IntelligentObject& object, const Interval& time, int max_depth,
                        const SweepPricing& pricing) {
    if (!(time.lo <= time.hi) || !std::isfinite(time.lo) || !std::isfinite(time.hi))
        throw std::invalid_argument("TimeSweep: the time range must be finite");
    max_depth = std::clamp(max_depth, 0, 20);
    TimeSweep sweep;
    sweep.time_ = time;
    std::vector<Box4> level{object.box_over(time)};
    int depth = 0;
    if (object.moves() && time.lo < time.hi && max_depth > 0 && !level.front().is_empty()) {
        // How finely to cut: the object's size at one instant, and its
        // speed measured over three short probes (start, middle, end); a
        // piece should sweep at most (kSweptBoundGrowth - 1) sizes.
        const double width = time.hi - time.lo;
        const double size = largest_extent(object.box_over(Interval(time.mid())));
        const double probe = width / double(std::size_t(1) << max_depth);
        double speed = 0.0;
        for (const double start : {time.lo, time.mid() - 0.5 * probe, time.hi - probe}) {
            const double swept = largest_extent(object.box_over(Interval(start, start + probe)));
            speed = std::max(speed, (swept - size) / probe);
        }
        const double pieces = speed * width / ((kSweptBoundGrowth - 1.0) * std::max(size, 1e-300));
        while (depth < max_depth && (!std::isfinite(pieces) || double(std::size_t(1) << depth) < pieces))
            ++depth;
        if (depth > 0) {
            sweep.depth_ = depth;
            level.resize(std::size_t(1) << depth);
            for (std::size_t i = 0; i < level.size(); ++i) level[i] = object.box_over(sweep.piece_time(i));
        }
        // Then back up, merging pairs (their union holds both), while the
        // coarser pieces are already within the growth of the object's
        // size, or the object tests the finer ones save, for the rays
        // expected to meet them, do not pay for evaluating them.
        while (depth > 0) {
            std::vector<Box4> coarser(level.size() / 2);
            for (std::size_t i = 0; i < coarser.size(); ++i) {
                coarser[i] = level[2 * i];
                coarser[i].extend(level[2 * i + 1]);
            }
            bool needed = false;
            double saved = 0.0;
            const double piece_width = width / double(coarser.size());
            for (const Box4& b : coarser) {
                const double swept = largest_extent(b);
                if (!(swept > kSweptBoundGrowth * size)) continue;
                needed = true;
                const glm::dvec4 e = b.extent();
                const double area = 2.0 * (e.x * e.y + e.y * e.z + e.z * e.x);
                saved += pricing.ray_density * area * piece_width * 0.5 * (1.0 - size / swept);
            }
            if (needed && (!(pricing.ray_density > 0.0) ||
                           saved * pricing.object_cost >= pricing.evaluation_cost * double(level.size())))
                break;
            level = std::move(coarser);
            --depth;
            sweep.depth_ = depth;
        }
    }
    sweep.depth_ = depth;
    sweep.whole_ = Box4::empty();
    for (const Box4& b : level) sweep.whole_.extend(b);
    if (sweep.whole_.is_empty()) {
        sweep.depth_ = 0;
        return sweep;
    }
    sweep.whole_.lo.w = time.lo;
    sweep.whole_.hi.w = time.hi;
    for (int k = 0; k < 3; ++k) sweep.step_[k] = (sweep.whole_.hi[k] - sweep.whole_.lo[k]) / double(kTop);
    if (depth > 0) {
        sweep.steps_.resize(6 * level.size());
        for (std::size_t i = 0; i < level.size(); ++i) sweep.encode(i, level[i]);
    }
    return sweep;
}

}  // namespace hexant::runtime
