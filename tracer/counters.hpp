// What the tracer counts, per thread and merged at the end: the rows of the
// paper's Tables 1 and 2.
#pragma once

#include <algorithm>
#include <cstdint>

namespace hexant::tracer {

struct Counters {
    // Rays by kind.
    std::uint64_t primary_rays = 0;
    std::uint64_t shadow_rays = 0;
    std::uint64_t reflected_rays = 0;
    std::uint64_t refracted_rays = 0;
    // Radiosity: the rays its samples gathered with, the samples gathered
    // (records made) and the reuses of the cache (--stats).
    std::uint64_t radiosity_rays = 0;
    std::uint64_t radiosity_samples = 0;
    std::uint64_t radiosity_reuses = 0;
    // Photons: the rays shooting them traced (per frame, before its
    // samples: not in rays()), the photons kept in the frame's map, and
    // the gathers of the render (--stats).
    std::uint64_t photon_rays = 0;
    std::uint64_t photons_stored = 0;
    std::uint64_t media_photons_stored = 0;
    std::uint64_t photon_gathers = 0;
    // Dispersion: the refracted rays that took one spectral band of a ray
    // of every colour (tracer/spectral_band.hpp; counted in refracted_rays
    // too).
    std::uint64_t dispersed_rays = 0;
    // Hierarchy.
    std::uint64_t bounds_built = 0;  // object bound() answers while building
    std::uint64_t cells = 0;         // cells built (a lazy build: those rays reached)
    std::uint64_t cells_full = 0;    // cells a full build makes (counted on request)
    std::uint64_t node_tests = 0;    // nodes tested (each tests its children's bounds at once)
    // Nodes built by the style of their children's bounds (cell.hpp), time
    // nodes, and references to objects at the bottom (an object in several
    // cells counts once in each).
    std::uint64_t box_nodes = 0, motion_nodes = 0, slab_nodes = 0, time_nodes = 0;
    std::uint64_t piece_nodes = 0;  // bottom nodes whose objects' bounds are piecewise linear
    std::uint64_t object_refs = 0;
    std::uint64_t bound_tests = 0;   // ray / bound tests (children's bounds in the nodes tested)
    std::uint64_t object_tests = 0;  // ray / object intersections (at the ray's time)
    std::uint64_t mailbox_hits = 0;  // object tests saved by the mailbox
    // Paying only for what a scene uses: these stay 0 where it uses nothing.
    std::uint64_t objects = 0;           // intelligent objects built from the scene
    std::uint64_t time_splits = 0;       // cells whose children halve time
    std::uint64_t deformation_maps = 0;  // runtime::WorkCounts, while building and tracing
    std::uint64_t filtered_surfaces =
        0;                              // surfaces that filtered a shadow ray (transparent objects)
    std::uint64_t travelling_rays = 0;  // rays whose time runs along them (--light-speed)
    // Wall time: building before the frames (sweeps, the root; everything
    // when eager) and rendering them. A lazy build's cells are built during
    // the render, by the threads that reach them: their time is inside
    // render_seconds, and lazy_build_seconds sums it over the threads.
    double build_seconds = 0.0;
    double sweep_seconds = 0.0;  // the part of build_seconds spent on the objects' sweeps
    double render_seconds = 0.0;
    double lazy_build_seconds = 0.0;
    // Memory: the most the hierarchy's nodes held at once and the objects'
    // sweeps (RayQuery::measure_memory), and the process's resident memory
    // before the render began and at its peak (the app fills these in; the
    // peak is the process's, earlier renders in it included, before the
    // statistics' count of a full build).
    std::uint64_t node_bytes = 0, sweep_bytes = 0;
    double memory_start_mb = 0.0, memory_peak_mb = 0.0;

    std::uint64_t rays() const {
        return primary_rays + shadow_rays + reflected_rays + refracted_rays + radiosity_rays;
    }

    Counters& operator+=(const Counters& o) {
        primary_rays += o.primary_rays;
        shadow_rays += o.shadow_rays;
        reflected_rays += o.reflected_rays;
        refracted_rays += o.refracted_rays;
        radiosity_rays += o.radiosity_rays;
        radiosity_samples += o.radiosity_samples;
        radiosity_reuses += o.radiosity_reuses;
        photon_rays += o.photon_rays;
        photons_stored += o.photons_stored;
        media_photons_stored += o.media_photons_stored;
        photon_gathers += o.photon_gathers;
        dispersed_rays += o.dispersed_rays;
        bounds_built += o.bounds_built;
        cells += o.cells;
        cells_full += o.cells_full;
        node_tests += o.node_tests;
        box_nodes += o.box_nodes;
        motion_nodes += o.motion_nodes;
        piece_nodes += o.piece_nodes;
        slab_nodes += o.slab_nodes;
        time_nodes += o.time_nodes;
        object_refs += o.object_refs;
        bound_tests += o.bound_tests;
        object_tests += o.object_tests;
        mailbox_hits += o.mailbox_hits;
        objects += o.objects;
        time_splits += o.time_splits;
        deformation_maps += o.deformation_maps;
        filtered_surfaces += o.filtered_surfaces;
        travelling_rays += o.travelling_rays;
        build_seconds += o.build_seconds;
        sweep_seconds += o.sweep_seconds;
        render_seconds += o.render_seconds;
        lazy_build_seconds += o.lazy_build_seconds;
        node_bytes = std::max(node_bytes, o.node_bytes);
        sweep_bytes = std::max(sweep_bytes, o.sweep_bytes);
        memory_start_mb = std::max(memory_start_mb, o.memory_start_mb);
        memory_peak_mb = std::max(memory_peak_mb, o.memory_peak_mb);
        return *this;
    }
};

}  // namespace hexant::tracer
