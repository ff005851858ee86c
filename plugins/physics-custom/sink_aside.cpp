// The gas lane's report made on another core (sink_aside.hpp).
#include "sink_aside.hpp"

#include <chrono>
#include <system_error>
#include <utility>
#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#endif

namespace physics_custom {

namespace {
void pause() {
#if defined(__x86_64__) || defined(__i386__)
    _mm_pause();
#else
    std::this_thread::yield();
#endif
}
// How many times the reporting thread looks for more before it sleeps, and how long it sleeps
// before it looks again: it reports what has come in batches of half a millisecond (the rings
// hold several), so that it takes little of its core from whatever else runs there (spinning for
// a millisecond at a time, it made no bake faster). The lane does not wake it, which would cost
// a fence at every batch, unless it finds a ring full or is done.
constexpr int kSpins = 1 << 6;
constexpr auto kNap = std::chrono::microseconds(500);
} // namespace

SinkAside::SinkAside(GasLane::Sink &to, std::function<bool()> meanwhile)
    : to_(to), meanwhile_(std::move(meanwhile)), meanwhile_left_(bool(meanwhile_)),
      meanwhile_done_(!meanwhile_) {
    if (std::thread::hardware_concurrency() < 2) return;
    try {
        thread_ = std::thread([this] { report(); });
    } catch (const std::system_error &) {
    }
}

SinkAside::~SinkAside() {
    stop();
}

void SinkAside::stop() {
    if (!thread_.joinable()) return;
    publish();
    {
        std::lock_guard<std::mutex> hold(lock_);
        stop_.store(true, std::memory_order_release);
        wake_.notify_one();
    }
    thread_.join();
}

void SinkAside::finish() {
    stop();
    throw_if_failed();
}

void SinkAside::progress(double now) {
    if (thread_.joinable()) {
        publish();
        throw_if_failed();
    }
    to_.progress(now);
}

void SinkAside::throw_if_failed() const {
    if (failed_.load(std::memory_order_acquire)) std::rethrow_exception(failure_);
}

void SinkAside::publish() {
    segments_.published.store(segments_.written, std::memory_order_release);
    collisions_.published.store(collisions_.written, std::memory_order_release);
}

template <class R> void SinkAside::wait_for_room(R &ring) {
    // The room the thread's reports have made since the lane last looked: nearly always some
    // (the lane looks only when it has written up to what it knew of). Only a ring truly full
    // wakes the thread: waking it each time cost a system call, 1.5% of a 10,000-ball bake.
    const auto room = [&ring] {
        ring.room_until = ring.taken.load(std::memory_order_acquire) + R::kSize;
        return ring.room_until != ring.written;
    };
    if (room()) return;
    publish();
    {
        std::lock_guard<std::mutex> hold(lock_);
        wake_.notify_one();
    }
    for (int spins = 0;; ++spins) {
        throw_if_failed();
        if (room()) return;
        if (spins < kSpins)
            pause();
        else
            std::this_thread::yield();
    }
}

// (Made here for both rings: the header's push() calls them, in every file that hands a segment
// or collision over.)
template void SinkAside::wait_for_room(Segments &);
template void SinkAside::wait_for_room(Collisions &);

void SinkAside::report() {
    // After a report throws, the rest is taken and not reported (the lane throws it at its next
    // progress report, or when it finishes).
    bool reporting = true;
    const auto segment = [&](const ani_motion_segment &s) {
        if (reporting) to_.segment(s);
    };
    const auto collision = [&](const ani_collision_event &e) {
        if (reporting) to_.collision(e);
    };
    for (int idle = 0;;) {
        bool any = false;
        try {
            any = segments_.drain(segment);
            any = collisions_.drain(collision) || any;
        } catch (...) {
            failure_ = std::current_exception();
            failed_.store(true, std::memory_order_release);
            reporting = false;
            continue;
        }
        if (any) {
            idle = 0;
            continue;
        }
        // (The lane publishes before it stops: once stop_ is seen, what is published is all.)
        if (stop_.load(std::memory_order_acquire)) {
            if (segments_.pending() || collisions_.pending()) continue;
            return;
        }
        if (meanwhile_left_) { // (a piece, then a look at the rings again)
            try {
                meanwhile_done_ = meanwhile_();
                meanwhile_left_ = !meanwhile_done_;
            } catch (...) { // (left undone: its owner sees to it)
                meanwhile_left_ = false;
            }
            continue;
        }
        if (++idle < kSpins) {
            pause();
            continue;
        }
        std::unique_lock<std::mutex> hold(lock_);
        wake_.wait_for(hold, kNap, [&] {
            return stop_.load(std::memory_order_acquire) || segments_.pending() ||
                   collisions_.pending();
        });
        idle = 0;
    }
}

} // namespace physics_custom
