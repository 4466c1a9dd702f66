// The bytes a scene's arrays and its variables' strings hold, against
// Limits::array_memory. An array, and a variable, carries a MemoryCharge:
// what it was charged is given back when it goes, so the count is of what
// is held at once, not of all that was ever made (a loop that rebuilds an
// array keeps one copy's worth).
#pragma once

#include <cstddef>
#include <memory>

namespace hexant::language {

class MemoryBudget {
  public:
    explicit MemoryBudget(std::size_t limit) : limit_(limit) {}
    // Adds `bytes`; throws ValueError (the limit, what is held, the option
    // that raises it) when the total would pass the limit, adding nothing.
    void charge(std::size_t bytes);
    void release(std::size_t bytes) noexcept { held_ -= bytes < held_ ? bytes : held_; }
    std::size_t held() const { return held_; }

  private:
    std::size_t limit_;
    std::size_t held_ = 0;
};

// What one array was charged. A copy is charged again (arrays are values
// in SDL: each copy holds its own slots). Without a budget it counts
// nothing (arrays made outside a reading, in tests).
class MemoryCharge {
  public:
    MemoryCharge() = default;
    explicit MemoryCharge(std::shared_ptr<MemoryBudget> budget) : budget_(std::move(budget)) {}
    MemoryCharge(const MemoryCharge& other) : budget_(other.budget_) { add(other.bytes_); }
    MemoryCharge& operator=(const MemoryCharge&) = delete;
    ~MemoryCharge() {
        if (budget_) budget_->release(bytes_);
    }
    // Charges this (still empty) charge to `budget` from now on.
    void attach(std::shared_ptr<MemoryBudget> budget) {
        if (bytes_ == 0) budget_ = std::move(budget);
    }
    // Throws as MemoryBudget::charge, adding nothing.
    void add(std::size_t bytes) {
        if (budget_) budget_->charge(bytes);
        bytes_ += bytes;
    }
    // Charges `bytes` in place of what it held (throws as add, changing
    // nothing; the new is charged before the old is given back).
    void set(std::size_t bytes) {
        if (budget_) {
            budget_->charge(bytes);
            budget_->release(bytes_);
        }
        bytes_ = bytes;
    }
    void remove(std::size_t bytes) noexcept {
        if (bytes > bytes_) bytes = bytes_;
        if (budget_) budget_->release(bytes);
        bytes_ -= bytes;
    }
    const std::shared_ptr<MemoryBudget>& budget() const { return budget_; }

  private:
    std::shared_ptr<MemoryBudget> budget_;
    std::size_t bytes_ = 0;
};

}  // namespace hexant::language
