#include "runtime/texture/finish_pool.hpp"

#include <bit>
#include <optional>

namespace hexant::runtime {

namespace {

// A member added to Finish must be added to key_of too, or finishes that
// differ in it would be shared.
static_assert(sizeof(void*) != 8 || sizeof(Finish) == 288, "Finish changed: update key_of");

// The key of a pooled finish, or nothing: every amount's bits (so 0.0 and
// -0.0 differ, and no NaN is equal to itself by accident) and the flags.
std::optional<std::vector<std::uint64_t>> key_of(const Finish& f) {
    if (!f.unrendered.empty()) return std::nullopt;
    std::vector<std::uint64_t> key;
    key.reserve(40);
    const auto add = [&key](const TimeFunction& value) {
        if (!value.is_constant()) return false;
        key.push_back(std::bit_cast<std::uint64_t>(value.constant()));
        return true;
    };
    for (const auto& scalar : f.scalars())
        if (!add(*scalar.value)) return std::nullopt;
    for (const auto& c : f.reflection.c)
        if (!add(c)) return std::nullopt;
    key.push_back(f.reflection_max.has_value());
    if (f.reflection_max)
        for (const auto& c : f.reflection_max->c)
            if (!add(c)) return std::nullopt;
    key.push_back(f.reflection_fresnel);
    key.push_back(f.conserve_energy);
    return key;
}

}  // namespace

std::shared_ptr<Finish> FinishPool::share(Finish&& finish) {
    auto key = key_of(finish);
    if (!key) return std::make_shared<Finish>(std::move(finish));
    auto [it, added] = pool_.try_emplace(std::move(*key));
    if (added) it->second = std::make_shared<Finish>(std::move(finish));
    return it->second;
}

}  // namespace hexant::runtime
