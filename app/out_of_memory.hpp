// A std::bad_alloc after the scene is read, named by what was being done.
// (While reading, the reader names the scene's place itself.) Without this
// a run that asked for too much ended in "std::bad_alloc" and no more.
#pragma once

#include <new>
#include <stdexcept>
#include <string>
#include <utility>

namespace hexant::app {

// Runs `body`; a std::bad_alloc from it becomes a std::runtime_error
// "out of memory while STAGE".
template <typename Body>
decltype(auto) naming_out_of_memory(const std::string& stage, Body&& body) {
    try {
        return std::forward<Body>(body)();
    } catch (const std::bad_alloc&) {
        throw std::runtime_error(
            "out of memory while " + stage +
            " (std::bad_alloc): the run needs more memory than the machine gives");
    }
}

}  // namespace hexant::app
