#include "tracer/photon_shooting.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <numbers>
#include <stdexcept>
#include <string>

#include <glm/geometric.hpp>
#include <tbb/parallel_for.h>

namespace hexant::tracer {

namespace {

constexpr double kEpsilon = 1.0e-10;  // POV-Ray's EPSILON
constexpr double kPi = std::numbers::pi;
// The most photons a frame may shoot (a bound, counted before shooting).
constexpr double kMostPhotons = 2.0e7;

// A target: its members' box over the shutter, its spacing factor and its
// own photon flags (its first member's: a group's are its members').
struct Target {
    std::int32_t group = -1;
    double factor = 1.0;
    glm::dvec3 lo{std::numeric_limits<double>::infinity()};
    glm::dvec3 hi{-std::numeric_limits<double>::infinity()};
    std::int8_t refraction = 0, reflection = 0;
    bool collect = true;
};

bool photon_on(std::int8_t a, std::int8_t b) {
    return (a == 1 && b != -1) || (a != -1 && b == 1);
}

// Uniform in [0, 1) from a key (splitmix64's finaliser).
double uniform(std::uint64_t key) {
    key += 0x9e3779b97f4a7c15ull;
    key = (key ^ (key >> 30)) * 0xbf58476d1ce4e5b9ull;
    key = (key ^ (key >> 27)) * 0x94d049bb133111ebull;
    key ^= key >> 31;
    return double(key >> 11) * 0x1.0p-53;
}
std::uint64_t key_of(std::uint64_t combo, std::uint64_t ring, std::uint64_t step, std::uint64_t k) {
    return ((combo * 0x100000001b3ull + ring) * 0x100000001b3ull + step) * 8 + k;
}

// `v` turned by `angle` about the unit `axis` (Rodrigues).
glm::dvec3 turned(const glm::dvec3& v, const glm::dvec3& axis, double angle) {
    const double c = std::cos(angle), s = std::sin(angle);
    return v * c + glm::cross(axis, v) * s + axis * (glm::dot(axis, v) * (1.0 - c));
}

// POV-Ray's ShootingDirection: the target's bounding sphere as the light
// sees it.
struct Aim {
    glm::dvec3 centre{0.0}, to_centre{0.0, 0.0, 1.0}, up{0.0}, left{0.0};
    double radius = 0.0, distance = 0.0;
};
Aim aim(const Target& target, const glm::dvec3& light, const glm::dvec3* axis) {
    Aim a;
    const glm::dvec3 half = (target.hi - target.lo) * 0.5;
    a.centre = target.lo + half;
    a.radius = glm::length(half);
    const glm::dvec3 to = a.centre - light;
    a.distance = glm::length(to);
    if (a.distance > 0.0) a.to_centre = to / a.distance;
    a.up =
        std::fabs(std::fabs(a.to_centre.z) - 1.0) < 0.1 ? glm::dvec3(0, 1, 0) : glm::dvec3(0, 0, 1);
    const glm::dvec3 across = glm::cross(axis ? *axis : a.to_centre, a.up);
    const double l = glm::length(across);
    a.left = l > 0.0 ? across / l : glm::dvec3(1, 0, 0);
    return a;
}

}  // namespace

PhotonMaps shoot_photons(const Shader& shader,
                         const std::vector<runtime::IntelligentObjectPtr>& objects,
                         const std::function<double(double)>& time_at,
                         const std::function<ThreadState&()>& state, Counters& counters) {
    const runtime::PhotonSettings& settings = shader.photon_settings();
    const double t0 = time_at(0.0), t1 = time_at(1.0), middle = time_at(0.5);
    const runtime::Interval shutter(std::min(t0, t1), std::max(t0, t1));

    // The targets, in the order their first members come.
    std::vector<Target> targets;
    std::map<std::int32_t, std::size_t> index;
    for (const auto& o : objects) {
        const runtime::ObjectFlags& f = o->flags();
        if (!(f.photon_target > 0.0f)) continue;
        auto [at, fresh] = index.emplace(f.photon_group, targets.size());
        if (fresh) {
            Target t;
            t.group = f.photon_group;
            t.factor = f.photon_target;
            t.refraction = f.photon_refraction;
            t.reflection = f.photon_reflection;
            t.collect = f.photon_collect;
            targets.push_back(t);
        }
        Target& t = targets[at->second];
        const runtime::Box4 box = o->box_over(shutter);
        if (box.is_empty()) continue;
        for (int k = 0; k < 3; ++k) {
            // (An unbounded target, a plane: no sphere to shoot at.)
            if (!std::isfinite(box.lo[k]) || !std::isfinite(box.hi[k])) continue;
            t.lo[k] = std::min(t.lo[k], box.lo[k]);
            t.hi[k] = std::max(t.hi[k], box.hi[k]);
        }
    }

    // The light / target pairs that shoot (POV-Ray's units): a light that
    // casts shadows, a target that reflects or refracts for it.
    struct Combo {
        std::size_t light;
        const Target* target;
        Aim aim;
        double spread, dtheta, maxtheta;
        bool parallel;
    };
    std::vector<Combo> combos;
    const auto& lights = shader.lights();
    for (std::size_t l = 0; l < lights.size(); ++l) {
        const ShadedLight& light = lights[l];
        if (light.shadowless() || !light.shines_at(middle)) continue;
        for (const Target& target : targets) {
            if (!(target.lo.x <= target.hi.x)) continue;
            if (!photon_on(target.refraction, light.photons().refraction) &&
                !photon_on(target.reflection, light.photons().reflection))
                continue;
            Combo c{l, &target, {}, 0.0, 0.0, 0.0, light.parallel()};
            const glm::dvec3 axis = light.axis(middle);
            c.aim = aim(target, light.position_at(middle), c.parallel ? &axis : nullptr);
            combos.push_back(c);
        }
    }
    if (combos.empty()) return {};

    // count: the spacing that shoots about that many (PhotonEstimationTask).
    double spacing = settings.spacing;
    if (settings.count > 0) {
        double estimate = 0.0;
        for (const Combo& c : combos) {
            const runtime::LightPhotons& asks = lights[c.light].photons();
            const bool refracts = photon_on(c.target->refraction, asks.refraction);
            const bool reflects = photon_on(c.target->reflection, asks.reflection);
            const double x0 = c.aim.radius / (c.target->factor * spacing);
            double x = x0 * x0 * kPi;
            if (refracts && reflects) x *= 1.5;
            if (c.target->collect && refracts) x *= reflects ? 3.0 : 2.0;
            estimate += x * 0.5;
        }
        if (estimate > 0.0) spacing *= std::sqrt(estimate / double(settings.count));
    }

    for (Combo& c : combos) {
        c.spread = c.target->factor * spacing;
        if (!c.parallel) c.spread /= std::max(c.aim.distance, kEpsilon);
        c.dtheta = c.parallel ? c.spread : std::atan(c.spread);
        if (c.parallel) {
            c.maxtheta = c.aim.radius;
        } else if (c.aim.distance >= c.aim.radius) {
            c.maxtheta = std::asin(c.aim.radius / c.aim.distance);
        } else {
            // (The light inside the target's sphere: every direction.)
            c.maxtheta = kPi;
            if (std::fabs(c.aim.distance) < kEpsilon) {
                c.aim.up = {1, 0, 0};
                c.aim.left = {0, 1, 0};
                c.aim.to_centre = {0, 0, 1};
            }
            c.aim.distance = c.aim.radius;
        }
    }

    // (A bound on the photons the rings shoot, refused above kMostPhotons:
    // a spacing far below the scene's scale would take the machine's
    // memory, 40 bytes a photon kept, before it took its time.)
    double most = 0.0;
    for (const Combo& c : combos) {
        if (!(c.spread > 0.0) || !(c.dtheta > 0.0)) continue;
        const double rings = std::ceil(c.maxtheta / c.dtheta);
        const double across = c.parallel ? c.maxtheta : std::sin(std::min(c.maxtheta, kPi / 2.0));
        most += rings * (2.0 * kPi * across / c.dtheta + 1.0);
    }
    if (!(most <= kMostPhotons))
        throw std::runtime_error("photons: the spacing " + std::to_string(spacing) +
                                 " would shoot about " +
                                 std::to_string(static_cast<long long>(std::min(most, 1e18))) +
                                 " photons, more than hexant's limit of " +
                                 std::to_string(static_cast<long long>(kMostPhotons)) +
                                 "; raise photons' spacing (or lower its count)");

    // Rings in batches, each ring's photons in its own list, joined in
    // order; autostop checked in ring order after each batch (at most a
    // batch's rings shot for nothing past the stop).
    constexpr int kBatch = 8;
    // (No ring count beyond what a double loop of POV-Ray's would run.)
    constexpr long long kMostRings = 1 << 22;
    std::vector<Photon> all, all_media;
    for (std::size_t ci = 0; ci < combos.size(); ++ci) {
        const Combo& c = combos[ci];
        if (!(c.spread > 0.0) || !(c.dtheta > 0.0) || !std::isfinite(c.dtheta)) continue;
        const ShadedLight& light = lights[c.light];
        const Shader::PhotonShot shot{c.light, c.target->group, c.spread};
        const long long rings = std::min<long long>(
            kMostRings, static_cast<long long>(std::ceil(c.maxtheta / c.dtheta)));
        bool hit_once = false;
        for (long long first = 0; first < rings; first += kBatch) {
            const int count = static_cast<int>(std::min<long long>(kBatch, rings - first));
            std::vector<std::vector<Photon>> found(static_cast<std::size_t>(count)),
                found_media(static_cast<std::size_t>(count));
            std::vector<char> hit(static_cast<std::size_t>(count), 0);
            std::vector<std::uint64_t> shot_count(static_cast<std::size_t>(count), 0);
            tbb::parallel_for(0, count, 1, [&](int r) {
                ThreadState& ts = state();
                const long long ring = first + r;
                const double theta = double(ring) * c.dtheta;
                const double dphi = theta < kEpsilon ? 2.0 * kPi
                                    : c.parallel     ? c.dtheta / theta
                                                     : c.dtheta / std::sin(theta);
                const double minphi = -kPi + dphi * uniform(key_of(ci, ring, 0, 0)) * 0.5;
                const double maxphi = kPi - dphi / 2.0 + (minphi + kPi);
                std::uint64_t step = 0;
                for (double phi = minphi; phi < maxphi; phi += dphi, ++step) {
                    const double jphi =
                        phi + dphi * (uniform(key_of(ci, ring, step, 1)) - 0.5) * settings.jitter;
                    const double jtheta = theta + c.dtheta *
                                                      (uniform(key_of(ci, ring, step, 2)) - 0.5) *
                                                      settings.jitter;
                    const double t = time_at(uniform(key_of(ci, ring, step, 3)));
                    if (!light.shines_at(t)) continue;
                    glm::dvec3 origin = light.position_at(t), direction;
                    if (c.parallel) {
                        direction = light.axis(t);
                        const double a = glm::dot(direction, c.aim.to_centre);
                        origin = c.aim.centre + direction * (-a * c.aim.distance) +
                                 turned(c.aim.left * jtheta, direction, jphi);
                    } else {
                        const glm::dvec3 v =
                            -std::sin(jtheta) * c.aim.left + std::cos(jtheta) * c.aim.to_centre;
                        direction = turned(v, c.aim.to_centre, jphi);
                    }
                    const double attenuation = light.beam(origin, direction, t);
                    if (attenuation < 0.00001) continue;
                    ++shot_count[static_cast<std::size_t>(r)];
                    const runtime::Ray4 ray{runtime::Event(origin, t),
                                            runtime::Event(direction, 0.0)};
                    if (shader.shoot_photon(shot, ray, light.colour_at(t) * attenuation,
                                            found[static_cast<std::size_t>(r)],
                                            found_media[static_cast<std::size_t>(r)], ts))
                        hit[static_cast<std::size_t>(r)] = 1;
                }
            });
            bool stop = false;
            for (int r = 0; r < count && !stop; ++r) {
                const double theta = double(first + r) * c.dtheta;
                all.insert(all.end(), found[static_cast<std::size_t>(r)].begin(),
                           found[static_cast<std::size_t>(r)].end());
                all_media.insert(all_media.end(), found_media[static_cast<std::size_t>(r)].begin(),
                                 found_media[static_cast<std::size_t>(r)].end());
                if (hit[static_cast<std::size_t>(r)]) hit_once = true;
                if (hit_once && !hit[static_cast<std::size_t>(r)] &&
                    theta > settings.autostop * c.maxtheta)
                    stop = true;
            }
            if (stop) break;
        }
    }
    counters.photons_stored += all.size();
    counters.media_photons_stored += all_media.size();
    return {PhotonMap(std::move(all), settings),
            PhotonMap(std::move(all_media), settings, PhotonMap::Kind::Media)};
}

}  // namespace hexant::tracer
