#include "language/random_stream.hpp"

#include <climits>
#include <cmath>

namespace hexant::language {

RandomStream::RandomStream(double seed_value) {
    std::int32_t seed = INT_MIN;
    // In range means truncation toward zero lands inside int.
    if (seed_value > -2147483649.0 && seed_value < 2147483648.0)
        seed = static_cast<std::int32_t>(seed_value);
    state_ = static_cast<std::uint32_t>(seed);
}

double RandomStream::next() {
    state_ = state_ * 1812433253u + 12345u;
    return static_cast<double>(state_) / 4294967295.0;
}

}  // namespace hexant::language
