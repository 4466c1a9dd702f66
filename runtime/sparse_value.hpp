// A value of T that takes 8 bytes while it is T's default: reads see one
// shared default until the first write (edit(), or an assignment) gives the
// holder its own. For a large member most records leave at its default: a
// pigment's, a normal's or a texture's pattern (288 bytes; a plain colour
// has none), which every object record of a scene of 10^5 spheres paid
// twice (issue 43's memory). Copies copy the value (not shared), so a
// record's copy is changed on its own, as a plain member's.
#pragma once

#include <memory>
#include <utility>

namespace hexant::runtime {

template <class T>
class SparseValue {
  public:
    SparseValue() = default;
    SparseValue(const T& value) : box_(std::make_unique<T>(value)) {}
    SparseValue(T&& value) : box_(std::make_unique<T>(std::move(value))) {}
    SparseValue(const SparseValue& other)
        : box_(other.box_ ? std::make_unique<T>(*other.box_) : nullptr) {}
    SparseValue(SparseValue&&) noexcept = default;
    SparseValue& operator=(const SparseValue& other) {
        if (this != &other) box_ = other.box_ ? std::make_unique<T>(*other.box_) : nullptr;
        return *this;
    }
    SparseValue& operator=(SparseValue&&) noexcept = default;
    SparseValue& operator=(const T& value) {
        edit() = value;
        return *this;
    }
    SparseValue& operator=(T&& value) {
        edit() = std::move(value);
        return *this;
    }

    const T& get() const { return box_ ? *box_ : fallback(); }
    const T& operator*() const { return get(); }
    const T* operator->() const { return &get(); }
    operator const T&() const { return get(); }
    // The holder's own value, made from the default on the first write.
    T& edit() {
        if (!box_) box_ = std::make_unique<T>();
        return *box_;
    }

  private:
    static const T& fallback() {
        static const T value{};
        return value;
    }
    std::unique_ptr<T> box_;
};

}  // namespace hexant::runtime
