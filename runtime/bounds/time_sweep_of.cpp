// Making an object's sweep (time_sweep.hpp): its pieces by chords or by
// interval boxes, merged back where finer ones do not pay, then stored.
#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <vector>

#include "runtime/bounds/swept_bound.hpp"
#include "runtime/bounds/time_sweep.hpp"
#include "runtime/bounds/time_sweep_detail.hpp"

namespace hexant::runtime {

namespace {

using time_sweep_detail::float_up;
using time_sweep_detail::largest_extent;

}  // namespace

namespace {

// The largest extent of a moving box at any instant of its piece (its
// widths are linear in time: largest at an end).
double largest_instant_extent(const MovingBox& m) {
    if (m.empty) return 0.0;
    double e = 0.0;
    for (int k = 0; k < 3; ++k) e = std::max({e, m.hi0[k] - m.lo0[k], m.hi1[k] - m.lo1[k]});
    return e;
}

// One moving box over two consecutive pieces a, b (a's end is b's start):
// per side the line through the outer ends, moved outward by what the
// inner ends need (the sides are lines, so the three ends decide).
MovingBox merged(const MovingBox& a, const MovingBox& b) {
    if (a.empty || b.empty) {
        Box4 both = a.hull();
        both.extend(b.hull());
        return MovingBox::constant(both, Interval(a.time.lo, b.time.hi));
    }
    MovingBox m;
    m.time = Interval(a.time.lo, b.time.hi);
    m.empty = false;
    const double span = m.time.hi - m.time.lo;
    const double u = span > 0.0 ? (a.time.hi - a.time.lo) / span : 0.5;
    for (int k = 0; k < 3; ++k) {
        m.lo0[k] = a.lo0[k];
        m.lo1[k] = b.lo1[k];
        const double lo_mid = std::min(a.lo1[k], b.lo0[k]);
        const double lo_line = m.lo0[k] + u * (m.lo1[k] - m.lo0[k]);
        const double lo_shift = std::max(0.0, lo_line - lo_mid);
        m.hi0[k] = a.hi0[k];
        m.hi1[k] = b.hi1[k];
        const double hi_mid = std::max(a.hi1[k], b.hi0[k]);
        const double hi_line = m.hi0[k] + u * (m.hi1[k] - m.hi0[k]);
        const double hi_shift = std::max(0.0, hi_mid - hi_line);
        // The shift, and the interpolation's rounding, paid outward.
        const double lo_slack =
            MovingBox::kSlack *
            std::max({std::fabs(m.lo0[k]), std::fabs(m.lo1[k]), std::fabs(lo_mid)});
        const double hi_slack =
            MovingBox::kSlack *
            std::max({std::fabs(m.hi0[k]), std::fabs(m.hi1[k]), std::fabs(hi_mid)});
        m.lo0[k] -= lo_shift + lo_slack;
        m.lo1[k] -= lo_shift + lo_slack;
        m.hi0[k] += hi_shift + hi_slack;
        m.hi1[k] += hi_shift + hi_slack;
    }
    // Never looser than the two pieces' boxes held still.
    Box4 both = a.hull();
    both.extend(b.hull());
    m.tighten(MovingBox::constant(both, m.time));
    return m;
}

}  // namespace

namespace {

// Pieces by chords (IntelligentObject::chord_bound_over): halve while a
// piece's box at some instant exceeds the growth over the object's size
// and, with pricing, the object tests saved pay for the new ends. Each
// piece is the line between the placed boxes at its ends, moved out by the
// chord's error (its length squared / 8 times the acceleration bound) and
// the margin; one jet over the whole range bounds the acceleration (a jet
// per coarse piece would be tighter where the motion is uneven, and costs
// as much as forty ends). Returns the depth and fills `level`; `capped`
// when max_depth stopped it.
int chord_pieces(const IntelligentObject& object, const Interval& time, int max_depth,
                 const SweepPricing& pricing, const IntelligentObject::ChordBound& whole,
                 double size, std::vector<MovingBox>& level, bool& capped) {
    const double width = time.hi - time.lo;
    const double a = std::max({whole.acceleration.x, whole.acceleration.y, whole.acceleration.z});
    const double m = std::max({whole.margin.x, whole.margin.y, whole.margin.z});
    const double allowed = 0.5 * (kSweptBoundGrowth - 1.0) * size - m;
    const auto chord_error = [&](int d) {
        const double w = width / double(std::size_t(1) << d);
        return w * w * 0.125 * a;
    };
    int depth = 0;
    while (depth < max_depth && !(chord_error(depth) <= allowed)) {
        if (pricing.ray_density > 0.0) {
            // A box of the object's size, widened on every side.
            const auto area = [&](double e) {
                return 6.0 * (size + 2.0 * (e + m)) * (size + 2.0 * (e + m));
            };
            const double saved = pricing.ray_density * width *
                                 (area(chord_error(depth)) - area(chord_error(depth + 1)));
            if (saved * pricing.object_cost < pricing.point_cost * double(std::size_t(1) << depth))
                break;
        }
        ++depth;
    }
    // Stopped by the depth limit (memory), not by tightness or price: finer
    // pieces would still pay, so the sweep refines on request.
    capped = depth == max_depth && !(chord_error(depth) <= allowed);
    const std::size_t n = std::size_t(1) << depth;
    std::vector<Box4> ends(n + 1);
    for (std::size_t i = 0; i <= n; ++i)
        ends[i] = object.placed_box_at(dyadic_time(time, depth, i));
    level.assign(n, MovingBox{});
    for (std::size_t i = 0; i < n; ++i) {
        const Interval t(dyadic_time(time, depth, i), dyadic_time(time, depth, i + 1));
        const IntelligentObject::ChordBound& b = whole;
        MovingBox& piece = level[i];
        piece.time = t;
        if (ends[i].is_empty() || ends[i + 1].is_empty()) {
            piece = MovingBox::constant(object.box_over(t), t);
            continue;
        }
        piece.empty = false;
        // The piece's length rounded up (t.hi - t.lo exactly is at most it).
        const double w = interval_detail::next_up(t.hi - t.lo);
        for (int k = 0; k < 3; ++k) {
            const double out =
                interval_detail::up(w * w * 0.125 * b.acceleration[k] + b.margin[k], 4);
            piece.lo0[k] = interval_detail::next_down(ends[i].lo[k] - out);
            piece.lo1[k] = interval_detail::next_down(ends[i + 1].lo[k] - out);
            piece.hi0[k] = interval_detail::next_up(ends[i].hi[k] + out);
            piece.hi1[k] = interval_detail::next_up(ends[i + 1].hi[k] + out);
        }
    }
    return depth;
}

// Pieces by interval boxes over each piece: as many as keep a piece's box
// within the growth of the object's size, judged from its speed over three
// short probes (start, middle, end). Returns the depth and fills `level`.
int box_pieces(const IntelligentObject& object, const Interval& time, int max_depth, double size,
               std::vector<MovingBox>& level) {
    const double width = time.hi - time.lo;
    const double probe = width / double(std::size_t(1) << max_depth);
    double speed = 0.0;
    for (const double start : {time.lo, time.mid() - 0.5 * probe, time.hi - probe}) {
        const double swept = largest_extent(object.box_over(Interval(start, start + probe)));
        speed = std::max(speed, (swept - size) / probe);
    }
    const double pieces = speed * width / ((kSweptBoundGrowth - 1.0) * size);
    int depth = 0;
    while (depth < max_depth &&
           (!std::isfinite(pieces) || double(std::size_t(1) << depth) < pieces))
        ++depth;
    if (depth == 0) return 0;
    level.resize(std::size_t(1) << depth);
    for (std::size_t i = 0; i < level.size(); ++i) {
        const Interval t(dyadic_time(time, depth, i), dyadic_time(time, depth, i + 1));
        level[i] = MovingBox::constant(object.box_over(t), t);
    }
    return depth;
}

}  // namespace

TimeSweep TimeSweep::of(const IntelligentObject& object, const Interval& time, int max_depth,
                        const SweepPricing& pricing) {
    if (!(time.lo <= time.hi) || !std::isfinite(time.lo) || !std::isfinite(time.hi))
        throw std::invalid_argument("TimeSweep: the time range must be finite");
    max_depth = std::clamp(max_depth, 0, 20);
    TimeSweep sweep;
    sweep.time_ = time;
    const Box4 whole_box = object.box_over(time);
    std::vector<MovingBox> level{MovingBox::constant(whole_box, time)};
    int depth = 0;
    std::optional<IntelligentObject::ChordBound> chord;
    double size = 0.0;
    if (object.moves() && time.lo < time.hi && max_depth > 0 && !whole_box.is_empty()) {
        const double width = time.hi - time.lo;
        size = std::max(largest_extent(object.placed_box_at(time.mid())), 1e-300);
        chord = object.chord_bound_over(time);
        if (chord) {
            bool capped = false;
            depth = chord_pieces(object, time, max_depth, pricing, *chord, size, level, capped);
            if (capped) sweep.refines_ = true;
        } else
            depth = box_pieces(object, time, max_depth, size, level);
        // Then back up, merging pairs, while the coarser pieces are already
        // within the growth of the object's size, or the object tests the
        // finer ones save, for the rays expected to meet them, do not pay
        // for them. Chord pieces too are priced at an interval evaluation
        // here, not at a placement: finer pieces also make the hierarchy
        // split time finer (swarm 10^4 priced at a placement: 4.2 object
        // tests per ray instead of 7.5, but twice the references, 439 MB
        // instead of 321 at peak and the same render time).
        while (depth > 0) {
            std::vector<MovingBox> coarser(level.size() / 2);
            for (std::size_t i = 0; i < coarser.size(); ++i)
                coarser[i] = merged(level[2 * i], level[2 * i + 1]);
            bool needed = false;
            double saved = 0.0;
            const double piece_width = width / double(coarser.size());
            for (const MovingBox& b : coarser) {
                const double swept = largest_instant_extent(b);
                if (!(swept > kSweptBoundGrowth * size)) continue;
                needed = true;
                const glm::dvec4 e = b.box_over(Interval(b.time.mid())).extent();
                const double area = 2.0 * (e.x * e.y + e.y * e.z + e.z * e.x);
                saved += pricing.ray_density * area * piece_width * 0.5 * (1.0 - size / swept);
            }
            if (needed &&
                (!(pricing.ray_density > 0.0) ||
                 saved * pricing.object_cost >= pricing.evaluation_cost * double(level.size())))
                break;
            level = std::move(coarser);
            --depth;
        }
    }
    sweep.depth_ = std::uint8_t(depth);
    // Chords finer than the pieces kept, where those are looser than the
    // growth allows (the pricing stopped them, or merged them back).
    if (chord && !sweep.refines_) {
        for (const MovingBox& b : level)
            if (largest_instant_extent(b) > kSweptBoundGrowth * size) sweep.finer_chords_ = true;
    }
    if (chord && (sweep.refines_ || sweep.finer_chords_)) {
        for (int k = 0; k < 3; ++k) {
            sweep.acceleration_[k] = float_up(chord->acceleration[k]);
            sweep.margin_[k] = float_up(chord->margin[k]);
        }
    }
    Box4 whole = Box4::empty();
    for (const MovingBox& b : level) whole.extend(b.hull());
    if (whole.is_empty()) {
        sweep.depth_ = 0;
        sweep.refines_ = false;
        sweep.finer_chords_ = false;
        return sweep;
    }
    sweep.set_whole(whole);
    sweep.encode_pieces(level);
    return sweep;
}

}  // namespace hexant::runtime
