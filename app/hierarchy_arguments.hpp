// The hierarchy's flags, shared by `render` and `bench error-time`:
// --split, --build, --bounds, --max-depth, --no-instances (and the
// baseline's --frames-slab-bounds).
#pragma once

#include <string>

#include <CLI/CLI.hpp>

#include "tracer/hierarchy.hpp"

namespace hexant::app {

struct HierarchyArguments {
    std::string split = "cost";
    std::string build = "lazy";
    std::string bounds = "auto";
    int max_depth = 0;  // 0: the criterion's own
    bool frames_slab_bounds = false;
    bool no_instances = false;

    // Throws std::runtime_error naming the flag for a value it does not know.
    tracer::BuildOptions options() const;
};

void add_hierarchy_arguments(CLI::App& command, HierarchyArguments& arguments);

}  // namespace hexant::app
