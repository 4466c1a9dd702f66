// Where in a scene file something was written, kept with records whose use
// may fail later (an unsupported pattern), so the error can point at it.
#pragma once

#include <cstddef>
#include <string>

namespace hexant::runtime {

struct SourcePlace {
    std::string file;
    std::size_t line = 0;
    std::size_t column = 0;

    std::string to_string() const {
        return file + ":" + std::to_string(line) + ":" + std::to_string(column);
    }
};

// Something read that hexant does not render as POV-Ray renders it, kept
// with the finish, interior or object it belongs to: warned where the scene
// uses it (a declaration an include file never uses says nothing).
struct Unrendered {
    SourcePlace place;
    std::string message;
};

}  // namespace hexant::runtime
