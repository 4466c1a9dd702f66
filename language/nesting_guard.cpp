#include "language/nesting_guard.hpp"

#include <algorithm>

#include <sys/resource.h>

namespace hexant::language {

thread_local const char* NestingGuard::base_ = nullptr;
thread_local std::ptrdiff_t NestingGuard::budget_ = 0;

namespace {

// Half the stack limit, counting at most 8 MB (threads other than the main
// one get their own, often smaller, stacks: 8 MB is glibc's default for
// them too); 1 MB where no limit can be read.
std::ptrdiff_t stack_budget() {
    constexpr std::ptrdiff_t kMost = std::ptrdiff_t(8) << 20;
    rlimit limit{};
    if (getrlimit(RLIMIT_STACK, &limit) != 0 || limit.rlim_cur == 0) return std::ptrdiff_t(1) << 20;
    const std::ptrdiff_t total =
        limit.rlim_cur == RLIM_INFINITY
            ? kMost
            : std::min<std::ptrdiff_t>(kMost, std::ptrdiff_t(limit.rlim_cur));
    return total / 2;
}

}  // namespace

NestingGuard::NestingGuard() {
    if (base_ != nullptr) return;
    const char mark = 0;
    base_ = &mark;
    budget_ = stack_budget();
    outermost_ = true;
}

NestingGuard::~NestingGuard() {
    if (outermost_) base_ = nullptr;
}

}  // namespace hexant::language
