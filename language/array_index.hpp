// Where an element of an array lies: its indices (constant numbers, each
// floored as POV-Ray does) to the flat position. Throws ValueError for the
// wrong number of indices, and (checked_integer) for one out of range.
#pragma once

#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

#include "language/checked_integer.hpp"
#include "language/value.hpp"

namespace hexant::language {

// The element of an array; `indices` already constant.
inline std::size_t element_index(const Array& array, const std::vector<double>& indices) {
    if (indices.size() != array.dimensions.size())
        throw ValueError("this array has " + std::to_string(array.dimensions.size()) +
                         " dimension(s) but " + std::to_string(indices.size()) +
                         " index(es) were given");
    std::size_t flat = 0;
    for (std::size_t d = 0; d < indices.size(); ++d) {
        const long long i =
            checked_integer(std::floor(indices[d]), "an array index", 0, array.dimensions[d] - 1);
        flat = flat * static_cast<std::size_t>(array.dimensions[d]) + static_cast<std::size_t>(i);
    }
    return flat;
}

}  // namespace hexant::language
