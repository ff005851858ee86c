// A gas lane's report made on another core: the lane hands each segment and collision to a ring,
// and a thread of its own reports them to the sink it wraps (to the host, which logs them), in
// the order they were given. A gas reports two segments and a collision at each of its
// events, and reported on the lane's thread they were a fifth of its bake (docs/performance.md,
// the gas); so the lane goes on with its next event while they are reported beside it. Progress
// (which may cancel the bake) is reported on the lane's thread, as before.
#pragma once

#include "gas_lane.hpp"

#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <exception>
#include <functional>
#include <memory>
#include <mutex>
#include <thread>

namespace physics_custom {

// Asks for the cache line at p, to be written (PREFETCHW; where the processor lacks it, a no-op;
// __builtin_prefetch(p, 1) gives a prefetch to read unless the whole build targets it).
inline void prefetch_to_write(const void *p) {
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
    asm volatile("prefetchw %0" : : "m"(*static_cast<const char *>(p)));
#else
    __builtin_prefetch(p, 1);
#endif
}

class SinkAside final : public GasLane::Sink {
  public:
    // Reports to `to` on a thread of its own (or here, where no thread can be had or the
    // machine has one core). That thread also does `meanwhile`, a piece at a time, whenever it
    // has nothing to report, until it returns true (done: meanwhile_done()); a piece must be
    // short (well under the few milliseconds of a gas's report that the rings hold).
    explicit SinkAside(GasLane::Sink &to, std::function<bool()> meanwhile = {});
    // Stops the thread (what is handed over and not yet reported is reported first).
    ~SinkAside() override;
    SinkAside(const SinkAside &) = delete;
    SinkAside &operator=(const SinkAside &) = delete;

    void segment(const ani_motion_segment &s) override {
        if (!thread_.joinable()) return to_.segment(s);
        segments_.push(s, *this);
    }
    void collision(const ani_collision_event &e) override {
        if (!thread_.joinable()) return to_.collision(e);
        collisions_.push(e, *this);
    }
    // (Here: what has been handed over is made visible to the thread first, and a failure of
    // the thread thrown.)
    void progress(double now) override;
    // Waits until everything handed over has been reported; throws what the thread's report
    // threw. Segments and collisions after it are reported here.
    void finish();
    // Whether `meanwhile` was done to the end (read after finish()).
    bool meanwhile_done() const { return meanwhile_done_; }

  private:
    // A ring of what one thread writes and the other reads, in order.
    template <class T, std::size_t N> struct Ring {
        static_assert((N & (N - 1)) == 0, "a power of two");
        static constexpr std::size_t kSize = N;
        std::unique_ptr<T[]> slot{new T[N]};
        alignas(64) std::atomic<std::size_t> published{0};   // written by the lane
        alignas(64) std::atomic<std::size_t> taken{0};       // by the reporting thread
        alignas(64) std::size_t written = 0, room_until = N; // the lane's own
        // (The reporting thread's own, on a line of its own: on the lane's line, each report
        // took that line from the lane.)
        alignas(64) std::size_t read = 0;

        void push(const T &value, SinkAside &owner) {
            if (written == room_until) owner.wait_for_room(*this);
            slot[written & (N - 1)] = value;
            // (The slot 8 ahead asked for, to be written: the other core read it last.)
            prefetch_to_write(&slot[(written + 8) & (N - 1)]);
            if ((++written & (kBatch - 1)) == 0) owner.publish();
        }
        // Reports what has been published and not yet reported; whether there was any.
        template <class F> bool drain(F &&report) {
            const std::size_t until = published.load(std::memory_order_acquire);
            if (until == read) return false;
            while (read != until) report(slot[read++ & (N - 1)]); // (past one that throws)
            taken.store(read, std::memory_order_release);
            return true;
        }
        bool pending() const { return published.load(std::memory_order_acquire) != read; }
    };
    // Published every kBatch of a kind (and at each progress report).
    static constexpr std::size_t kBatch = 16;

    void publish();
    template <class R> void wait_for_room(R &ring); // (made for both rings in sink_aside.cpp)
    void report(); // the thread's loop
    void stop();   // (the thread ends once it has reported everything)
    void throw_if_failed() const; // what the thread's report threw, if it threw

    GasLane::Sink &to_;
    std::function<bool()> meanwhile_;
    bool meanwhile_left_, meanwhile_done_; // (the thread's own until it is joined)
    using Segments = Ring<ani_motion_segment, 8192>;
    using Collisions = Ring<ani_collision_event, 4096>;
    Segments segments_;
    Collisions collisions_;
    std::atomic<bool> stop_{false}, failed_{false};
    std::exception_ptr failure_; // the thread's report's, written before failed_
    std::mutex lock_;
    std::condition_variable wake_;
    std::thread thread_;
};

} // namespace physics_custom
