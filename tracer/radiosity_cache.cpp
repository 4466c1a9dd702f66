#include "tracer/radiosity_cache.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>

namespace hexant::tracer {

namespace {

// POV-Ray's constants (radiosity.cpp): how far in front of the point an
// old one may lie before it is taken to shadow it, distances below which
// two points are one, and weights too small to count.
constexpr double kInFrontLimit = -0.05;
constexpr double kAverageNearEpsilon = 0.000001;
constexpr double kRadiosityEpsilon = 0.001;
constexpr double kBrillianceEpsilon = 1e-5;
constexpr std::uint32_t kLeafRecords = 4;

}  // namespace

void RadiosityReuse::add(const RadiosityRecord& block, const RadiosityQuery& q) {
    // AverageNearBlock, step by step.
    if (block.depth != q.depth) return;
    if (std::fabs(block.brilliance - q.brilliance) > kBrillianceEpsilon) return;
    const glm::dvec3 delta = q.point - block.point;
    const double square = glm::dot(delta, delta);
    const double quick = block.harmonic_mean * q.error_bound;
    if (!(square < quick * quick)) return;
    const double dist = std::sqrt(square);
    double ri = block.harmonic_mean;
    const bool apart = dist > kAverageNearEpsilon;
    glm::dvec3 unit(0.0);
    if (apart) {
        unit = delta / dist;
        // (Less reach toward the nearest surface its rays met.)
        const double toward = glm::dot(block.to_nearest, unit);
        if (toward > 0.0) ri = toward * block.nearest + (1.0 - toward) * ri;
    }
    if (!(dist < ri * q.error_bound)) return;
    const double translate = dist / ri;
    const double rotate = 2.0 * std::sqrt(std::fabs(1.0 - glm::dot(q.normal, block.normal)));
    const double error = translate + rotate;
    if (!(error < q.error_bound)) return;
    double in_front = 1.0;
    if (apart) {
        const glm::dvec3 half = q.normal + block.normal;
        const double length = glm::length(half);
        in_front = length > 0.0 ? glm::dot(unit, half) / length : 0.0;
    }
    if (!(in_front > kInFrontLimit)) return;
    const double t = error / q.error_bound;  // 0 < t < 1
    // (The final trace's pseudo-sigmoid; else linear.)
    double w = !(q.smooth && block.depth == 0) ? 1.0 - t
               : t < 0.5                       ? 1.0 - (t * 2.0) * (t * 2.0) / 2.0
                                               : ((1.0 - t) * 2.0) * ((1.0 - t) * 2.0) / 2.0;
    if (in_front <= 0.0) w *= 1.0 - in_front / kInFrontLimit;
    if (!(w > kRadiosityEpsilon)) return;
    w *= block.quality;
    weighted += block.illuminance * w;
    weight += w;
}

void RadiosityCache::clear() {
    records_.clear();
    indices_.clear();
}

void RadiosityCache::add(std::span<const RadiosityRecord> records) {
    if (records.empty()) return;
    records_.insert(records_.end(), records.begin(), records.end());
    indices_.assign(reach_.size(), Index{});
    for (int d = 0; d < static_cast<int>(reach_.size()); ++d) build(d);
}

void RadiosityCache::build(int depth) {
    Index& index = indices_[std::size_t(depth)];
    for (std::uint32_t i = 0; i < records_.size(); ++i)
        if (records_[i].depth == depth) index.order.push_back(i);
    if (index.order.empty()) return;
    index.nodes.reserve(2 * index.order.size() / kLeafRecords + 2);
    build_node(index, 0, static_cast<std::uint32_t>(index.order.size()), depth);
}

// A node over order[first, first + count), returned by its place: split at
// the median of the centres along their widest spread. Its depth is the
// log of the records' count, well within the walk's stack.
std::uint32_t RadiosityCache::build_node(Index& index, std::uint32_t first, std::uint32_t count,
                                         int depth) {
    const auto self = static_cast<std::uint32_t>(index.nodes.size());
    index.nodes.emplace_back();
    const double reach = reach_[std::size_t(depth)];
    glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-lo);
    glm::dvec3 clo = lo, chi = hi;
    for (std::uint32_t k = first; k < first + count; ++k) {
        const RadiosityRecord& r = records_[index.order[k]];
        const double radius = r.harmonic_mean * reach;
        lo = glm::min(lo, r.point - radius);
        hi = glm::max(hi, r.point + radius);
        clo = glm::min(clo, r.point);
        chi = glm::max(chi, r.point);
    }
    index.nodes[self].lo = lo;
    index.nodes[self].hi = hi;
    if (count <= kLeafRecords) {
        index.nodes[self].first = first;
        index.nodes[self].count = count;
        return self;
    }
    const glm::dvec3 spread = chi - clo;
    const int axis = spread.x >= spread.y && spread.x >= spread.z ? 0
                     : spread.y >= spread.z                       ? 1
                                                                  : 2;
    const std::uint32_t half = count / 2;
    std::nth_element(index.order.begin() + first, index.order.begin() + first + half,
                     index.order.begin() + first + count, [&](std::uint32_t a, std::uint32_t b) {
                         return records_[a].point[axis] < records_[b].point[axis];
                     });
    const std::uint32_t left = build_node(index, first, half, depth);
    const std::uint32_t right = build_node(index, first + half, count - half, depth);
    index.nodes[self].first = left;
    index.nodes[self].right = right;
    index.nodes[self].count = 0;
    return self;
}

void RadiosityCache::gather(const RadiosityQuery& query, RadiosityReuse& into) const {
    if (query.depth < 0 || std::size_t(query.depth) >= indices_.size()) return;
    const Index& index = indices_[std::size_t(query.depth)];
    if (index.nodes.empty()) return;
    std::uint32_t stack[64];
    int top = 0;
    stack[top++] = 0;
    const glm::dvec3& p = query.point;
    while (top > 0) {
        const Node& node = index.nodes[stack[--top]];
        if (p.x < node.lo.x || p.y < node.lo.y || p.z < node.lo.z || p.x > node.hi.x ||
            p.y > node.hi.y || p.z > node.hi.z)
            continue;
        if (node.count > 0) {
            for (std::uint32_t k = node.first; k < node.first + node.count; ++k)
                into.add(records_[index.order[k]], query);
            continue;
        }
        stack[top++] = node.first;
        stack[top++] = node.right;
    }
}

}  // namespace hexant::tracer
