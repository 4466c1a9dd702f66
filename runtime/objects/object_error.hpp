// An object the tracer cannot build from its record (an unsupported pattern
// in use, a deformed plane): the message names where it was written.
#pragma once

#include <stdexcept>
#include <string>

#include "runtime/source_place.hpp"

namespace hexant::runtime {

class ObjectError : public std::runtime_error {
  public:
    ObjectError(const SourcePlace& place, const std::string& message)
        : std::runtime_error(place.to_string() + ": error: " + message), place_(place) {}
    const SourcePlace& place() const { return place_; }

  private:
    SourcePlace place_;
};

}  // namespace hexant::runtime
