#include "runtime/texture/evaluation_cost.hpp"

#include <algorithm>
#include <map>
#include <vector>

namespace hexant::runtime {
namespace {

constexpr double kPast = 1e300;
constexpr int kDeepest = 10000;

class Counter {
  public:
    double of(const Texture& t, int depth) {
        if (depth > kDeepest) return kPast;
        double own;
        if (t.is_patterned()) {
            std::vector<double> entries;
            for (const auto& e : t.texture_map)
                entries.push_back(e.texture ? shared(e.texture.get(), depth) : 1.0);
            own = 1.0 + blended(entries, takes(t.patterned));
        } else {
            own = of(t.pigment, depth) + (t.normal ? of(*t.normal, depth) : 0.0);
        }
        for (const auto& layer : t.below) own += of(layer, depth + 1);
        return std::min(own, kPast);
    }

  private:
    std::map<const void*, double> known_;

    enum class Takes { One, Two, All };
    // A block pattern's value is an entry's index (checker, brick, hexagon:
    // one entry a point); average takes all; any other blends two.
    static Takes takes(const pattern::Pattern& p) {
        if (p.kind && p.kind->average) return Takes::All;
        if (p.kind && p.kind->argument == pattern::Kind::Argument::Colours) return Takes::One;
        return Takes::Two;
    }

    // The entries a point evaluates (the dearest, at most).
    static double blended(std::vector<double>& entries, Takes how) {
        if (how == Takes::One) {
            double most = 0.0;
            for (const double e : entries) most = std::max(most, e);
            return most;
        }
        if (how == Takes::All || entries.size() <= 2) {
            double sum = 0.0;
            for (const double e : entries) sum += e;
            return sum;
        }
        std::partial_sort(entries.begin(), entries.begin() + 2, entries.end(),
                          [](double a, double b) { return a > b; });
        return entries[0] + entries[1];
    }

    template <class Part>
    double shared(const Part* part, int depth) {
        if (const auto it = known_.find(part); it != known_.end()) return it->second;
        const double cost = of(*part, depth + 1);
        known_[part] = cost;
        return cost;
    }

    double of(const Pigment& p, int depth) {
        if (depth > kDeepest) return kPast;
        if (p.pigment_map.empty()) return 1.0;
        std::vector<double> entries;
        for (const auto& e : p.pigment_map)
            entries.push_back(e.pigment ? shared(e.pigment.get(), depth) : 1.0);
        return std::min(1.0 + blended(entries, takes(p.patterned)), kPast);
    }

    double of(const Normal& n, int depth) {
        if (depth > kDeepest) return kPast;
        if (n.normal_map.empty()) return 1.0;
        std::vector<double> entries;
        for (const auto& e : n.normal_map)
            entries.push_back(e.normal ? shared(e.normal.get(), depth) : 1.0);
        return std::min(1.0 + blended(entries, takes(n.patterned)), kPast);
    }
};

}  // namespace

double evaluation_cost(const Texture& texture) {
    Counter counter;
    return counter.of(texture, 0);
}

}  // namespace hexant::runtime
