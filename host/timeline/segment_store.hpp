// Every model's motion segments of a bake, in one array: each model's in a run of its own, in time
// order. A bake reports its segments model after model in time order, and at 100,000 balls a
// vector per model cost a hundred thousand allocations and about 4,000 page faults each bake
// (docs/performance.md, the gas); here a bake's segments are filed once per bake call (counted
// first, then written into runs sized for them) into one array in 2 MB pages. A run that must
// grow moves to the array's end with twice its capacity; the space it leaves is reused when the
// store is compacted, once more is left than used.
#pragma once

#include <animator/huge_pages.hpp>
#include <animator/physics.h>

#include <cstddef>
#include <cstdint>
#include <new>
#include <utility>
#include <vector>

namespace animator {

// A model's segments, read-only and contiguous (valid until the store changes).
class SegmentSpan {
  public:
    SegmentSpan() = default;
    SegmentSpan(const ani_motion_segment *begin, std::size_t size) : begin_(begin), size_(size) {}
    SegmentSpan(const std::vector<ani_motion_segment> &list) : begin_(list.data()), size_(list.size()) {}
    const ani_motion_segment *begin() const { return begin_; }
    const ani_motion_segment *end() const { return begin_ + size_; }
    std::size_t size() const { return size_; }
    bool empty() const { return size_ == 0; }
    const ani_motion_segment &operator[](std::size_t k) const { return begin_[k]; }
    const ani_motion_segment &front() const { return begin_[0]; }
    const ani_motion_segment &back() const { return begin_[size_ - 1]; }

  private:
    const ani_motion_segment *begin_ = nullptr;
    std::size_t size_ = 0;
};

class SegmentStore {
  public:
    explicit SegmentStore(std::size_t models = 0) : runs_(models) {}

    std::size_t models() const { return runs_.size(); }
    SegmentSpan operator[](std::size_t model) const {
        const Run &r = runs_[model];
        return SegmentSpan(pool_.data() + r.begin, r.size);
    }
    // Every segment, for tests and reports.
    std::size_t segment_count() const { return live_; }
    // The array's length in segments (used, reserved for growth, or left by runs that moved).
    std::size_t capacity() const { return pool_.size(); }

    // Empties the store for `models` models.
    void reset(std::size_t models);
    // Appends segments to their models' runs: `count[m]` segments for model m, then each given
    // by `each(put)` calling put(segment) in time order per model (the bake's order).
    template <class Each> void append(const std::vector<std::uint32_t> &count, Each &&each) {
        make_room(count);
        each([this](const ani_motion_segment &s) {
            Run &r = runs_[s.model];
            pool_[r.begin + r.size++] = s;
        });
    }
    // Drops every segment starting at `from` or later, and ends the one going on there at `from`.
    void truncate(double from);

    // As lists per model (a bake's file: timeline/bake_file.hpp), and back.
    std::vector<std::vector<ani_motion_segment>> lists() const;
    void assign(const std::vector<std::vector<ani_motion_segment>> &lists);

  private:
    struct Run {
        std::size_t begin = 0;
        std::uint32_t size = 0, capacity = 0;
    };
    static std::size_t room_for(const Run &r, std::uint32_t more);
    // Runs with room for `count` more segments each (live_ counts them).
    void make_room(const std::vector<std::uint32_t> &count);
    void compact_with(const std::vector<std::uint32_t> &count);

    // The pool's allocator leaves the room a resize adds unwritten (std::vector would zero it):
    // every segment in it is written before it is read, and zeroing the room first cost a quarter
    // as much as filing a bake's segments (docs/performance.md, the gas).
    template <class T> struct Unwritten : ani::HugePageAllocator<T> {
        template <class U> struct rebind {
            using other = Unwritten<U>;
        };
        Unwritten() = default;
        template <class U> Unwritten(const Unwritten<U> &) {}
        template <class U> void construct(U *p) noexcept { ::new (static_cast<void *>(p)) U; }
        template <class U, class... A> void construct(U *p, A &&...a) {
            ::new (static_cast<void *>(p)) U(std::forward<A>(a)...);
        }
    };
    using Pool = std::vector<ani_motion_segment, Unwritten<ani_motion_segment>>;

    std::vector<Run> runs_;
    Pool pool_;
    std::size_t live_ = 0;
};

} // namespace animator
