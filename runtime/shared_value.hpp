// A value of T shared between copies until one of them is written: copies
// share one block (a pointer each), reads see T's default while there is
// none, and edit() gives the holder a block of its own first when others
// share it (copy on write). For a large member that many records hold with
// the same numbers: a finish (280 bytes), which every sphere of a scene of
// 10^5 spheres paid while its records were alive (issue 43's memory; equal
// finishes are made one block by FinishPool, finish_pool.hpp).
//
// Not thread-safe to edit (use_count decides whether to copy): records are
// written by the one thread that reads the scene, and only read after.
#pragma once

#include <memory>
#include <utility>

namespace hexant::runtime {

template <class T>
class SharedValue {
  public:
    SharedValue() = default;
    SharedValue(const T& value) : block_(std::make_shared<T>(value)) {}
    SharedValue(T&& value) : block_(std::make_shared<T>(std::move(value))) {}
    explicit SharedValue(std::shared_ptr<T> block) : block_(std::move(block)) {}
    SharedValue& operator=(const T& value) {
        block_ = std::make_shared<T>(value);
        return *this;
    }
    SharedValue& operator=(T&& value) {
        block_ = std::make_shared<T>(std::move(value));
        return *this;
    }
    SharedValue& operator=(std::shared_ptr<T> block) {
        block_ = std::move(block);
        return *this;
    }

    const T& get() const { return block_ ? *block_ : fallback(); }
    const T& operator*() const { return get(); }
    const T* operator->() const { return &get(); }
    operator const T&() const { return get(); }
    // The block read, null while the value is the default (to tell whether
    // two holders share one).
    const T* block() const { return block_.get(); }

    // The holder's own value: a copy of the shared one (or of the default)
    // made first unless this holder is its only owner.
    T& edit() {
        if (!block_ || block_.use_count() > 1) block_ = std::make_shared<T>(get());
        return *block_;
    }

  private:
    static const T& fallback() {
        static const T value{};
        return value;
    }
    // Never written through while shared (edit() copies first).
    std::shared_ptr<T> block_;
};

}  // namespace hexant::runtime
