#include "runtime/bounds/time_sweep.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>

#include "runtime/bounds/swept_bound.hpp"

namespace hexant::runtime {

namespace {

constexpr std::uint16_t kTop = 65535;

// The float at or above x (+infinity past the floats' range or for NaN,
// which makes a chord's box infinite: the cached piece is kept).
float float_up(double x) {
    if (!(x <= double(std::numeric_limits<float>::max())))
        return std::numeric_limits<float>::infinity();
    // Below the floats' range (a conversion there is undefined): the lowest float is above x.
    if (x < -double(std::numeric_limits<float>::max())) return -std::numeric_limits<float>::max();
    float f = float(x);
    if (double(f) < x) f = std::nextafter(f, std::numeric_limits<float>::infinity());
    return f;
}

// A placed box that gives no chord edge: empty, or not finite.
bool no_chord_end(const Box4& b) {
    if (b.is_empty()) return true;
    for (int a = 0; a < 3; ++a)
        if (!std::isfinite(b.lo[a]) || !std::isfinite(b.hi[a])) return true;
    return false;
}

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

Box4 TimeSweep::whole() const {
    if (empty()) return Box4::empty();
    return {Event(lo_, time_.lo), Event(hi_, time_.hi)};
}

std::size_t TimeSweep::step_count() const {
    const std::size_t n = piece_count();
    switch (layout_) {
        case Layout::Whole:
            return 0;
        case Layout::Still:
            return 6 * n;
        case Layout::Shared:
            return 6 * (n + 1);
        case Layout::Separate:
            return 12 * n;
    }
    return 0;
}

double TimeSweep::decode(int axis, std::uint16_t q) const {
    if (q == 0) return lo_[axis];
    if (q == kTop) return hi_[axis];
    // One step is the extent / kTop, computed the same way at every call.
    const double step = (hi_[axis] - lo_[axis]) / double(kTop);
    return std::min(lo_[axis] + double(q) * step, hi_[axis]);
}

namespace {

// A count of steps as an int in [0, kTop], clamped while still a double: a
// tiny extent makes the scale infinite, and 0 times it (v at the low end)
// is NaN, which no int holds (undefined behaviour, found by UBSan on a floor
// of huge triangles); NaN gives `otherwise`, the conservative end.
int steps_at(double steps, int otherwise) {
    if (std::isnan(steps)) return otherwise;
    return int(std::clamp(steps, 0.0, double(kTop)));
}

}  // namespace

// A step at or below v (v inside the whole box), checked on the decoded value.
std::uint16_t TimeSweep::encode_down(int k, double v) const {
    const double extent = hi_[k] - lo_[k];
    if (!(extent > 0.0) || !std::isfinite(extent)) return 0;
    int q = steps_at(std::floor((v - lo_[k]) * (double(kTop) / extent)), 0);
    while (q > 0 && decode(k, std::uint16_t(q)) > v) --q;
    return std::uint16_t(q);
}

std::uint16_t TimeSweep::encode_up(int k, double v) const {
    const double extent = hi_[k] - lo_[k];
    if (!(extent > 0.0) || !std::isfinite(extent)) return kTop;
    int q = steps_at(std::ceil((v - lo_[k]) * (double(kTop) / extent)), int(kTop));
    while (q < int(kTop) && decode(k, std::uint16_t(q)) < v) ++q;
    return std::uint16_t(q);
}

void TimeSweep::encode_box(std::uint16_t* q, const glm::dvec3& lo, const glm::dvec3& hi) const {
    if (!(lo.x <= hi.x && lo.y <= hi.y && lo.z <= hi.z)) {
        for (int k = 0; k < 3; ++k) q[k] = kTop, q[3 + k] = 0;  // no surface
        return;
    }
    for (int k = 0; k < 3; ++k) {
        q[k] = encode_down(k, lo[k]);
        q[3 + k] = encode_up(k, hi[k]);
    }
}

void TimeSweep::encode_pieces(const std::vector<MovingBox>& level) {
    const std::size_t n = level.size();
    bool still = true, some_empty = false;
    for (const MovingBox& b : level) {
        if (b.empty || b.hull().is_empty())
            some_empty = true;
        else if (b.lo0 != b.lo1 || b.hi0 != b.hi1)
            still = false;
    }
    // One box held still over the whole time needs no pieces.
    layout_ = depth_ == 0 && still ? Layout::Whole
              : still              ? Layout::Still
              : some_empty         ? Layout::Separate
                                   : Layout::Shared;
    if (layout_ == Layout::Whole) return;
    steps_ = std::make_unique<std::uint16_t[]>(step_count());
    std::uint16_t* q = steps_.get();
    const glm::dvec3 none_lo(std::numeric_limits<double>::infinity()), none_hi(-none_lo);
    switch (layout_) {
        case Layout::Still:
            for (const MovingBox& b : level) {
                const bool none = b.empty || b.hull().is_empty();
                encode_box(q, none ? none_lo : b.lo0, none ? none_hi : b.hi0);
                q += 6;
            }
            break;
        case Layout::Shared:
            // The box at cut i holds the ends of both pieces that meet there.
            for (std::size_t i = 0; i <= n; ++i) {
                const MovingBox& before = level[i > 0 ? i - 1 : 0];
                const MovingBox& after = level[i < n ? i : n - 1];
                const glm::dvec3 lo = i == 0   ? after.lo0
                                      : i == n ? before.lo1
                                               : glm::min(before.lo1, after.lo0);
                const glm::dvec3 hi = i == 0   ? after.hi0
                                      : i == n ? before.hi1
                                               : glm::max(before.hi1, after.hi0);
                encode_box(q, lo, hi);
                q += 6;
            }
            break;
        case Layout::Separate:
            for (const MovingBox& b : level) {
                if (b.empty || b.hull().is_empty()) {
                    encode_box(q, none_lo, none_hi);
                    encode_box(q + 6, none_lo, none_hi);
                } else {
                    encode_box(q, b.lo0, b.hi0);
                    encode_box(q + 6, b.lo1, b.hi1);
                }
                q += 12;
            }
            break;
        case Layout::Whole:
            break;
    }
}

MovingBox TimeSweep::moving_piece(std::size_t i) const {
    const Interval t = piece_time(i);
    if (layout_ == Layout::Whole) return MovingBox::constant(whole(), t);
    // The steps of the piece's start and end boxes (lo xyz, hi xyz each).
    const std::uint16_t* start = nullptr;
    const std::uint16_t* end = nullptr;
    switch (layout_) {
        case Layout::Still:
            start = end = &steps_[6 * i];
            break;
        case Layout::Shared:
            start = &steps_[6 * i], end = start + 6;
            break;
        case Layout::Separate:
            start = &steps_[12 * i], end = start + 6;
            break;
        case Layout::Whole:
            break;
    }
    MovingBox m;
    m.time = t;
    if (start[0] > start[3] && end[0] > end[3]) return m;  // no surface (lo > hi at both ends)
    m.empty = false;
    for (int k = 0; k < 3; ++k) {
        m.lo0[k] = decode(k, start[k]);
        m.lo1[k] = decode(k, end[k]);
        m.hi0[k] = decode(k, start[3 + k]);
        m.hi1[k] = decode(k, end[3 + k]);
    }
    return m;
}

Box4 TimeSweep::piece(std::size_t i) const {
    const Interval t = piece_time(i);
    if (layout_ == Layout::Whole) {
        Box4 b = whole();
        b.lo.w = t.lo;
        b.hi.w = t.hi;
        return b;
    }
    return moving_piece(i).hull();
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
    if (layout_ == Layout::Whole) {
        box = whole();
    } else if (level >= depth_) {
        // A part of one piece: its moving box over that part.
        box = moving_piece(std::size_t(index >> (level - depth_))).box_over(t);
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

bool TimeSweep::cached_edges(int level, std::uint64_t first, std::size_t count, glm::dvec3* edge_lo,
                             glm::dvec3* edge_hi) const {
    if (empty() || count == 0) return false;
    if (layout_ == Layout::Whole) {
        for (std::size_t j = 0; j <= count; ++j) edge_lo[j] = lo_, edge_hi[j] = hi_;
        return true;
    }
    if (level < depth_) return false;
    const int finer = level - depth_;
    // The last two pieces decoded (a cut between two has both sides').
    std::size_t decoded[2] = {piece_count(), piece_count()};
    MovingBox pieces[2];
    const auto piece = [&](std::size_t p) -> const MovingBox& {
        for (int i = 0; i < 2; ++i)
            if (decoded[i] == p) return pieces[i];
        decoded[0] = decoded[1];
        pieces[0] = pieces[1];
        decoded[1] = p;
        pieces[1] = moving_piece(p);
        return pieces[1];
    };
    for (std::size_t j = 0; j <= count; ++j) {
        const std::uint64_t cut = first + j;
        const double t = dyadic_time(time_, level, cut);
        glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-lo);
        // The pieces of the bins on either side of the cut (within range).
        for (const bool before : {true, false}) {
            if (before ? j == 0 : j == count) continue;
            const std::uint64_t bin = before ? cut - 1 : cut;
            const MovingBox& m = piece(std::size_t(bin >> finer));
            const Box4 at = m.box_over(Interval(t, t));
            if (at.is_empty()) return false;
            for (int a = 0; a < 3; ++a) {
                lo[a] = std::min(lo[a], at.lo[a]);
                hi[a] = std::max(hi[a], at.hi[a]);
            }
        }
        edge_lo[j] = lo;
        edge_hi[j] = hi;
    }
    return true;
}

bool TimeSweep::boxes_over_dyadic(int level, std::uint64_t first, std::size_t count,
                                  const IntelligentObject& object, Box4* out, glm::dvec3* edge_lo,
                                  glm::dvec3* edge_hi) const {
    if (!empty() && layout_ != Layout::Whole && level >= depth_) {
        // Pieces inside cached ones: each cached piece decoded once (a
        // leaf's eight bins mostly lie in one).
        const int finer = level - depth_;
        std::size_t decoded = piece_count();
        MovingBox m;
        for (std::size_t k = 0; k < count; ++k) {
            const std::size_t p = std::size_t((first + k) >> finer);
            if (p != decoded) m = moving_piece(decoded = p);
            out[k] = m.box_over(Interval(dyadic_time(time_, level, first + k),
                                         dyadic_time(time_, level, first + k + 1)));
        }
    } else {
        for (std::size_t k = 0; k < count; ++k) out[k] = box_over_dyadic(level, first + k);
    }
    const bool want_edges = edge_lo != nullptr && edge_hi != nullptr;
    // (Chords the pricing left out are made for bounds, which ask for
    // edges; the cost criterion, which asks for boxes, prices from the
    // cache as before.)
    const bool refine = refines_ || (finer_chords_ && want_edges);
    if (!refine || level <= depth_ || empty() || count == 0)
        return want_edges && cached_edges(level, first, count, edge_lo, edge_hi);
    // The chord's error over one piece of this level (its length rounded up).
    const double length = interval_detail::next_up(dyadic_time(time_, level, first + 1) -
                                                   dyadic_time(time_, level, first));
    double out_by[3];
    for (int a = 0; a < 3; ++a)
        out_by[a] = interval_detail::up(
            length * length * 0.125 * double(acceleration_[a]) + double(margin_[a]), 4);
    // The placed box at a cut, moved out by the chord's error: the chord
    // between two of them holds the object over the piece between.
    const auto widened = [&](const Box4& placed, glm::dvec3& lo, glm::dvec3& hi) {
        for (int a = 0; a < 3; ++a) {
            lo[a] = interval_detail::next_down(placed.lo[a] - out_by[a]);
            hi[a] = interval_detail::next_up(placed.hi[a] + out_by[a]);
        }
    };
    // The chords' edges are written in place of the cached ones; should a
    // placed box be missing or not finite, the cached ones are made again.
    Box4 start = object.placed_box_at(dyadic_time(time_, level, first));
    bool chords = want_edges && !no_chord_end(start);
    if (chords) widened(start, edge_lo[0], edge_hi[0]);
    for (std::size_t k = 0; k < count; ++k) {
        const Box4 end = object.placed_box_at(dyadic_time(time_, level, first + k + 1));
        if (!start.is_empty() && !end.is_empty() && !out[k].is_empty()) {
            Box4 chord = start;
            chord.extend(end);
            for (int a = 0; a < 3; ++a) {
                chord.lo[a] = interval_detail::next_down(chord.lo[a] - out_by[a]);
                chord.hi[a] = interval_detail::next_up(chord.hi[a] + out_by[a]);
            }
            chord.lo.w = out[k].lo.w;
            chord.hi.w = out[k].hi.w;
            const Box4 both = chord.intersection(out[k]);
            if (!both.is_empty()) out[k] = both;
        }
        chords = chords && !no_chord_end(end);
        if (chords) widened(end, edge_lo[k + 1], edge_hi[k + 1]);
        start = end;
    }
    if (chords) return true;
    return want_edges && cached_edges(level, first, count, edge_lo, edge_hi);
}

Box4 TimeSweep::box_over(const Interval& t) const {
    const Interval clipped(std::max(t.lo, time_.lo), std::min(t.hi, time_.hi));
    if (empty() || clipped.is_empty()) return Box4::empty();
    Box4 box = Box4::empty();
    if (layout_ == Layout::Whole) {
        box = whole();
    } else {
        std::size_t first, last;
        pieces_meeting(clipped, first, last);
        for (std::size_t i = first; i <= last && first <= last; ++i)
            box.extend(moving_piece(i).box_over(clipped));
        if (box.is_empty()) return box;
    }
    box.lo.w = clipped.lo;
    box.hi.w = clipped.hi;
    return box;
}

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
    sweep.lo_ = glm::dvec3(whole.lo);
    sweep.hi_ = glm::dvec3(whole.hi);
    sweep.encode_pieces(level);
    return sweep;
}

}  // namespace hexant::runtime
