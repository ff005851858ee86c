// The gas lane's report made on another core (plugins/physics-custom/sink_aside.hpp): what the
// lane hands over reaches the sink it wraps in the order given and all of it, on a thread of its
// own; a failure there is thrown on the lane's thread; a cancel leaves nothing running.
#include "sink_aside.hpp"

#include <catch2/catch.hpp>

#include <atomic>
#include <chrono>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

using physics_custom::GasLane;
using physics_custom::SinkAside;

namespace {

// Writes down what it is given, and on which thread; throws at a given segment or progress.
struct Recorder final : GasLane::Sink {
    std::vector<uint32_t> segments, collisions;
    std::vector<double> times;
    std::thread::id segment_thread, progress_thread;
    std::size_t fail_at_segment = ~std::size_t{0}, cancel_at_progress = ~std::size_t{0};
    std::size_t progresses = 0;
    void segment(const ani_motion_segment &s) override {
        segment_thread = std::this_thread::get_id();
        if (segments.size() == fail_at_segment)
            throw std::runtime_error("segment " + std::to_string(s.model) + " is not finite");
        segments.push_back(s.model);
        times.push_back(s.t1);
    }
    void collision(const ani_collision_event &e) override { collisions.push_back(e.a); }
    void progress(double) override {
        progress_thread = std::this_thread::get_id();
        if (progresses++ == cancel_at_progress) throw std::runtime_error("cancelled");
    }
};

ani_motion_segment segment(uint32_t k) {
    ani_motion_segment s{};
    s.model = k;
    s.t1 = 0.5 * k;
    return s;
}

ani_collision_event collision(uint32_t k) {
    ani_collision_event e{};
    e.a = k;
    return e;
}

// What a lane's run hands over: two segments and a collision an event, progress every 1024
// events.
void run(GasLane::Sink &sink, uint32_t events) {
    for (uint32_t k = 0; k < events; ++k) {
        sink.segment(segment(2 * k));
        sink.segment(segment(2 * k + 1));
        sink.collision(collision(k));
        if ((k + 1) % 1024 == 0) sink.progress(k);
    }
}

} // namespace

TEST_CASE("the gas lane's report made aside comes in the order given, all of it, beside the lane") {
    Recorder to;
    {
        SinkAside aside(to);
        run(aside, 100000); // (far more than its rings hold: the lane waits for room at times)
        aside.finish();
        // Everything reported once finish() returns, each kind in the order given.
        REQUIRE(to.segments.size() == 200000);
        REQUIRE(to.collisions.size() == 100000);
        for (uint32_t k = 0; k < 200000; ++k) {
            if (to.segments[k] != k || to.times[k] != 0.5 * k)
                FAIL("segment " << k << " out of order");
        }
        for (uint32_t k = 0; k < 100000; ++k) {
            if (to.collisions[k] != k) FAIL("collision " << k << " out of order");
        }
        // After finish(), reported here.
        aside.segment(segment(7));
        CHECK(to.segments.back() == 7);
        CHECK(to.segment_thread == std::this_thread::get_id());
    }
    // Progress (which may cancel) on the lane's thread; the rest on another, where there is one.
    Recorder beside;
    SinkAside aside(beside);
    run(aside, 5000);
    aside.finish();
    CHECK(beside.progress_thread == std::this_thread::get_id());
    if (std::thread::hardware_concurrency() >= 2)
        CHECK(beside.segment_thread != std::this_thread::get_id());
    CHECK(beside.segments.size() == 10000);
}

TEST_CASE("a failure of the report made aside is thrown on the lane's thread") {
    Recorder to;
    to.fail_at_segment = 5000;
    SinkAside aside(to);
    // Thrown at the lane's next progress report (or when it finishes), with its message.
    CHECK_THROWS_WITH(run(aside, 20000), "segment 5000 is not finite");
    CHECK(to.segments.size() == 5000); // nothing reported after it
    Recorder late;
    late.fail_at_segment = 10;
    SinkAside aside_late(late);
    for (uint32_t k = 0; k < 100; ++k) aside_late.segment(segment(k));
    CHECK_THROWS_WITH(aside_late.finish(), "segment 10 is not finite");
    CHECK(late.segments.size() == 10);
}

TEST_CASE("a cancel of a lane reporting aside leaves nothing running and nothing unreported") {
    Recorder to;
    to.cancel_at_progress = 3;
    {
        SinkAside aside(to);
        CHECK_THROWS_WITH(run(aside, 100000), "cancelled");
    } // (its thread stopped here, once everything handed over is reported)
    // The lane stopped at its fourth progress report, after 4 x 1024 events.
    CHECK(to.segments.size() == 2 * 4 * 1024);
    CHECK(to.collisions.size() == 4 * 1024);
}

TEST_CASE(
    "the thread reporting aside does other work meanwhile, a piece at a time, when it waits") {
    Recorder to;
    std::thread::id worker;
    int pieces = 0;
    std::atomic<bool> all_done{false};
    {
        SinkAside aside(to, [&] {
            worker = std::this_thread::get_id();
            all_done = ++pieces == 50;
            return all_done.load();
        });
        run(aside, 3000);
        // (Waits a little for the thread to have nothing to report, as a lane between events.)
        for (int k = 0; k < 1000 && !all_done; ++k)
            std::this_thread::sleep_for(std::chrono::microseconds(100));
        aside.finish();
        CHECK(to.segments.size() == 6000); // its report still whole
        if (std::thread::hardware_concurrency() >= 2) {
            CHECK(aside.meanwhile_done());
            CHECK(pieces == 50); // not one piece after it said it was done
            CHECK(worker != std::this_thread::get_id());
        } else {
            CHECK_FALSE(aside.meanwhile_done()); // left to its owner
        }
    }
    // Stopped before it is done, it is left undone (its owner does the rest).
    Recorder quick;
    std::atomic<int> done_pieces{0};
    SinkAside slow(quick, [&] {
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
        return ++done_pieces == 1000000;
    });
    slow.finish();
    CHECK_FALSE(slow.meanwhile_done());
    CHECK(done_pieces < 1000000);
}
