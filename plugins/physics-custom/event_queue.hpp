// The event queue of the event-driven bake: an indexed binary min-heap holding one time per body,
// the time of that body's earliest predicted event. Updating a body's time is O(log n) in place;
// ties go to the lower body index, so a bake is deterministic.
#pragma once

#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

namespace physics_custom {

class EventQueue {
  public:
    explicit EventQueue(std::size_t n)
        : time_(n, std::numeric_limits<double>::infinity()), heap_(n), slot_(n) {
        for (std::size_t i = 0; i < n; ++i) heap_[i] = slot_[i] = i;
    }

    // The body whose event comes first, and its time.
    std::size_t top() const { return heap_[0]; }
    double top_time() const {
        return heap_.empty() ? std::numeric_limits<double>::infinity() : time_[heap_[0]];
    }
    double time(std::size_t body) const { return time_[body]; }

    void set(std::size_t body, double t) {
        const double old = time_[body];
        time_[body] = t;
        if (t < old)
            up(slot_[body]);
        else
            down(slot_[body]);
    }

  private:
    bool before(std::size_t a, std::size_t b) const {
        return time_[a] < time_[b] || (time_[a] == time_[b] && a < b);
    }
    void place(std::size_t at, std::size_t body) {
        heap_[at] = body;
        slot_[body] = at;
    }
    void up(std::size_t at) {
        const std::size_t body = heap_[at];
        while (at > 0) {
            const std::size_t parent = (at - 1) / 2;
            if (!before(body, heap_[parent])) break;
            place(at, heap_[parent]);
            at = parent;
        }
        place(at, body);
    }
    void down(std::size_t at) {
        const std::size_t body = heap_[at], n = heap_.size();
        while (true) {
            std::size_t child = 2 * at + 1;
            if (child >= n) break;
            if (child + 1 < n && before(heap_[child + 1], heap_[child])) ++child;
            if (!before(heap_[child], body)) break;
            place(at, heap_[child]);
            at = child;
        }
        place(at, body);
    }

    std::vector<double> time_;
    std::vector<std::size_t> heap_; // bodies, heap-ordered by time
    std::vector<std::size_t> slot_; // where each body is in heap_
};

} // namespace physics_custom
