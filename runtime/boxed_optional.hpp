// std::optional's interface over a box on the heap: 8 bytes where the value
// is absent. For a large member that most records lack (a texture's
// normal, 488 bytes; an object's interior, 120): held inline, every object
// record of a scene of 10^5 spheres paid for them (issue 43's memory).
// Copies copy the value (not shared: a record's copy may be changed on its
// own, as an optional's).
#pragma once

#include <memory>
#include <optional>
#include <utility>

namespace hexant::runtime {

template <class T>
class BoxedOptional {
  public:
    BoxedOptional() = default;
    BoxedOptional(std::nullopt_t) {}
    BoxedOptional(const T& value) : box_(std::make_unique<T>(value)) {}
    BoxedOptional(T&& value) : box_(std::make_unique<T>(std::move(value))) {}
    BoxedOptional(const std::optional<T>& value)
        : box_(value ? std::make_unique<T>(*value) : nullptr) {}
    BoxedOptional(const BoxedOptional& other)
        : box_(other.box_ ? std::make_unique<T>(*other.box_) : nullptr) {}
    BoxedOptional(BoxedOptional&&) noexcept = default;
    BoxedOptional& operator=(const BoxedOptional& other) {
        if (this != &other) box_ = other.box_ ? std::make_unique<T>(*other.box_) : nullptr;
        return *this;
    }
    BoxedOptional& operator=(BoxedOptional&&) noexcept = default;
    BoxedOptional& operator=(std::nullopt_t) {
        box_.reset();
        return *this;
    }
    BoxedOptional& operator=(const T& value) {
        if (box_)
            *box_ = value;
        else
            box_ = std::make_unique<T>(value);
        return *this;
    }
    BoxedOptional& operator=(T&& value) {
        if (box_)
            *box_ = std::move(value);
        else
            box_ = std::make_unique<T>(std::move(value));
        return *this;
    }

    bool has_value() const { return box_ != nullptr; }
    explicit operator bool() const { return box_ != nullptr; }
    // As std::optional: undefined when empty (value() throws instead).
    T& operator*() { return *box_; }
    const T& operator*() const { return *box_; }
    T* operator->() { return box_.get(); }
    const T* operator->() const { return box_.get(); }
    T& value() {
        if (!box_) throw std::bad_optional_access();
        return *box_;
    }
    const T& value() const {
        if (!box_) throw std::bad_optional_access();
        return *box_;
    }
    template <class... Args>
    T& emplace(Args&&... args) {
        box_ = std::make_unique<T>(std::forward<Args>(args)...);
        return *box_;
    }
    void reset() { box_.reset(); }
    // The value as a std::optional (a copy), for what takes one.
    std::optional<T> optional() const { return box_ ? std::optional<T>(*box_) : std::nullopt; }

  private:
    std::unique_ptr<T> box_;
};

}  // namespace hexant::runtime
