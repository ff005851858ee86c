// A calendar queue of event times, one per item (a sphere), for the event-driven gases: the gas
// lane of physics.custom (gas_lane.hpp) and the benchmark's reference gas. Brown, Commun. ACM 31,
// 1220 (1988), in the form event-driven codes use: times in buckets of width `width_`, those of
// the current bucket in a small binary heap, those of the next `ring_` buckets in unsorted
// lists, later ones in one far list spread into the ring once per turn. Updating an item is O(1)
// on average when a bucket holds a few events; ties go to the lower item, so a run is
// deterministic. Nothing is allocated after init.
#pragma once

#include <animator/huge_pages.hpp>

#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

namespace physics_custom {

class CalendarQueue {
  public:
    // Every item's time (times[0, n); infinite: none), none before `now`; `per_bucket`: about
    // how many events a bucket holds.
    void init(const double *times, std::size_t n, double now, double per_bucket = 16.0);
    // The earliest time (infinite when there is none), and its item.
    double top_time() {
        while (heap_.empty())
            if (!next_bucket()) return std::numeric_limits<double>::infinity();
        return heap_[0].time;
    }
    std::uint32_t top() const { return heap_[0].item; }
    // The item after the top in its bucket (kNone when the top is alone there): the next event's
    // unless the top's update comes before it. (For fetching its records ahead.)
    std::uint32_t second() const {
        const std::size_t n = heap_.size();
        if (n < 2) return kNone;
        return n == 2 || heap_[1].before(heap_[2]) ? heap_[1].item : heap_[2].item;
    }
    void update(std::uint32_t i, double time);
    // Asks for item i's place to be fetched from memory (it is about to be updated).
    void fetch(std::uint32_t i) const { __builtin_prefetch(&slot_[i]); }

  private:
    struct Entry {
        double time;
        std::uint32_t item;
        bool before(const Entry &o) const {
            return time < o.time || (time == o.time && item < o.item);
        }
    };
    static constexpr std::uint32_t kNone = 0xffffffffu;
    static constexpr std::int64_t kNever = std::int64_t{1} << 62;
    std::int64_t bucket(double t) const {
        const double b = t / width_;
        return b < 4e18 ? static_cast<std::int64_t>(b) : kNever;
    }
    bool next_bucket(); // false when every time left is infinite
    void insert(std::uint32_t i, double time);
    void link(std::uint32_t i, std::size_t list);
    void unlink(std::uint32_t i);
    void sift(std::size_t k, Entry moved);

    double width_ = 1.0;
    std::int64_t base_ = 0;            // the heap's bucket
    std::size_t ring_ = 1;             // buckets in the ring
    std::size_t listed_ = 0, far_ = 0; // items in lists, in the far list
    ani::HugeVector<Entry> heap_; // room for every item reserved: it never allocates
    // Each item's time, where it is (its heap slot, or -1 - its list; ring_: the far list), and
    // its neighbour before it in its list: together, one cache miss per item touched, not three.
    // The neighbour after it apart, in an array of 4 bytes an item that stays in the processor's
    // cache: a bucket's list is walked one item after another (each next read from the last),
    // and each step was a cache miss when the links were in the slots.
    struct Slot {
        double time;
        std::int32_t where;
        std::uint32_t prev;
    };
    ani::HugeVector<Slot> slot_;
    ani::HugeVector<std::uint32_t> next_;
    ani::HugeVector<std::uint32_t> head_; // each list's first item
};

} // namespace physics_custom
