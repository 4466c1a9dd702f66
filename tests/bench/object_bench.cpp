// Micro-benchmark of the intelligent objects' two hot messages: nanoseconds
// per intersect() and per bound() call, for each object kind, static versus
// moving versus deformed, and the plain sphere routine beside the static
// sphere (what "cost is paid only where used" promises).
//
//   build/tests/bench/hexant_object_bench [--rays N] [--repeats R] [--kind K] [--variant V]
//
// Each figure is the median over R timed passes over the same N rays (or N
// regions), all kinds measured in one run, so ratios between rows are fair;
// absolute figures depend on the machine.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "runtime/object_test_support.hpp"
#include "runtime/objects/sphere/sphere_geometry.hpp"

using namespace object_test;

namespace {

struct Options {
    int rays = 4096;
    int repeats = 9;
    std::string kind, variant;  // only these, when given
};

Options parse_options(int argc, char** argv) {
    Options o;
    for (int i = 1; i < argc; ++i) {
        const bool has_value = i + 1 < argc;
        if (!std::strcmp(argv[i], "--rays") && has_value) {
            o.rays = std::max(1, std::atoi(argv[++i]));
        } else if (!std::strcmp(argv[i], "--repeats") && has_value) {
            o.repeats = std::max(1, std::atoi(argv[++i]));
        } else if (!std::strcmp(argv[i], "--kind") && has_value) {
            o.kind = argv[++i];
        } else if (!std::strcmp(argv[i], "--variant") && has_value) {
            o.variant = argv[++i];
        } else {
            std::fprintf(stderr,
                         "usage: %s [--rays N] [--repeats R] [--kind sphere|box|...] "
                         "[--variant static|moving|deformed]\n",
                         argv[0]);
            std::exit(2);
        }
    }
    return o;
}

// Keeps the optimiser from dropping the measured calls.
volatile double g_sink = 0.0;

template <class Pass>
double median_ns(int repeats, int count, Pass&& pass) {
    std::vector<double> ns;
    for (int r = 0; r < repeats; ++r) {
        const auto t0 = std::chrono::steady_clock::now();
        pass();
        const auto t1 = std::chrono::steady_clock::now();
        ns.push_back(std::chrono::duration<double, std::nano>(t1 - t0).count() / count);
    }
    std::nth_element(ns.begin(), ns.begin() + ns.size() / 2, ns.end());
    return ns[ns.size() / 2];
}

struct Workload {
    std::vector<rt::Ray4> rays;
    std::vector<rt::Box4> regions;
};

// Rays from 4 units away aimed into the unit cube around the origin (about
// half of them hit), at random times in [0, 1]; regions are cells of the
// 16-way subdivision of [-2, 2]^3 x [0, 1], one to three levels down, as the
// hierarchy asks.
Workload make_workload(int count) {
    Random random(2026);
    Workload w;
    rt::Box4 root;
    root.lo = rt::Event(-2.0, -2.0, -2.0, 0.0);
    root.hi = rt::Event(2.0, 2.0, 2.0, 1.0);
    for (int i = 0; i < count; ++i) {
        const glm::dvec3 origin = 4.0 * random.unit_vector();
        const glm::dvec3 aim(random.uniform(-0.8, 0.8), random.uniform(-0.8, 0.8),
                             random.uniform(-0.8, 0.8));
        const double t = random.uniform(0.0, 1.0);
        w.rays.push_back({rt::Event(origin, t), rt::Event(glm::normalize(aim - origin), 0.0)});
        rt::Box4 region = root;
        const int depth = random.integer(1, 3);
        for (int d = 0; d < depth; ++d) region = region.child(random.integer(0, 15));
        w.regions.push_back(region);
    }
    return w;
}

struct BenchVariant {
    const char* name;
    const char* transform;
};

const BenchVariant kVariants[] = {
    {"static", "rotate <20, 30, 40>"},
    {"moving", "translate <0.3, 0, 0> rotate <0, 360 * clock, 0> translate <0, 0.2 * clock, 0>"},
    {"orbit", "translate <5, 0, 0> rotate y * (37 + 1440 * clock) rotate <30, 0, -50>"},
    // The same orbit with its angles written as a vector. `y * f` above
    // makes 0 * f in x and z, which time functions fold to 0
    // (time_function.cpp), so the two rows should agree.
    {"orbit-vec", "translate <5, 0, 0> rotate <0, 37 + 1440 * clock, 0> rotate <30, 0, -50>"},
    {"deformed", "twist <0, 1, 0>, 180"},
};

}  // namespace

int main(int argc, char** argv) {
    const Options options = parse_options(argc, argv);
    const Workload work = make_workload(options.rays);
    const double inf = std::numeric_limits<double>::infinity();

    std::printf("hexant_object_bench: %d rays/regions, median of %d passes\n", options.rays,
                options.repeats);
    std::printf("%-16s %-9s %14s %12s %10s %12s %12s\n", "kind", "variant", "ns/intersect",
                "ns/bound", "hit rate", "ns/box_over", "ns/placed");

    std::vector<KindScene> kinds = kind_scenes();
    kinds.push_back({"plane", "<0.2, 1, 0.1>, 0.1", ""});
    for (const KindScene& kind : kinds) {
        for (const BenchVariant& variant : kVariants) {
            if (kind.keyword == "plane" && std::string(variant.name) == "deformed") continue;
            if (!options.kind.empty() && options.kind != kind.keyword) continue;
            if (!options.variant.empty() && options.variant != variant.name) continue;
            const std::string sdl = std::string(kPath) + kind.keyword + " { " + kind.fixed + " " +
                                    variant.transform + " }\n";
            const Parsed parsed = parse(sdl);
            const rt::IntelligentObject& object = *parsed.objects.front();
            int hits = 0;
            for (const auto& ray : work.rays) hits += object.intersect(ray, 0.0, inf) ? 1 : 0;
            const double intersect_ns = median_ns(options.repeats, options.rays, [&] {
                double sum = 0.0;
                for (const auto& ray : work.rays)
                    if (const auto hit = object.intersect(ray, 0.0, inf)) sum += hit->s;
                g_sink = g_sink + sum;
            });
            double bound_ns = 0.0;
            if (object.bounded()) {
                std::vector<rt::SlabBound> out;
                bound_ns = median_ns(options.repeats, options.rays, [&] {
                    std::size_t n = 0;
                    for (const auto& region : work.regions) {
                        out.clear();
                        object.bound(region, out);
                        n += out.size();
                    }
                    g_sink = g_sink + double(n);
                });
            }
            // The sweep's evaluations (runtime/bounds/time_sweep.hpp): the box over
            // 1/64 of the animation (interval), and a placed box at one
            // instant (a chord's end, doubles).
            double box_ns = 0.0, moving_ns = 0.0;
            if (object.bounded()) {
                constexpr int kPieces = 64;
                const auto piece = [](int i) {
                    return rt::Interval(i / double(kPieces), (i + 1) / double(kPieces));
                };
                box_ns = median_ns(options.repeats, kPieces, [&] {
                    double sum = 0.0;
                    for (int i = 0; i < kPieces; ++i) sum += object.box_over(piece(i)).hi.x;
                    g_sink = g_sink + sum;
                });
                moving_ns = median_ns(options.repeats, kPieces, [&] {
                    double sum = 0.0;
                    for (int i = 0; i < kPieces; ++i) sum += object.placed_box_at(piece(i).lo).hi.x;
                    g_sink = g_sink + sum;
                });
            }
            char bound_text[32];
            if (object.bounded())
                std::snprintf(bound_text, sizeof bound_text, "%12.1f", bound_ns);
            else
                std::snprintf(bound_text, sizeof bound_text, "%12s", "unbounded");
            std::printf("%-16s %-9s %14.1f %s %9.0f%% %12.1f %12.1f\n", kind.keyword.c_str(),
                        variant.name, intersect_ns, bound_text, 100.0 * hits / options.rays, box_ns,
                        moving_ns);
        }
    }

    // The plain routine on the static sphere's own geometry (no transform),
    // beside the intelligent object built from the same scene text.
    const Parsed plain_scene = parse("sphere { <0.2, 0.1, 0>, 0.8 }\n");
    const rt::IntelligentObject& sphere = *plain_scene.objects.front();
    const rt::geometry::SphereGeometry geometry{{0.2, 0.1, 0.0}, 0.8};
    const double object_ns = median_ns(options.repeats, options.rays, [&] {
        double sum = 0.0;
        for (const auto& ray : work.rays)
            if (const auto hit = sphere.intersect(ray, 0.0, inf)) sum += hit->s;
        g_sink = g_sink + sum;
    });
    const double plain_ns = median_ns(options.repeats, options.rays, [&] {
        double sum = 0.0;
        for (const auto& ray : work.rays) {
            const rt::geometry::Ray3 r{glm::dvec3(ray.origin), glm::dvec3(ray.direction)};
            if (const auto hit = rt::geometry::intersect(geometry, r, 0.0, inf)) sum += hit->s;
        }
        g_sink = g_sink + sum;
    });
    std::printf(
        "\nstatic sphere without transform: %.1f ns per intersect as an object, "
        "%.1f ns by the plain routine (ratio %.2f)\n",
        object_ns, plain_ns, object_ns / plain_ns);
    return 0;
}
