#include "runtime/bounds/time_sweep.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <optional>
#include <stdexcept>

#include "runtime/bounds/swept_bound.hpp"
#include "runtime/bounds/time_sweep_detail.hpp"

namespace hexant::runtime {

namespace {

using time_sweep_detail::float_down;
using time_sweep_detail::float_up;
using time_sweep_detail::largest_extent;

constexpr std::uint16_t kTop = 65535;

// A placed box that gives no chord edge: empty, or not finite.
bool no_chord_end(const Box4& b) {
    if (b.is_empty()) return true;
    for (int a = 0; a < 3; ++a)
        if (!std::isfinite(b.lo[a]) || !std::isfinite(b.hi[a])) return true;
    return false;
}

}  // namespace

double TimeSweep::boundary(std::size_t i) const {
    return dyadic_time(time_, depth_, i);
}

Interval TimeSweep::piece_time(std::size_t i) const {
    return {boundary(i), boundary(i + 1)};
}

double TimeSweep::whole_lo(int k) const {
    if (!wide_) return lo_[k];
    double v;
    std::memcpy(&v, steps_.get() + k * (sizeof(double) / sizeof(std::uint16_t)), sizeof v);
    return v;
}

double TimeSweep::whole_hi(int k) const {
    if (!wide_) return hi_[k];
    double v;
    std::memcpy(&v, steps_.get() + (3 + k) * (sizeof(double) / sizeof(std::uint16_t)), sizeof v);
    return v;
}

// Rounded outward, a float is at or beyond the double on its side, so the
// float box holds the double one; where that rounding makes a finite end
// infinite, the doubles are kept (at the head of the steps, which
// encode_pieces allocates after them).
void TimeSweep::set_whole(const Box4& box) {
    wide_ = false;
    for (int k = 0; k < 3; ++k) {
        lo_[k] = float_down(box.lo[k]);
        hi_[k] = float_up(box.hi[k]);
        if ((std::isinf(lo_[k]) && std::isfinite(box.lo[k])) ||
            (std::isinf(hi_[k]) && std::isfinite(box.hi[k])))
            wide_ = true;
    }
    if (!wide_) return;
    steps_ = std::make_unique<std::uint16_t[]>(kWideSteps);
    const double ends[6] = {box.lo.x, box.lo.y, box.lo.z, box.hi.x, box.hi.y, box.hi.z};
    std::memcpy(steps_.get(), ends, sizeof ends);
}

Box4 TimeSweep::whole() const {
    if (empty()) return Box4::empty();
    return {Event(whole_lo(0), whole_lo(1), whole_lo(2), time_.lo),
            Event(whole_hi(0), whole_hi(1), whole_hi(2), time_.hi)};
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
        case Layout::Centred:
            return kHalfSteps + 3 * (n + 1);
    }
    return 0;
}

double TimeSweep::decode(int axis, std::uint16_t q) const {
    const double lo = whole_lo(axis), hi = whole_hi(axis);
    if (q == 0) return lo;
    if (q == kTop) return hi;
    // One step is the extent / kTop, computed the same way at every call.
    const double step = (hi - lo) / double(kTop);
    return std::min(lo + double(q) * step, hi);
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
    const double extent = whole_hi(k) - whole_lo(k);
    if (!(extent > 0.0) || !std::isfinite(extent)) return 0;
    int q = steps_at(std::floor((v - whole_lo(k)) * (double(kTop) / extent)), 0);
    while (q > 0 && decode(k, std::uint16_t(q)) > v) --q;
    return std::uint16_t(q);
}

std::uint16_t TimeSweep::encode_up(int k, double v) const {
    const double extent = whole_hi(k) - whole_lo(k);
    if (!(extent > 0.0) || !std::isfinite(extent)) return kTop;
    int q = steps_at(std::ceil((v - whole_lo(k)) * (double(kTop) / extent)), int(kTop));
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

// Centred pieces (issue 43): a rigid object's box at each cut is its
// placed box there moved out by the chord's error, the same size at every
// cut to within rounding (a sphere's at any turn), so one half extent per
// axis and a centre per cut hold what the shared ends held, in half the
// steps: 102 bytes instead of 204 for a swarm sphere's 16 chords, 10 MB of
// the peak at 10^5. Only where the cuts' extents differ by at most two
// steps per axis (what the shared ends' own rounding may add).
bool TimeSweep::centred_fits(const std::vector<glm::dvec3>& lo,
                             const std::vector<glm::dvec3>& hi) const {
    for (int k = 0; k < 3; ++k) {
        const double step = (whole_hi(k) - whole_lo(k)) / double(kTop);
        if (!(step > 0.0) || !std::isfinite(step)) return false;
        double least = std::numeric_limits<double>::infinity(), most = 0.0;
        for (std::size_t i = 0; i < lo.size(); ++i) {
            const double extent = hi[i][k] - lo[i][k];
            if (!(extent >= 0.0) || !std::isfinite(extent)) return false;
            least = std::min(least, extent);
            most = std::max(most, extent);
        }
        if (!(most - least <= 2.0 * step)) return false;
    }
    return true;
}

// The half extents (three floats at the head), then each cut's centre to
// the nearest step. The half extent along k is the float at or above every
// cut's distance from its decoded centre to either side, checked on the
// decoded sides themselves (moving_piece computes decode - half and
// decode + half, in that order, as here), so that no rounding can cut
// anything off.
void TimeSweep::encode_centred(std::uint16_t* q, const std::vector<glm::dvec3>& lo,
                               const std::vector<glm::dvec3>& hi) const {
    const std::size_t cuts = lo.size();
    std::uint16_t* centres = q + kHalfSteps;
    float half[3];
    for (int k = 0; k < 3; ++k) {
        const double step = (whole_hi(k) - whole_lo(k)) / double(kTop);
        double need = 0.0;
        for (std::size_t i = 0; i < cuts; ++i) {
            const double centre = 0.5 * lo[i][k] + 0.5 * hi[i][k];
            const std::uint16_t c =
                std::uint16_t(steps_at(std::nearbyint((centre - whole_lo(k)) / step), 0));
            centres[3 * i + k] = c;
            const double at = decode(k, c);
            need = std::max({need, interval_detail::next_up(at - lo[i][k]),
                             interval_detail::next_up(hi[i][k] - at)});
        }
        half[k] = float_up(need);
        for (std::size_t i = 0; i < cuts; ++i) {
            const double at = decode(k, centres[3 * i + k]);
            while (at - double(half[k]) > lo[i][k] || at + double(half[k]) < hi[i][k])
                half[k] = std::nextafter(half[k], std::numeric_limits<float>::infinity());
        }
    }
    std::memcpy(q, half, sizeof half);
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
    // The box at cut i holds the ends of both pieces that meet there.
    std::vector<glm::dvec3> cut_lo, cut_hi;
    if (layout_ == Layout::Shared) {
        cut_lo.resize(n + 1);
        cut_hi.resize(n + 1);
        for (std::size_t i = 0; i <= n; ++i) {
            const MovingBox& before = level[i > 0 ? i - 1 : 0];
            const MovingBox& after = level[i < n ? i : n - 1];
            cut_lo[i] = i == 0 ? after.lo0 : i == n ? before.lo1 : glm::min(before.lo1, after.lo0);
            cut_hi[i] = i == 0 ? after.hi0 : i == n ? before.hi1 : glm::max(before.hi1, after.hi0);
        }
        if (centred_fits(cut_lo, cut_hi)) layout_ = Layout::Centred;
    }
    // (After the whole box's doubles, where it has them.)
    std::unique_ptr<std::uint16_t[]> steps =
        std::make_unique<std::uint16_t[]>(head() + step_count());
    if (wide_) std::copy(steps_.get(), steps_.get() + kWideSteps, steps.get());
    steps_ = std::move(steps);
    std::uint16_t* q = steps_.get() + head();
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
            for (std::size_t i = 0; i <= n; ++i) {
                encode_box(q, cut_lo[i], cut_hi[i]);
                q += 6;
            }
            break;
        case Layout::Centred:
            encode_centred(q, cut_lo, cut_hi);
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
            start = end = piece_steps() + 6 * i;
            break;
        case Layout::Shared:
            start = piece_steps() + 6 * i, end = start + 6;
            break;
        case Layout::Separate:
            start = piece_steps() + 12 * i, end = start + 6;
            break;
        case Layout::Centred: {
            // The cuts' centres, each within the half extents (the head).
            float half[3];
            std::memcpy(half, piece_steps(), sizeof half);
            const std::uint16_t* a = piece_steps() + kHalfSteps + 3 * i;
            MovingBox m;
            m.time = t;
            m.empty = false;
            for (int k = 0; k < 3; ++k) {
                m.lo0[k] = decode(k, a[k]) - double(half[k]);
                m.hi0[k] = decode(k, a[k]) + double(half[k]);
                m.lo1[k] = decode(k, a[3 + k]) - double(half[k]);
                m.hi1[k] = decode(k, a[3 + k]) + double(half[k]);
            }
            return m;
        }
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
        const Box4 w = whole();
        for (std::size_t j = 0; j <= count; ++j)
            edge_lo[j] = glm::dvec3(w.lo), edge_hi[j] = glm::dvec3(w.hi);
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
        // leaf's bins mostly lie in one).
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
    // The chord's error over `pieces` pieces of this level (their length
    // rounded up), per axis.
    const auto chord_error = [&](std::uint64_t pieces, double* out_by) {
        const double length = interval_detail::next_up(dyadic_time(time_, level, first + pieces) -
                                                       dyadic_time(time_, level, first));
        for (int a = 0; a < 3; ++a)
            out_by[a] = interval_detail::up(
                length * length * 0.125 * double(acceleration_[a]) + double(margin_[a]), 4);
    };
    double out_by[3];
    chord_error(1, out_by);
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
    // Knots at every other cut where the chord over two pieces (four
    // times one piece's error) stays within the growth the sweep allows
    // for the object's size: three placements for a leaf's four bins
    // instead of five (issue 43: a placement was most of a leaf's work).
    std::size_t stride = 1;
    if (count % 2 == 0 && !no_chord_end(start)) {
        double wide[3];
        chord_error(2, wide);
        const double allowed = 0.5 * (kSweptBoundGrowth - 1.0) * largest_extent(start);
        if (std::max({wide[0], wide[1], wide[2]}) <= allowed) {
            stride = 2;
            std::copy(wide, wide + 3, out_by);
        }
    }
    // Piece k's box, narrowed to `chord` where they meet.
    const auto narrow = [&](std::size_t k, Box4 chord) {
        if (out[k].is_empty() || chord.is_empty()) return;
        chord.lo.w = out[k].lo.w;
        chord.hi.w = out[k].hi.w;
        const Box4 both = chord.intersection(out[k]);
        if (!both.is_empty()) out[k] = both;
    };
    bool chords = want_edges && !no_chord_end(start);
    if (chords) widened(start, edge_lo[0], edge_hi[0]);
    for (std::size_t k = 0; k < count; k += stride) {
        const Box4 end = object.placed_box_at(dyadic_time(time_, level, first + k + stride));
        if (stride == 1 && !start.is_empty() && !end.is_empty()) {
            Box4 chord = start;
            chord.extend(end);
            for (int a = 0; a < 3; ++a) {
                chord.lo[a] = interval_detail::next_down(chord.lo[a] - out_by[a]);
                chord.hi[a] = interval_detail::next_up(chord.hi[a] + out_by[a]);
            }
            narrow(k, chord);
        } else if (stride == 2 && !no_chord_end(start) && !no_chord_end(end)) {
            // The chord over pieces k and k + 1, a box moving linearly
            // between the knots' (MovingBox pays its interpolation's
            // rounding outward): its box over each piece, and its box at
            // the cut between them as the edge there, so that the lines
            // from edge to edge are the chord's own, moved out.
            MovingBox m;
            m.time = Interval(dyadic_time(time_, level, first + k),
                              dyadic_time(time_, level, first + k + 2));
            m.empty = false;
            widened(start, m.lo0, m.hi0);
            widened(end, m.lo1, m.hi1);
            const double cut = dyadic_time(time_, level, first + k + 1);
            narrow(k, m.box_over(Interval(m.time.lo, cut)));
            narrow(k + 1, m.box_over(Interval(cut, m.time.hi)));
            if (chords) {
                const Box4 at = m.box_over(Interval(cut));
                edge_lo[k + 1] = glm::dvec3(at.lo);
                edge_hi[k + 1] = glm::dvec3(at.hi);
            }
        } else {
            chords = false;
        }
        chords = chords && !no_chord_end(end);
        if (chords) widened(end, edge_lo[k + stride], edge_hi[k + stride]);
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

}  // namespace hexant::runtime
