// The calendar queue (calendar_queue.hpp).
#include "calendar_queue.hpp"

#include <algorithm>

namespace physics_custom {

void CalendarQueue::init(const double *times, std::size_t n, double now, double per_bucket) {
    double sum = 0.0;
    std::size_t finite = 0;
    for (std::size_t i = 0; i < n; ++i)
        if (times[i] < 1e300) sum += times[i] - now, ++finite;
    // Events come at about n / mean(time from now) per unit time; the ring spans 8 mean times.
    const double mean = finite ? sum / static_cast<double>(finite) : 1.0;
    width_ = mean > 0.0 ? per_bucket * mean / static_cast<double>(n) : 1.0;
    ring_ = std::max<std::size_t>(
        16, static_cast<std::size_t>(8.0 * static_cast<double>(n) / per_bucket));
    heap_.reserve(n);
    slot_.assign(n, Slot{std::numeric_limits<double>::infinity(), 0, kNone});
    next_.assign(n, kNone);
    head_.assign(ring_ + 1, kNone);
    base_ = std::max<std::int64_t>(bucket(now), 0);
    for (std::uint32_t i = 0; i < n; ++i) insert(i, times[i]);
}

void CalendarQueue::link(std::uint32_t i, std::size_t list) {
    slot_[i].where = -1 - static_cast<std::int32_t>(list);
    slot_[i].prev = kNone;
    next_[i] = head_[list];
    if (next_[i] != kNone) slot_[next_[i]].prev = i;
    head_[list] = i;
    ++listed_;
    far_ += list == ring_;
}

void CalendarQueue::unlink(std::uint32_t i) {
    const std::size_t list = static_cast<std::size_t>(-1 - slot_[i].where);
    if (slot_[i].prev != kNone)
        next_[slot_[i].prev] = next_[i];
    else
        head_[list] = next_[i];
    if (next_[i] != kNone) slot_[next_[i]].prev = slot_[i].prev;
    --listed_;
    far_ -= list == ring_;
}

void CalendarQueue::insert(std::uint32_t i, double time) {
    slot_[i].time = time;
    const std::int64_t b = bucket(time);
    if (b <= base_) {
        heap_.emplace_back();
        sift(heap_.size() - 1, {time, i});
    } else if (b < base_ + static_cast<std::int64_t>(ring_)) {
        link(i, static_cast<std::size_t>(b % static_cast<std::int64_t>(ring_)));
    } else {
        link(i, ring_);
    }
}

void CalendarQueue::update(std::uint32_t i, double time) {
    if (slot_[i].where >= 0) { // in the heap: take it out (the last entry fills its place)
        const std::size_t k = static_cast<std::size_t>(slot_[i].where);
        if (bucket(time) <= base_) {
            slot_[i].time = time;
            sift(k, {time, i});
            return;
        }
        const Entry last = heap_.back();
        heap_.pop_back();
        if (k < heap_.size()) sift(k, last);
    } else {
        unlink(i);
    }
    insert(i, time);
}

// The heap is empty: the next bucket's events go into it. Once per turn of the ring, the far
// list's events that are now within the ring move into it.
bool CalendarQueue::next_bucket() {
    const auto ring = static_cast<std::int64_t>(ring_);
    if (listed_ == far_) { // the ring is empty: on to the turn of the far list's earliest
        std::int64_t first = kNever;
        for (std::uint32_t k = head_[ring_]; k != kNone; k = next_[k])
            first = std::min(first, bucket(slot_[k].time));
        if (first >= kNever) return false;
        base_ = std::max(base_, first / ring * ring - 1);
    }
    ++base_;
    if (base_ % ring == 0) {
        std::uint32_t k = head_[ring_];
        head_[ring_] = kNone;
        listed_ -= far_;
        far_ = 0;
        while (k != kNone) {
            const std::uint32_t next = next_[k];
            insert(k, slot_[k].time);
            k = next;
        }
    }
    const auto list = static_cast<std::size_t>(base_ % ring);
    std::uint32_t k = head_[list];
    head_[list] = kNone;
    while (k != kNone) {
        const std::uint32_t next = next_[k];
        --listed_;
        heap_.emplace_back();
        sift(heap_.size() - 1, {slot_[k].time, k});
        k = next;
    }
    return true;
}

// Moves `moved` from heap slot k up or down to its place.
void CalendarQueue::sift(std::size_t k, Entry moved) {
    while (k > 0) {
        const std::size_t up = (k - 1) / 2;
        if (!moved.before(heap_[up])) break;
        heap_[k] = heap_[up];
        slot_[heap_[k].item].where = static_cast<std::int32_t>(k);
        k = up;
    }
    const std::size_t size = heap_.size();
    for (;;) {
        std::size_t down = 2 * k + 1;
        if (down >= size) break;
        if (down + 1 < size && heap_[down + 1].before(heap_[down])) ++down;
        if (!heap_[down].before(moved)) break;
        heap_[k] = heap_[down];
        slot_[heap_[k].item].where = static_cast<std::int32_t>(k);
        k = down;
    }
    heap_[k] = moved;
    slot_[moved.item].where = static_cast<std::int32_t>(k);
}

} // namespace physics_custom
