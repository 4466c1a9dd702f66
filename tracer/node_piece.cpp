// The bottom node over moving objects (cell.hpp's PieceNode): each object's
// bound a line over each of four pieces of the node's time, the knots kept
// in 8 bits of a frame per knot and axis.
//
// Fit: piece p is bin p of the object's bins; fit_linear over that bin
// (and its line where lined) gives a line below (above) everything the
// object occupies over the piece.
// Neighbouring pieces meet at a knot, which takes the lower (upper) of the
// two lines' ends there: lowering an end of a line lowers the whole line
// over its piece, so each piece's line stays below. A knot between two
// pieces where the object has no surface in the cell bounds nothing.
//
// Rounding. Let F be the largest magnitude of the knots along an axis over
// the node's children. The walk evaluates, in float, a = base_j + q_a step,
// b = base_j+1 + q_b step (a fused multiply-add, or a product and a sum
// where the target has no FMA), d = b - a, and a + v d with v the ray's
// place in the piece rounded to float (v in [0, 1], off by at most 2^-25).
// Each rounding is within 2^-24 of its result or operands, all of which
// are within about 2 F: the decodes are off by at most 3 2^-24 F each
// (the product q step is at most a frame's width, under 2 F), d by 2 2^-24
// F plus both decodes' errors, v's rounding times |d| adds 2^-24 F, and the
// last step 3 2^-24 F: under 16 2^-24 F in all, and u's own rounding in
// double (2^-52 of it, times four pieces) far less. Each knot is moved out
// by kPieceMargin F = 32 2^-24 F before it is stored, then stored as the
// step at or below it (above, for upper ends), checked on the decoded value
// in double (exact but for one rounding of 2^-53 of the sum), so the walk's
// box at any instant holds the fitted lines'. Non-finite knots, or values
// whose frame would not fit floats, are not stored here: the caller makes a
// MotionNode instead.
#include <algorithm>
#include <cmath>
#include <limits>
#include <span>

#include "tracer/bound_rounding.hpp"
#include "tracer/hierarchy_builder.hpp"
#include "tracer/piece_node.hpp"

namespace hexant::tracer {

using namespace hierarchy_build;

namespace {

constexpr int kPieces = PieceNode::kPieces;
// A piece is one bin: the builder's bins (kFitBins) are as many as the
// pieces, and no more fit a TimeBins. (With more bins a piece, fit each
// piece's bins as one TimeBins with fit_linear.)
static_assert(kMaxBins == kPieces);
constexpr int kKnots = PieceNode::kKnots;
constexpr int kTop = 255;
constexpr double kInf = std::numeric_limits<double>::infinity();

// Knots of one child: lo[j][k] and hi[j][k]; +inf / -inf where the object
// has no surface on either side of knot j.
struct Knots {
    double lo[kKnots][3], hi[kKnots][3];
};

// The object's piecewise-linear bound over the pieces of its bins (false:
// a knot is not finite).
bool fit_pieces(const TimeBins& bins, Knots& out) {
    for (int j = 0; j < kKnots; ++j)
        for (int k = 0; k < 3; ++k) out.lo[j][k] = kInf, out.hi[j][k] = -kInf;
    const bool lines = bins.lines();
    for (int p = 0; p < kPieces; ++p) {
        const LinearBox fit = fit_linear(bins.bin[p], bins.edge[p], bins.edge[p + 1], lines);
        if (fit.empty) continue;
        for (int k = 0; k < 3; ++k) {
            out.lo[p][k] = std::min(out.lo[p][k], fit.lo0[k]);
            out.lo[p + 1][k] = std::min(out.lo[p + 1][k], fit.lo1[k]);
            out.hi[p][k] = std::max(out.hi[p][k], fit.hi0[k]);
            out.hi[p + 1][k] = std::max(out.hi[p + 1][k], fit.hi1[k]);
        }
    }
    for (int j = 0; j < kKnots; ++j) {
        // (A knot bounding nothing on both sides stays empty.)
        if (out.lo[j][0] == kInf) continue;
        for (int k = 0; k < 3; ++k)
            if (!std::isfinite(out.lo[j][k]) || !std::isfinite(out.hi[j][k])) return false;
    }
    return true;
}

double decoded(float base, float step, int q) {
    return double(base) + double(q) * double(step);
}

}  // namespace

bool fit_piece_node(PieceNode& node, const runtime::Interval& time,
                    std::span<const TimeBins* const> bins) {
    const std::size_t n = bins.size();
    if (n == 0 || n > std::size_t(kNodeWidth)) return false;
    std::array<Knots, kNodeWidth> knots;
    for (std::size_t i = 0; i < n; ++i) {
        if (bins[i]->count != kPieces) return false;
        if (!fit_pieces(*bins[i], knots[i])) return false;
    }
    // Per axis, the margin; per knot and axis, the targets' frame.
    double margin[3], lo_of[kKnots][3], hi_of[kKnots][3];
    for (int k = 0; k < 3; ++k) {
        double f = 0.0;
        for (std::size_t i = 0; i < n; ++i)
            for (int j = 0; j < kKnots; ++j)
                if (knots[i].lo[j][0] != kInf)
                    f = std::max({f, std::fabs(knots[i].lo[j][k]), std::fabs(knots[i].hi[j][k])});
        // (Beyond 1e30 the frames' floats would not hold the margins.)
        if (!(f < 1e30)) return false;
        margin[k] = kPieceMargin * f + std::numeric_limits<float>::min();
        for (int j = 0; j < kKnots; ++j) lo_of[j][k] = kInf, hi_of[j][k] = -kInf;
    }
    for (std::size_t i = 0; i < n; ++i)
        for (int j = 0; j < kKnots; ++j) {
            if (knots[i].lo[j][0] == kInf) continue;
            // (A knot next to a piece the object is absent from may be
            // inverted, its lines met beyond where they hold anything: the
            // frame holds both ends whatever their order.)
            for (int k = 0; k < 3; ++k) {
                knots[i].lo[j][k] -= margin[k];
                knots[i].hi[j][k] += margin[k];
                lo_of[j][k] = std::min({lo_of[j][k], knots[i].lo[j][k], knots[i].hi[j][k]});
                hi_of[j][k] = std::max({hi_of[j][k], knots[i].lo[j][k], knots[i].hi[j][k]});
            }
        }
    node.children = std::uint32_t(n);
    node.t0 = time.lo;
    node.t1 = time.hi;
    node.inverse_span = time.hi > time.lo ? 1.0 / (time.hi - time.lo) : 0.0;
    if (!std::isfinite(node.inverse_span)) node.inverse_span = 0.0;
    for (int k = 0; k < 3; ++k) {
        double widest = 0.0;
        for (int j = 0; j < kKnots; ++j) {
            if (!(lo_of[j][k] <= hi_of[j][k])) {
                node.base[j][k] = 0.0f;  // (no child has a surface at this knot)
                continue;
            }
            node.base[j][k] = float_down(lo_of[j][k]);
            widest = std::max(widest, hi_of[j][k] - double(node.base[j][k]));
        }
        float step = float_up(widest / kTop);
        if (!(step > 0.0f)) step = std::numeric_limits<float>::min();
        // Every frame's top at or above its highest target.
        for (int j = 0; j < kKnots; ++j)
            while (lo_of[j][k] <= hi_of[j][k] && decoded(node.base[j][k], step, kTop) < hi_of[j][k])
                step = float_step_up(step);
        node.step[k] = step;
    }
    for (int i = 0; i < kNodeWidth; ++i)
        for (int j = 0; j < kKnots; ++j)
            for (int k = 0; k < 3; ++k) {
                // Empty (a slot past the children, or nothing at this knot):
                // the lower end at the top, the upper at the bottom.
                node.lo[j][k][i] = kTop;
                node.hi[j][k][i] = 0;
                if (i >= int(n) || knots[i].lo[j][0] == kInf) continue;
                const float base = node.base[j][k], step = node.step[k];
                const double lo = knots[i].lo[j][k], hi = knots[i].hi[j][k];
                int qlo = int(std::clamp(std::floor((lo - base) / step), 0.0, double(kTop)));
                while (qlo > 0 && decoded(base, step, qlo) > lo) --qlo;
                int qhi = int(std::clamp(std::ceil((hi - base) / step), 0.0, double(kTop)));
                while (qhi < kTop && decoded(base, step, qhi) < hi) ++qhi;
                node.lo[j][k][i] = std::uint8_t(qlo);
                node.hi[j][k][i] = std::uint8_t(qhi);
            }
    for (NodeRef& c : node.child) c = NodeRef{};
    return true;
}

// Null where the knots cannot be stored in the node (fit_piece_node):
// the caller makes a MotionNode.
NodeRef Hierarchy::Builder::piece_node(NodeArena& arena, const Interval& time,
                                       const std::vector<Child>& children) const {
    std::array<const TimeBins*, kNodeWidth> bins;
    if (children.empty() || children.size() > bins.size()) return {};
    for (std::size_t i = 0; i < children.size(); ++i) bins[i] = &children[i].bins;
    PieceNode fitted;
    if (!fit_piece_node(fitted, time, std::span(bins.data(), children.size()))) return {};
    for (std::size_t i = 0; i < children.size(); ++i) fitted.child[i] = children[i].ref;
    PieceNode* node = arena.make<PieceNode>();
    *node = fitted;
    return NodeRef::node(RefKind::PieceNode, node);
}

// A piece node's test takes about 2.2 times a box node's (its knots are
// decoded at the ray's instant: in atom's profile Walk::pieces took 11.8%
// against the frame baseline's Walk::box 5.4%, at one node test a ray in
// both), so it pays only where the object tests it saves make up for 1.2
// node tests more. By the surface-area heuristic a ray that reaches the
// node meets child i's bound in proportion to its area: the pieces save
// sum_i c_i (A_box_i - A_piece_i) / A_node, c_i the child's test in node
// tests (BuildOptions' object prices), A_piece_i the mean area a ray at an
// instant sees (TimeBins::mean_area), A_box_i the box over the node's time.
// (A floor beside a few small movers, atom's leaves: the pieces save a
// fraction of a test; a leaf of swarm spheres: several.)
bool Hierarchy::Builder::pieces_pay(const std::vector<Child>& children) const {
    constexpr double kPieceExtra = 1.2;
    // Each child's box, and the node's, first: the savings then stop being
    // summed once they pay (a leaf of swarm spheres pays after one or two).
    std::array<double, kNodeWidth> box_area{};
    BinBox all;
    for (std::size_t i = 0; i < children.size(); ++i) {
        const BinBox hull = children[i].bins.hull();
        box_area[i] = surface_area(hull);
        all.extend(hull);
    }
    const double node = surface_area(all);
    // (A flat or empty node leaves no ratio: the pieces, as before.)
    if (!(node > 0.0)) return true;
    const double needed = kPieceExtra * node;
    double saved = 0.0;
    for (std::size_t i = 0; i < children.size(); ++i) {
        const Child& c = children[i];
        const double cost =
            c.ref.kind() == RefKind::Object && objects_.objects[c.ref.object_index()]->moves()
                ? options_.moving_object_cost
                : options_.object_cost;
        saved += cost * std::max(0.0, box_area[i] - c.bins.mean_area());
        if (saved > needed) return true;
    }
    return false;
}

// The node over a leaf's objects (at most eight): a PieceNode where
// something moves within the node's time, the style allows lines and (Auto)
// the pieces pay, else as bound_node chooses.
NodeRef Hierarchy::Builder::object_node(NodeArena& arena, const Interval& time,
                                        const std::vector<Child>& children,
                                        Counters& counters) const {
    const BoundStyle style = options_.bounds;
    if (!space_only() && (style == BoundStyle::Auto || style == BoundStyle::Linear) &&
        moves_within(children) && (style == BoundStyle::Linear || pieces_pay(children)))
        if (const NodeRef ref = piece_node(arena, time, children); !ref.empty()) {
            ++counters.piece_nodes;
            return ref;
        }
    return bound_node(arena, time, children, counters);
}

}  // namespace hexant::tracer
