#include "tracer/media.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>

namespace hexant::tracer {

namespace {

using One = runtime::MediaVolume::One;
using Scattering = runtime::Media::Scattering;

// One media sample's coefficients, the media's at the ray's time.
struct Coefficients {
    const One* media;
    One::At at;
    bool constant;  // no density, or only plain colours (POV-Ray's PLAIN_PATTERN)
};

// POV-Ray's LitInterval and MediaInterval: a stretch [s0, s1] of the ray,
// whether lights reach it (l0..l1 of them), and what its samples gathered.
struct Interval {
    bool lit = false;
    double s0 = 0.0, s1 = 0.0, ds = 0.0;
    std::size_t l0 = 0, l1 = 0;
    int samples = 0;
    glm::dvec3 od{0.0}, te{0.0}, te2{0.0};
};

glm::dvec3 exp_of(const glm::dvec3& x) {
    return {std::exp(x.x), std::exp(x.y), std::exp(x.z)};
}

double distance(const glm::dvec3& a, const glm::dvec3& b) {
    return std::fabs(a.x - b.x) + std::fabs(a.y - b.y) + std::fabs(a.z - b.z);
}

class Integration {
  public:
    Integration(const std::vector<Coefficients>& media, const MediaRay& ray,
                const std::vector<MediaLight>& lights, MediaRandom& random,
                const MediaLightFn& light_at, bool use_scattering, const PhotonMap* photons)
        : media_(media),
          ray_(ray),
          lights_(lights),
          random_(random),
          light_at_(light_at),
          use_scattering_(use_scattering),
          photons_(photons) {}

    // ComputeOneMediaSample: the sample at d0 in [0, 1] of the interval;
    // its emitted (and scattered) light and its optical depth.
    void sample(Interval& interval, double d0, glm::dvec3& colour, glm::dvec3& depth, int method) {
        d0 *= interval.ds;
        const double d1 = interval.s0 + d0;
        const glm::dvec3 point = ray_.origin + ray_.direction * d1;
        glm::dvec3 extinction(0.0), emission(0.0), scattering(0.0);
        for (const Coefficients& c : media_) {
            const glm::dvec3 density = c.media->density_at(point, ray_.time);
            extinction += density * (c.at.absorption + c.at.extinction * c.at.scattering);
            if (!ray_.shadow) {
                emission += density * c.at.emission;
                scattering += density * c.at.scattering;
            }
        }
        depth = extinction * interval.ds;
        if (method != 3) interval.od += depth;
        if (!ray_.shadow && use_scattering_ && interval.lit)
            for (std::size_t i = interval.l0; i <= interval.l1 && i < lights_.size(); ++i) {
                const MediaLight& light = lights_[i];
                if (d1 < light.s0 || d1 > light.s1) continue;
                glm::dvec3 to_light(0.0);
                const glm::dvec3 arriving = light_at_(light.index, point, to_light);
                if (arriving == glm::dvec3(0.0)) continue;
                emission += phase(to_light) * scattering * arriving;
            }
        // (Media photons whether a light reaches the sample or not.)
        if (!ray_.shadow && use_scattering_ && photons_)
            emission += scattering * photon_light(point);
        // (Method 3 takes its samples in order and dims them later; the
        // others assume the extinction constant over the interval.)
        emission *= method == 3 ? glm::dvec3(interval.ds) : interval.ds * exp_of(-extinction * d0);
        colour = emission;
        if (method != 3) {
            interval.te += emission;
            interval.te2 += emission * emission;
        }
        ++interval.samples;
    }

    // ComputeOneMediaSampleRecursive: between d1 and d3 (samples c1, c3),
    // the middle, and on into either half whose ends differ by more than
    // the threshold, `depth` levels deep; POV-Ray's weights (1:1:1 at the
    // bottom, 2:1 and 1:2 across a half) kept as they are.
    void recurse(Interval& interval, double d1, double d3, glm::dvec3& result, const glm::dvec3& c1,
                 const glm::dvec3& c3, glm::dvec3& od_result, const glm::dvec3& od1,
                 const glm::dvec3& od3, int depth, double jitter, double threshold) {
        const double d2 = 0.5 * (d1 + d3);
        const double at = jitter != 0.0 ? d2 + jitter * (d3 - d1) * (random_.next() - 0.5) : d2;
        glm::dvec3 c2, od2;
        sample(interval, at, c2, od2, 3);
        if (depth <= 0) {
            result = (c1 + c2 + c3) / 3.0;
            od_result = (od1 + od2 + od3) / 3.0;
            return;
        }
        glm::dvec3 half, od_half;
        if (distance(c1, c2) > threshold) {
            recurse(interval, d1, d2, half, c1, c2, od_half, od1, od2, depth - 1, jitter,
                    threshold);
            result = half / 2.0;
            od_result = od_half / 2.0;
        } else {
            result = c1 / 3.0 + c2 / 6.0;
            od_result = od1 / 3.0 + od2 / 6.0;
        }
        if (distance(c2, c3) > threshold) {
            recurse(interval, d2, d3, half, c2, c3, od_half, od2, od3, depth - 1, jitter,
                    threshold);
            result += half / 2.0;
            od_result += od_half / 2.0;
        } else {
            result += c2 / 6.0 + c3 / 3.0;
            od_result += od2 / 6.0 + od3 / 3.0;
        }
    }

    double draw() { return random_.next(); }

  private:
    // ComputeMediaPhotons: the media photons within the gather's sphere,
    // each scattered from its direction, over the sphere's volume.
    glm::dvec3 photon_light(const glm::dvec3& point) const {
        thread_local PhotonMap::Found found;
        const double r = photons_->gather_in_volume(point, found);
        if (found.empty() || !(r > 0.0)) return glm::dvec3(0.0);
        glm::dvec3 sum(0.0);
        for (const auto& [d2, photon] : found)
            sum += phase(glm::dvec3(photon->from)) * glm::dvec3(photon->colour);
        return sum * (3.0 / (4.0 * std::numbers::pi * r * r * r));
    }

    // ComputeMediaScatteringAttenuation's phase, averaged over the media.
    double phase(const glm::dvec3& to_light) const {
        const double alpha = glm::dot(to_light, ray_.direction);
        double k = 0.0;
        for (const Coefficients& c : media_) {
            switch (c.media->record.type) {
                case Scattering::Rayleigh:
                    k += 0.799372013 * (1.0 + alpha * alpha);
                    break;
                case Scattering::MieHazy:
                    k += 0.576655375 * (1.0 + 9.0 * std::pow(0.5 * (1.0 + alpha), 8.0));
                    break;
                case Scattering::MieMurky:
                    k += 0.495714547 * (1.0 + 50.0 * std::pow(0.5 * (1.0 + alpha), 32.0));
                    break;
                case Scattering::HenyeyGreenstein: {
                    const double g = c.at.eccentricity, g2 = g * g;
                    const double base = 1.0 + g2 - 2.0 * g * alpha;
                    // (g of +-1 head-on: POV-Ray's division by zero; kept finite.)
                    if (base > 0.0) k += (1.0 - g2) / std::pow(base, 1.5);
                    break;
                }
                case Scattering::Isotropic:
                    k += 1.0;
                    break;
            }
        }
        return k / static_cast<double>(media_.size());
    }

    const std::vector<Coefficients>& media_;
    const MediaRay& ray_;
    const std::vector<MediaLight>& lights_;
    MediaRandom& random_;
    const MediaLightFn& light_at_;
    bool use_scattering_;
    const PhotonMap* photons_;
};

// ComputeMediaLightInterval's merge (POV-Ray 3.7's workaround: the starts
// and the ends sorted apart), then the unlit pieces between.
std::vector<Interval> lit_intervals(const std::vector<MediaLight>& lights, double depth) {
    std::vector<Interval> out;
    if (lights.empty()) return out;
    std::vector<double> s0, s1;
    for (const MediaLight& l : lights) {
        s0.push_back(l.s0);
        s1.push_back(l.s1);
    }
    std::sort(s0.begin(), s0.end());
    std::sort(s1.begin(), s1.end());
    const std::size_t last = lights.size() - 1;
    const auto add = [&](bool lit, double a, double b) {
        Interval i;
        i.lit = lit;
        i.s0 = a;
        i.s1 = b;
        i.l0 = 0;
        i.l1 = last;
        out.push_back(i);
    };
    if (s0[0] > 0.0) add(false, 0.0, s0[0]);
    add(true, s0[0], s1[0]);
    for (std::size_t i = 1; i < lights.size(); ++i) {
        if (s0[i] > out.back().s1) {
            const double from = out.back().s1;
            add(false, from, s0[i]);
            add(true, s0[i], s1[i]);
        } else if (s1[i] > out.back().s1) {
            out.back().s1 = s1[i];
        }
    }
    if (out.back().s1 < depth) add(false, out.back().s1, depth);
    for (Interval& i : out) i.ds = i.s1 - i.s0;
    return out;
}

// ComputeMediaSampleInterval: the lit pieces cut into sampling intervals,
// at least `intervals` of them (by `ratio` between lit and unlit ones).
std::vector<Interval> sample_intervals(const std::vector<Interval>& lit,
                                       const runtime::Media& media, bool constant) {
    std::vector<Interval> out;
    const std::size_t intervals = std::max(std::size_t(media.intervals), lit.size());
    const auto cut = [&](const Interval& piece, std::size_t n) {
        const double delta = piece.ds / static_cast<double>(n);
        for (std::size_t j = 0; j < n; ++j) {
            Interval i = piece;
            i.s0 = piece.s0 + delta * static_cast<double>(j);
            i.s1 = piece.s0 + delta * static_cast<double>(j + 1);
            i.ds = delta;
            out.push_back(i);
        }
    };
    if (lit.size() == 1) {
        if (!lit[0].lit && constant) {
            Interval i = lit[0];
            i.l0 = i.l1 = 0;
            out.push_back(i);
        } else {
            cut(lit[0], intervals);
        }
        return out;
    }
    double sum = 0.0;
    for (const Interval& piece : lit) sum += piece.lit ? media.ratio : 1.0 - media.ratio;
    std::size_t remaining = intervals;
    for (std::size_t i = 0; i < lit.size(); ++i) {
        const double weight = lit[i].lit ? media.ratio : 1.0 - media.ratio;
        std::size_t n = static_cast<std::size_t>(weight / sum * static_cast<double>(intervals)) + 1;
        const std::size_t r = remaining - lit.size() + i + 1;
        if (n > r) n = r;
        cut(lit[i], n);
        remaining -= n;
    }
    return out;
}

// What ComputeMedia reads of the media along a ray before sampling: each
// media's coefficients at the ray's time, the one with the most intervals
// (which leads the sampling), the smallest aa_threshold, and which
// effects any of them has.
struct MediaSet {
    std::vector<Coefficients> coefficients;
    const One* lead = nullptr;
    double threshold = HUGE_VAL;
    bool use_extinction = false, use_scattering = false, all_constant = true;
    bool collect = false;  // some media collects photons (not `collect off`)
};
MediaSet media_set(const std::vector<const One*>& media, double time) {
    MediaSet set;
    set.coefficients.reserve(media.size());
    set.lead = media.front();
    for (const One* m : media) {
        if (m->record.intervals > set.lead->record.intervals) set.lead = m;
        set.threshold = std::min(set.threshold, m->record.aa_threshold);
        const One::At at = m->at(time);
        set.use_extinction = set.use_extinction || at.absorption != glm::dvec3(0.0) ||
                             at.scattering != glm::dvec3(0.0);
        set.use_scattering = set.use_scattering || at.scattering != glm::dvec3(0.0);
        set.collect = set.collect || m->record.collect;
        bool constant = true;
        for (const runtime::Pigment& d : m->record.density)
            constant = constant && d.pattern == runtime::Pigment::Pattern::Solid;
        set.all_constant = set.all_constant && constant;
        set.coefficients.push_back({m, at, constant});
    }
    return set;
}

}  // namespace

double MediaRandom::next() {
    // SplitMix64: small, fast and good enough for sample placement.
    std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    z ^= z >> 31;
    return static_cast<double>(z >> 11) * 0x1.0p-53;
}

glm::dvec3 through_media(const std::vector<const One*>& media, const MediaRay& ray,
                         const std::vector<MediaLight>& lights, MediaRandom& random,
                         const MediaLightFn& light_at, const glm::dvec3& colour,
                         const PhotonMap* photons) {
    if (media.empty() || !(ray.depth > 0.0)) return colour;
    const MediaSet set = media_set(media, ray.time);
    const One* lead = set.lead;
    const double threshold = set.threshold;
    if (ray.shadow && !set.use_extinction) return colour;
    const bool constant_shadow = ray.shadow && set.all_constant;

    std::vector<Interval> lit =
        ray.shadow ? std::vector<Interval>{} : lit_intervals(lights, ray.depth);
    if (lit.empty()) {
        Interval whole;
        whole.s1 = whole.ds = ray.depth;
        lit.push_back(whole);
    }
    std::vector<Interval> intervals =
        sample_intervals(lit, lead->record, lead->record.density.empty());
    if (intervals.front().s0 > 0.0) {
        Interval front;
        front.s1 = front.ds = intervals.front().s0;
        intervals.insert(intervals.begin(), front);
    }
    if (intervals.back().s1 < ray.depth) {
        Interval back;
        back.s0 = intervals.back().s1;
        back.s1 = ray.depth;
        back.ds = ray.depth - back.s0;
        intervals.push_back(back);
    }

    Integration run(set.coefficients, ray, lights, random, light_at, set.use_scattering,
                    photons != nullptr && !photons->empty() ? photons : nullptr);
    const runtime::Media& m = lead->record;
    const int min_samples = m.min_samples;
    glm::dvec3 c0, c1, od0, od1, result, od_result;
    if (m.method == 3 && !constant_shadow) {
        // ComputeMediaAdaptiveSampling: sampleCount + 1 points 1 / (n + 1)
        // apart from the interval's start (POV-Ray's, which leaves the last
        // stretch unsampled), each pair refined recursively.
        for (Interval& i : intervals) {
            const int count = std::max(2, min_samples / 2 + 1);
            const double dd = 1.0 / static_cast<double>(count + 1);
            const auto jittered = [&](double d) {
                return m.jitter != 0.0 ? d + dd * m.jitter * (run.draw() - 0.5) : d;
            };
            double d0 = 0.0;
            run.sample(i, jittered(d0), c0, od0, 3);
            i.te = i.od = glm::dvec3(0.0);
            d0 += dd;
            for (int j = 1; j <= count; ++j, d0 += dd) {
                run.sample(i, jittered(d0), c1, od1, 3);
                run.recurse(i, d0 - dd, d0, result, c0, c1, od_result, od0, od1, m.aa_level - 1,
                            m.jitter, threshold);
                const double n = 1.0 / static_cast<double>(count);
                i.te += result * exp_of(-i.od * n);
                c0 = c1;
                i.od += od_result;
                od0 = od1;
            }
            i.samples = count;
        }
    } else {
        // ComputeMediaRegularSampling (its further samples by the variance
        // test are not taken: max_samples is read, min_samples used).
        for (Interval& i : intervals)
            for (int j = 0; j < min_samples; ++j) {
                if (m.method == 2)
                    run.sample(i, (j + 0.5) / min_samples + run.draw() * m.jitter / min_samples, c0,
                               od0, 2);
                else
                    run.sample(i, run.draw(), c0, od0, 1);
                if (constant_shadow) break;
            }
    }

    // ComputeMediaColour: each interval's light dimmed by the depth before
    // it; the colour behind by all of it.
    glm::dvec3 depth(0.0), emitted(0.0);
    for (const Interval& i : intervals) {
        const double n = 1.0 / static_cast<double>(std::max(i.samples, 1));
        emitted += i.te * n * exp_of(-depth);
        depth += i.od * n;
    }
    const glm::dvec3 out = colour * exp_of(-depth) + emitted;
    // (No NaN leaves: a density pattern that gives one adds nothing.)
    return std::isfinite(out.x) && std::isfinite(out.y) && std::isfinite(out.z) ? out : colour;
}

glm::dvec3 photon_through_media(const std::vector<const One*>& media, const MediaRay& way,
                                MediaRandom& random, const MediaPhotonDeposit* deposit,
                                const glm::dvec3& colour) {
    if (media.empty() || !(way.depth > 0.0)) return colour;
    const MediaSet set = media_set(media, way.time);
    // (POV-Ray returns here, photons deposited or not, when no media
    // dims: its comment calls it a bug; kept, as the images are its.)
    if (!set.use_extinction) return colour;
    // (A photon's samples are a shadow ray's: extinction only.)
    MediaRay ray = way;
    ray.shadow = true;
    const std::vector<MediaLight> no_lights;
    const MediaLightFn no_light;
    Integration run(set.coefficients, ray, no_lights, random, no_light, false, nullptr);
    const runtime::Media& lead = set.lead->record;
    Interval whole;
    whole.lit = true;
    whole.s1 = whole.ds = ray.depth;
    std::vector<Interval> intervals = sample_intervals({whole}, lead, false);
    glm::dvec3 depth(0.0), sampled, sample_depth;
    for (Interval& i : intervals) {
        int n = lead.min_samples;
        double factor = 1.0, jitter = lead.jitter;
        if (deposit) {
            const double per = deposit->spread * (deposit->parallel ? 1.0 : deposit->depth);
            factor = deposit->spacing_factor;
            const double steps = per * factor > 0.0 ? i.ds / (per * factor) : 0.0;
            n = steps < double(deposit->max_steps) ? static_cast<int>(steps) : deposit->max_steps;
            if (steps > double(deposit->max_steps) && n > 0) factor = i.ds / (per * n);
            jitter = deposit->jitter;
        }
        for (int j = 0; j < n; ++j) {
            const double d0 = (j + 0.5 + (random.next() - 0.5) * jitter) / n;
            run.sample(i, d0, sampled, sample_depth, 2);
            if (deposit && set.use_scattering && set.collect) {
                const double along = i.s0 + d0 * i.ds;
                const double per = deposit->parallel ? 1.0 : deposit->depth + along;
                deposit->keep(ray.origin + ray.direction * along, along,
                              colour * (factor * deposit->spread * per));
            }
        }
        depth += i.od / static_cast<double>(std::max(i.samples, 1));
    }
    const glm::dvec3 out = colour * exp_of(-depth);
    return std::isfinite(out.x) && std::isfinite(out.y) && std::isfinite(out.z) ? out : colour;
}

}  // namespace hexant::tracer
