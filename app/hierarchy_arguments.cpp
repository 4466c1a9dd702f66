#include "app/hierarchy_arguments.hpp"

#include <stdexcept>
#include <string>

namespace hexant::app {

namespace {

// "paper"/"cost", "lazy"/"eager", "auto"/"box"/"linear"/"slabs";
// std::invalid_argument otherwise.
tracer::Criterion parse_criterion(const std::string& name) {
    if (name == "cost") return tracer::Criterion::Cost;
    if (name == "paper") return tracer::Criterion::Paper;
    throw std::invalid_argument("unknown split criterion '" + name + "' (cost or paper)");
}

tracer::BuildKind parse_build_kind(const std::string& name) {
    if (name == "lazy") return tracer::BuildKind::Lazy;
    if (name == "eager") return tracer::BuildKind::Eager;
    throw std::invalid_argument("unknown build '" + name + "' (lazy or eager)");
}

tracer::BoundStyle parse_bound_style(const std::string& name) {
    if (name == "auto") return tracer::BoundStyle::Auto;
    if (name == "box") return tracer::BoundStyle::Box;
    if (name == "linear") return tracer::BoundStyle::Linear;
    if (name == "slabs") return tracer::BoundStyle::Slabs;
    throw std::invalid_argument("unknown bound style '" + name + "' (auto, box, linear or slabs)");
}

}  // namespace

tracer::BuildOptions HierarchyArguments::options() const {
    tracer::BuildOptions o;
    try {
        o.criterion = parse_criterion(split);
        o.build = parse_build_kind(build);
        o.bounds = parse_bound_style(bounds);
    } catch (const std::invalid_argument& e) {
        throw std::runtime_error(std::string("--split/--build/--bounds: ") + e.what());
    }
    if (frames_slab_bounds) {
        if (o.bounds != tracer::BoundStyle::Auto && o.bounds != tracer::BoundStyle::Slabs)
            throw std::runtime_error("--frames-slab-bounds contradicts --bounds " + bounds);
        o.bounds = tracer::BoundStyle::Slabs;
    }
    o.max_depth = max_depth;
    o.instances = !no_instances;
    return o;
}

void add_hierarchy_arguments(CLI::App& command, HierarchyArguments& a) {
    command.add_option("--split", a.split,
                       "When a cell splits: cost (default; a surface-area heuristic over space "
                       "and time) or paper (the paper's object count and density)");
    command.add_option("--build", a.build,
                       "lazy (default: cells are built when a ray first reaches them) or eager "
                       "(the whole hierarchy at once)");
    command.add_option("--bounds", a.bounds,
                       "The style of the cells' bounds: auto (default: a linear-motion box where "
                       "it is tighter, else a box), box, linear or slabs (the 12-slab bound)");
    command
        .add_option("--max-depth", a.max_depth,
                    "Hierarchy depth limit (default: 5 with --split paper, 24 with cost)")
        ->check(CLI::Range(0, tracer::BuildOptions::kMaxDepth));
    command.add_flag("--frames-slab-bounds", a.frames_slab_bounds,
                     "The same as --bounds slabs (kept for the frame-by-frame baseline)");
    command.add_flag("--no-instances", a.no_instances,
                     "Split every union into objects of its own, also one of many still members "
                     "under a moving transform (which is otherwise one instance: the comparison)");
}

}  // namespace hexant::app
