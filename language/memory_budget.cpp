#include "language/memory_budget.hpp"

#include <cstdio>
#include <string>

#include "language/value_ops.hpp"

namespace hexant::language {

void MemoryBudget::charge(std::size_t bytes) {
    if (bytes > limit_ - held_) {
        const auto mb = [](std::size_t b) {
            char text[32];
            std::snprintf(text, sizeof text, "%.1f", static_cast<double>(b) / (1 << 20));
            return std::string(text);
        };
        throw ValueError("the scene's arrays and strings would hold more than " + mb(limit_) +
                         " MiB (they hold " + mb(held_) + " MiB, and this needs " + mb(bytes) +
                         " MiB more); --max-array-memory MIB raises the limit");
    }
    held_ += bytes;
}

}  // namespace hexant::language
