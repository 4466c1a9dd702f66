// An intelligent object's sweep: what it occupies over time, computed once
// so that the hierarchy's cells clip cached boxes instead of evaluating
// motion again for every cell (the paper's future work: "objects cache
// their swept bounds").
//
// The time range is cut into 2^depth equal pieces, and each piece keeps a
// box whose sides move linearly over it (moving_box.hpp). Where the object
// bounds its motion's second derivative (chord_bound_over: a rigid shape
// on an affine motion without jumps or kinks), a piece is the chord between
// the object's placed boxes at the piece's ends (double placements, cheap),
// moved out by the chord's error, length^2 / 8 times that bound, and the
// rounding margin: a box at each instant wider than the object by the
// square of the piece's length, where a box over the whole piece is wider
// by its length times the speed. Elsewhere a piece is an interval box over
// the piece, held still. Both are conservative.
//
// The depth is the object's own: for chords, the fewest pieces whose error
// keeps the box at every instant within kSweptBoundGrowth of the object's
// size, or fewer where the object tests saved do not pay for the ends (one
// jet over the whole range bounds the acceleration); for boxes, as many as the speed measured over
// three short probes asks for. Then pairs are merged back while the coarser pieces are already that
// tight, or the finer ones save fewer object tests than they cost. So a static object keeps one
// piece, a slow one a few, a small fast one more, up to a limit. A motion that is fast only between
// the probes gets fewer box pieces than it could use: looser, never wrong.
//
// Storage: the box over the whole range in floats rounded outward (in
// doubles at the head of the steps where that is not finite, an object
// beyond the floats' range: rounding would make its bound infinite), and
// the pieces as 16-bit steps of that box rounded outward (lower ends to a step at or
// below them, upper ends at or above, checked on the decoded values, so the
// rounding of encoding and decoding cannot cut anything off; a line between
// outward ends lies outside the line between the true ends), in one of
// three layouts, whatever the scene's scale:
//   - still: each piece a box held still, 12 bytes a piece (the boxes of
//     box pieces);
//   - shared ends: the box at each of the 2^depth + 1 cuts, each piece the
//     box moving linearly between its two cuts', 12 bytes a piece and one
//     more (chords: neighbouring chords meet at the same placed box, so
//     sharing loses nothing; where merging left two ends apart, the cut
//     keeps the outer of the two, looser, never wrong);
//   - centred ends: as shared ends where the cuts' boxes are one size to
//     within two steps per axis (a rigid shape's chords, a sphere's at
//     any turn): one half extent per axis in floats and each cut's centre,
//     6 bytes a piece and one more, and 12 bytes;
//   - separate ends: the four ends of each piece's moving sides, 24 bytes a
//     piece, where a piece has no surface (its neighbours' ends cannot be
//     shared through it).
// The chord bound, kept where the sweep refines, is in floats rounded up.
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <utility>
#include <vector>

#include <glm/vec3.hpp>

#include "runtime/bounds/moving_box.hpp"
#include "runtime/geometry/spacetime.hpp"
#include "runtime/objects/intelligent_object.hpp"

namespace hexant::runtime {

// The end of piece `index` of 2^level equal pieces of `range`: range.lo +
// width * (index / 2^level), the same double for every (level, index) that
// names the same fraction, so that cuts made at different levels meet
// exactly. index == 2^level gives range.hi itself.
inline double dyadic_time(const Interval& range, int level, std::uint64_t index) {
    const std::uint64_t n = std::uint64_t(1) << level;
    if (index == 0) return range.lo;
    if (index >= n) return range.hi;
    return range.lo + (range.hi - range.lo) * (double(index) / double(n));
}

// What finer pieces are worth: each halving costs an evaluation of the
// object's box per new piece, and saves object tests for the rays that
// would have met the wider boxes. A piece's rays are estimated as
// ray_density * (its box's surface area) * (its time), the rays of an
// animation spreading evenly over the scene's area and time.
struct SweepPricing {
    double ray_density = 0.0;        // rays per unit of area and of time; 0: free
    double evaluation_cost = 100.0;  // one box evaluation (interval), in node tests
    double point_cost = 20.0;        // one placed box at an instant (doubles), in node tests
    double object_cost = 3.0;        // one object test, in node tests
};

class TimeSweep {
  public:
    TimeSweep() = default;
    // A sweep moved from is empty (its pieces went with the move).
    TimeSweep(TimeSweep&& other) noexcept { *this = std::move(other); }
    TimeSweep& operator=(TimeSweep&& other) noexcept {
        if (this != &other) {
            time_ = other.time_;
            for (int k = 0; k < 3; ++k) {
                lo_[k] = std::exchange(other.lo_[k], kNone);
                hi_[k] = std::exchange(other.hi_[k], -kNone);
                acceleration_[k] = other.acceleration_[k];
                margin_[k] = other.margin_[k];
            }
            steps_ = std::move(other.steps_);
            depth_ = std::exchange(other.depth_, std::uint8_t(0));
            layout_ = std::exchange(other.layout_, Layout::Whole);
            refines_ = std::exchange(other.refines_, false);
            finer_chords_ = std::exchange(other.finer_chords_, false);
            wide_ = std::exchange(other.wide_, false);
        }
        return *this;
    }

    // The sweep of `object` over `time` (finite, lo <= hi), with at most
    // 2^max_depth pieces (max_depth in [0, 20]). With pricing, pieces are
    // halved only while the object tests saved pay for the evaluations.
    static TimeSweep of(const IntelligentObject& object, const Interval& time, int max_depth,
                        const SweepPricing& pricing = {});

    const Interval& time() const { return time_; }
    int depth() const { return depth_; }
    std::size_t piece_count() const { return std::size_t(1) << depth_; }
    // The box over the whole time range (empty if the object has no surface).
    Box4 whole() const;
    bool empty() const { return !(lo_[0] <= hi_[0] && lo_[1] <= hi_[1] && lo_[2] <= hi_[2]); }

    // A box holding the object at every instant of t, from the pieces that
    // meet t (the whole sweep's box in space where t spans it all); its time
    // part is t clipped to time(). Empty where t misses time().
    Box4 box_over(const Interval& t) const;

    // The box over piece `index` of 2^level equal pieces of time(), cut as
    // dyadic_time() cuts them: the union of the sweep's pieces inside it,
    // or the one piece it lies in. Its time part is that piece of time.
    // Exact and cheap when the hierarchy's cells are cut the same way.
    Box4 box_over_dyadic(int level, std::uint64_t index) const;

    // As box_over_dyadic for pieces first .. first + count - 1 of level
    // `level`, into out[0 .. count). Where the level is finer than the
    // sweep's pieces and the sweep refines (refines(), or refines_chords()
    // where edges are asked for), each box is refined
    // from `object` (the object the sweep is of): the chord over that finer
    // piece, from placed boxes at its ends (shared by neighbours, count + 1
    // placements; or, where count is even and the chord over two pieces is
    // within the growth of the object's size, over pairs of pieces from
    // count / 2 + 1 placements), clipped to the cached piece's part. The
    // paper's star cluster: the cache answers coarse questions, the object
    // fine ones.
    //
    // With edge_lo and edge_hi (count + 1 entries each), also the object's
    // bound at each cut between the pieces, such that at every instant of
    // piece k the object lies between the lines from edge k to edge k + 1
    // (the sides of a moving box, as the sweep's own pieces): the chords'
    // placed boxes moved out by their error where the sweep refines, else
    // the cached pieces' lines at the cuts (the outer of two where a cut is
    // a piece's end and the next one's start). Returns whether the edges
    // were filled: not where a piece of this level spans several cached
    // pieces, or the object has no surface over part of the time.
    bool boxes_over_dyadic(int level, std::uint64_t first, std::size_t count,
                           const IntelligentObject& object, Box4* out,
                           glm::dvec3* edge_lo = nullptr, glm::dvec3* edge_hi = nullptr) const;
    // Was the sweep kept coarser than its chords could be by the depth
    // limit (memory), so that finer pieces would still pay? The cost
    // criterion looks further down such sweeps' time.
    bool refines() const { return refines_; }
    // Does boxes_over_dyadic refine below the cached pieces when asked for
    // edges (a node's bounds)? Where refines(), and also where the pricing
    // stopped the sweep, or merged it back, before its chords were within
    // the growth (issue 43: the swarm at 10^4 spheres kept one to four
    // chords a frame, and a leaf's bounds inherited chords 1.8 times a
    // sphere's size; a leaf's bins are made anyway, at five to nine
    // placements an object).
    bool refines_chords() const { return refines_ || finer_chords_; }

    // Piece i's time interval, its moving box, and the box over all of it
    // (empty if the object has no surface then).
    Interval piece_time(std::size_t i) const;
    MovingBox moving_piece(std::size_t i) const;
    Box4 piece(std::size_t i) const;
    // The pieces that meet t: [first, last], or first > last for none.
    void pieces_meeting(const Interval& t, std::size_t& first, std::size_t& last) const;

    // Heap and inline bytes this sweep takes.
    std::size_t bytes() const {
        return sizeof(*this) + (head() + step_count()) * sizeof(std::uint16_t);
    }

  private:
    // How the pieces are kept (the storage note above); Whole: one box held
    // still over the whole time, no pieces.
    enum class Layout : std::uint8_t { Whole, Still, Shared, Separate, Centred };

    double boundary(std::size_t i) const;
    std::size_t step_count() const;
    // Steps at the head of steps_ that hold the whole box in doubles
    // (wide_: six doubles), and the pieces' steps after them.
    static constexpr std::size_t kWideSteps = 6 * sizeof(double) / sizeof(std::uint16_t);
    std::size_t head() const { return wide_ ? kWideSteps : 0; }
    const std::uint16_t* piece_steps() const { return steps_.get() + head(); }
    // The whole box's ends along axis k, and setting them.
    double whole_lo(int k) const;
    double whole_hi(int k) const;
    void set_whole(const Box4& box);
    double decode(int axis, std::uint16_t q) const;
    std::uint16_t encode_down(int axis, double v) const;
    std::uint16_t encode_up(int axis, double v) const;
    // Six steps of a box: lo xyz rounded down, hi xyz up (an empty box, no
    // surface: lo at the top step, hi at the bottom).
    void encode_box(std::uint16_t* q, const glm::dvec3& lo, const glm::dvec3& hi) const;
    void encode_pieces(const std::vector<MovingBox>& level);
    // The Centred layout: three floats of half extent (kHalfSteps steps),
    // then a centre per cut.
    static constexpr std::size_t kHalfSteps = 3 * sizeof(float) / sizeof(std::uint16_t);
    bool centred_fits(const std::vector<glm::dvec3>& lo, const std::vector<glm::dvec3>& hi) const;
    void encode_centred(std::uint16_t* q, const std::vector<glm::dvec3>& lo,
                        const std::vector<glm::dvec3>& hi) const;
    // boxes_over_dyadic's edges from the cached pieces (false: none).
    bool cached_edges(int level, std::uint64_t first, std::size_t count, glm::dvec3* edge_lo,
                      glm::dvec3* edge_hi) const;

    static constexpr float kNone = std::numeric_limits<float>::infinity();
    Interval time_{0.0, 0.0};
    // The box over the whole time, rounded outward to floats (empty: lo >
    // hi); infinite where it lies beyond the floats' range, and then wide_
    // and the doubles at the head of steps_. 24 bytes an object where
    // doubles took 48 (2.4 MB of the swarm's peak at 10^5 spheres).
    float lo_[3] = {kNone, kNone, kNone};
    float hi_[3] = {-kNone, -kNone, -kNone};
    // The chord bound over the whole time, rounded up to floats, where the
    // sweep refines (IntelligentObject::chord_bound_over).
    float acceleration_[3] = {0.0f, 0.0f, 0.0f};
    float margin_[3] = {0.0f, 0.0f, 0.0f};
    // The pieces' steps, step_count() of them, in the layout's order.
    std::unique_ptr<std::uint16_t[]> steps_;
    std::uint8_t depth_ = 0;
    Layout layout_ = Layout::Whole;
    bool refines_ = false;
    bool finer_chords_ = false;
    bool wide_ = false;
};

}  // namespace hexant::runtime
