// Which sanitizer a test build runs under (README, "Tests": the fuzz build
// runs the whole suite with AddressSanitizer and UndefinedBehaviorSanitizer).
#pragma once

namespace hexant::test {

// AddressSanitizer reserves terabytes of address space for its shadow
// memory at start, so a test that caps the address space (RLIMIT_AS) to
// provoke a failed allocation cannot run under it.
#if defined(__SANITIZE_ADDRESS__)
inline constexpr bool kAddressSanitizer = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
inline constexpr bool kAddressSanitizer = true;
#else
inline constexpr bool kAddressSanitizer = false;
#endif
#else
inline constexpr bool kAddressSanitizer = false;
#endif

}  // namespace hexant::test
