#include "tracer/photon_map.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

#include <glm/geometric.hpp>

namespace hexant::tracer {

namespace {

// The middle element of [begin, end): the one that splits it.
std::size_t middle(std::size_t begin, std::size_t end) {
    return begin + (end - begin) / 2;
}

// Photon i of n for the radius estimate's k-th sample: POV-Ray draws them
// with rand(); a fixed spread (Knuth's multiplicative hash) keeps a frame
// the same whatever ran before.
std::size_t sample_photon(std::size_t k, std::size_t n, std::uint64_t salt) {
    return static_cast<std::size_t>(((k + salt) * 2654435761ull) % n);
}

}  // namespace

PhotonMap::PhotonMap(std::vector<Photon> photons, const runtime::PhotonSettings& settings,
                     Kind kind)
    : photons_(std::move(photons)), settings_(settings) {
    if (photons_.empty()) return;
    build(0, photons_.size());
    const int most = std::max(settings_.gather_max, 1);
    const bool media = kind == Kind::Media;
    // (POV-Ray's density of a gather: per area, or per volume for media.)
    const auto density_of = [media](std::size_t found, double r) {
        return media ? 3.0 * double(found) / (4.0 * std::numbers::pi * r * r * r)
                     : double(found) / (std::numbers::pi * r * r);
    };
    double radius = media ? settings_.media_radius : settings_.radius;
    if (!(radius > 0.0)) {
        // POV-Ray's setGatherOptions: 5% of the photons (100 to 1,000) as
        // gather centres; the mean density of the nearest gather_max
        // around each; the radius that holds gather_max at that density,
        // widened by the share of centres well below it.
        const std::size_t n = photons_.size();
        const std::size_t samples = std::clamp<std::size_t>(n / 20, 100, 1000);
        std::vector<std::pair<double, const Photon*>> heap;
        double sum = 0.0;
        for (std::size_t k = 0; k < samples; ++k) {
            const glm::dvec3 p(photons_[sample_photon(k, n, 0)].position);
            const double r = gather_within(p, nullptr, 1.0e7, most, heap);
            const double density = r > 0.0 ? density_of(heap.size(), r)
                                   : k > 0 ? sum / double(k)
                                           : 0.0;
            sum += density;
        }
        const double mean = sum / double(samples);
        // (POV-Ray's cube root is pow(x, 0.3333): kept, it is its radius.)
        radius = !(mean > 0.0) ? 1.0
                 : media ? std::pow(3.0 * double(most) / (mean * std::numbers::pi * 4.0), 0.3333)
                         : std::sqrt(double(most) / (mean * std::numbers::pi));
        std::size_t sparse = 0;
        for (std::size_t k = 0; k < samples; ++k) {
            const glm::dvec3 p(photons_[sample_photon(k, n, samples)].position);
            const double r = gather_within(p, nullptr, radius, most, heap);
            if (!(r > 0.0)) continue;
            const double density = density_of(heap.size(), r);
            if (density < mean * 0.7 && density > mean * 0.05) ++sparse;
        }
        radius *= 1.0 + 20.0 * double(sparse) / double(samples);
    }
    radius_ = radius * (media ? settings_.media_radius_factor : settings_.radius_factor);
    if (!(radius_ > 0.0) || !std::isfinite(radius_)) radius_ = 0.0;
}

void PhotonMap::build(std::size_t begin, std::size_t end) {
    // (Iterative over the larger half's loop: the depth is the tree's,
    // log2 of the photons.)
    while (end - begin > 0) {
        glm::vec3 lo(std::numeric_limits<float>::infinity()), hi(-lo);
        for (std::size_t i = begin; i < end; ++i) {
            lo = glm::min(lo, photons_[i].position);
            hi = glm::max(hi, photons_[i].position);
        }
        const glm::vec3 extent = hi - lo;
        const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0
                         : extent.y >= extent.z                       ? 1
                                                                      : 2;
        const std::size_t mid = middle(begin, end);
        std::nth_element(
            photons_.begin() + std::ptrdiff_t(begin), photons_.begin() + std::ptrdiff_t(mid),
            photons_.begin() + std::ptrdiff_t(end), [axis](const Photon& a, const Photon& b) {
                return a.position[axis] < b.position[axis];
            });
        photons_[mid].axis = static_cast<std::uint8_t>(axis);
        build(begin, mid);
        begin = mid + 1;
    }
}

double PhotonMap::gather_within(const glm::dvec3& point, const glm::dvec3* normal, double size,
                                int most,
                                std::vector<std::pair<double, const Photon*>>& heap) const {
    heap.clear();
    double reach = size * size;  // POV-Ray's dmax_s: the squared distance still kept
    bool full = false;
    // Ranges still to look at, each with the squared distance from the
    // point to its side of the split above it: a stack, the nearer side
    // popped first, a farther one skipped once the reach has shrunk below
    // its distance.
    struct Range {
        std::size_t begin, end;
        double plane2;
    };
    Range stack[128];
    int top = 0;
    stack[top++] = {0, photons_.size(), 0.0};
    const auto farther = [](const auto& a, const auto& b) { return a.first < b.first; };
    while (top > 0) {
        const Range range = stack[--top];
        if (range.begin >= range.end || range.plane2 >= reach) continue;
        const std::size_t mid = middle(range.begin, range.end);
        const Photon& photon = photons_[mid];
        const int axis = photon.axis;
        const double delta = point[axis] - double(photon.position[axis]);
        if (delta * delta < reach) {
            const glm::dvec3 offset = glm::dvec3(photon.position) - point;
            double d2 = glm::dot(offset, offset);
            // (POV-Ray's disc: the distance stretched by the offset's part
            // along the normal, against light bleeding round corners.)
            if (normal) d2 += std::fabs(glm::dot(*normal, offset)) * d2 * 16.0;
            if (d2 < reach) {
                heap.emplace_back(d2, &photon);
                std::push_heap(heap.begin(), heap.end(), farther);
                if (static_cast<int>(heap.size()) > most) {
                    std::pop_heap(heap.begin(), heap.end(), farther);
                    heap.pop_back();
                    full = true;
                }
                if (full) reach = heap.front().first;
            }
        }
        if (top + 2 > 128) continue;  // (never: the tree is balanced)
        // (delta < 0: the point lies below the split, the lower half nearer.)
        const Range lower{range.begin, mid, delta < 0.0 ? 0.0 : delta * delta};
        const Range upper{mid + 1, range.end, delta < 0.0 ? delta * delta : 0.0};
        if (delta < 0.0) {
            stack[top++] = upper;
            stack[top++] = lower;
        } else {
            stack[top++] = lower;
            stack[top++] = upper;
        }
    }
    return full ? std::sqrt(reach) : size;
}

double PhotonMap::gather(const glm::dvec3& point, const glm::dvec3* normal, Found& heap) const {
    heap.clear();
    if (photons_.empty() || !(radius_ > 0.0)) return 0.0;
    const int most = std::max(settings_.gather_max, 1);
    // (The widened gather's own list, the thread's: a gather calls none.)
    thread_local Found wider;
    double radius = gather_within(point, normal, radius_, most, heap);
    // POV-Ray's gatherPhotonsAdaptive with its two steps: too few found,
    // look once more three times as wide, and keep that when the density
    // changed little or it found few.
    constexpr double kLeast = 1e-16;  // POV-Ray's guard against dividing by 0
    double before = radius > 0.0 ? double(heap.size()) / (radius * radius) : 0.0;
    if (before == 0.0) before = kLeast;
    if (static_cast<int>(heap.size()) < settings_.gather_min) {
        const double r = gather_within(point, normal, radius_ * 3.0, most, wider);
        const double now = r > 0.0 ? double(wider.size()) / (r * r) : 0.0;
        const int found = static_cast<int>(wider.size());
        if ((now - before) / before < settings_.expand_tolerance ||
            (found < settings_.expand_min && found > 0)) {
            heap.swap(wider);
            radius = r;
        }
    }
    return radius;
}

}  // namespace hexant::tracer
