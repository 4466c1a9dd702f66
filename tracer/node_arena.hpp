// Where a hierarchy's nodes live: 64-byte aligned blocks that never move,
// one run of blocks per thread, so that a parallel or lazy build allocates
// without a lock. Everything is freed with the arena (a hierarchy has one
// for its lasting part and one per slab it holds: hierarchy.hpp). Nodes are plain data;
// the pending cells of a lazy build (which own vectors) are kept apart and
// destroyed properly.
//
// The blocks are mapped from the system (mmap), not taken from the heap:
// a slab let go returns its nodes' memory at once, where heap blocks stayed
// among the smaller allocations made since and the heap grew as slabs came
// and went (swarm 10^5, 16 frames: 10 MB more at the peak, docs/benchmarks.md, "Scale: the swarm").
#pragma once

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <new>
#include <vector>

#include <sys/mman.h>
#include <tbb/enumerable_thread_specific.h>

namespace hexant::tracer {

class NodeArena {
  public:
    NodeArena() = default;
    NodeArena(const NodeArena&) = delete;
    NodeArena& operator=(const NodeArena&) = delete;
    ~NodeArena() {
        for (auto& blocks : blocks_)
            for (void* b : blocks.list) munmap(b, kBlock);
    }

    // Zeroed, 64-byte aligned storage for one T (a plain node type).
    template <class T>
    T* make() {
        static_assert(alignof(T) <= kAlign && sizeof(T) <= kBlock &&
                      std::is_trivially_destructible_v<T>);
        void* p = allocate(sizeof(T));
        return new (p) T{};
    }

    // Owned objects with destructors (a lazy build's pending cells).
    template <class T, class... Args>
    T* own(Args&&... args) {
        auto& list = owned_.local();
        list.push_back(std::make_shared<T>(std::forward<Args>(args)...));
        return static_cast<T*>(list.back().get());
    }

    // The cells built into this arena (for statistics: a full build's count).
    void count_cell() { cells_.fetch_add(1, std::memory_order_relaxed); }
    std::uint64_t cells() const { return cells_.load(std::memory_order_relaxed); }

    // Bytes held in node blocks (what the hierarchy costs in memory).
    std::size_t bytes() const {
        std::size_t total = 0;
        for (const auto& blocks : blocks_) total += blocks.list.size() * kBlock;
        return total;
    }

  private:
    static constexpr std::size_t kAlign = 64;
    static constexpr std::size_t kBlock = 64 * 1024;
    struct Blocks {
        std::vector<void*> list;
        std::size_t used = kBlock;  // of the last block
    };

    void* allocate(std::size_t bytes) {
        bytes = (bytes + kAlign - 1) / kAlign * kAlign;
        Blocks& b = blocks_.local();
        if (b.used + bytes > kBlock) {
            // Room first, so that a mapped block is always recorded.
            if (b.list.size() == b.list.capacity())
                b.list.reserve(std::max<std::size_t>(8, 2 * b.list.size()));
            // Page-aligned (so 64-byte aligned) and zeroed.
            void* p =
                mmap(nullptr, kBlock, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
            if (p == MAP_FAILED) throw std::bad_alloc();
            b.list.push_back(p);
            b.used = 0;
        }
        void* p = static_cast<char*>(b.list.back()) + b.used;
        b.used += bytes;
        return p;
    }

    tbb::enumerable_thread_specific<Blocks> blocks_;
    std::atomic<std::uint64_t> cells_{0};
    tbb::enumerable_thread_specific<std::vector<std::shared_ptr<void>>> owned_;
};

}  // namespace hexant::tracer
