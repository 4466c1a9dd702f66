// The piecewise-linear bottom node (cell.hpp's PieceNode): its fit
// (node_piece.cpp, which argues the rounding) and the box a ray at one
// instant tests, evaluated as the walk evaluates it (traversal_simd.cpp).
#pragma once

#include <algorithm>
#include <cmath>
#include <span>

#include "runtime/geometry/spacetime.hpp"
#include "tracer/cell.hpp"
#include "tracer/linear_bound.hpp"

namespace hexant::tracer {

// Fills node's bounds and times for children with these bins (each over
// equal pieces of `time`, PieceNode::kPieces of them), the
// child slots left empty; false where the knots cannot be stored (not
// finite, or beyond the frames' floats).
bool fit_piece_node(PieceNode& node, const runtime::Interval& time,
                    std::span<const TimeBins* const> bins);

// Child i's box at instant t as the walk computes it, in float with fused
// multiply-adds (the targets without FMA round twice; the margin covers
// both).
struct PieceBox {
    float lo[3], hi[3];
};
inline PieceBox piece_box_at(const PieceNode& node, int i, double t) {
    const double u = std::clamp((t - node.t0) * node.inverse_span, 0.0, 1.0);
    const double s = u * PieceNode::kPieces;
    const int j = std::min(int(s), PieceNode::kPieces - 1);
    const float v = static_cast<float>(s - j);
    PieceBox box;
    for (int a = 0; a < 3; ++a) {
        const float step = node.step[a];
        const auto knot = [&](int k, std::uint8_t q) {
            return std::fma(static_cast<float>(q), step, node.base[k][a]);
        };
        const float lo0 = knot(j, node.lo[j][a][i]), lo1 = knot(j + 1, node.lo[j + 1][a][i]);
        const float hi0 = knot(j, node.hi[j][a][i]), hi1 = knot(j + 1, node.hi[j + 1][a][i]);
        box.lo[a] = std::fma(v, lo1 - lo0, lo0);
        box.hi[a] = std::fma(v, hi1 - hi0, hi0);
    }
    return box;
}

}  // namespace hexant::tracer
