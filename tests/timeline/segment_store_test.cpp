// The timeline's segment store (timeline/segment_store.hpp): after any sequence of bake calls
// (appends), re-bakes from a time (truncations) and resets, each model's segments are those of a
// plain list per model put through the same operations, in the same order.
#include "timeline/segment_store.hpp"

#include <catch2/catch.hpp>

#include <random>
#include <vector>

using namespace animator;

namespace {

using Lists = std::vector<std::vector<ani_motion_segment>>;

// One bake call's segments: per model in time order from `from`, models interleaved as a bake
// reports them.
std::vector<ani_motion_segment> bake_call(std::mt19937_64 &rng, std::size_t models, double from, double until) {
    std::vector<ani_motion_segment> out;
    std::uniform_int_distribution<int> how_many(0, 4);
    std::vector<double> t(models, from);
    std::vector<int> left(models);
    int total = 0;
    for (auto &l : left) total += l = how_many(rng);
    std::uniform_int_distribution<std::size_t> pick(0, models - 1);
    while (total > 0) {
        const std::size_t m = pick(rng);
        if (left[m] == 0) continue;
        --left[m];
        --total;
        ani_motion_segment s{};
        s.model = static_cast<std::uint32_t>(m);
        s.t0 = t[m];
        s.t1 = left[m] == 0 ? until : t[m] + (until - t[m]) * 0.5;
        s.p0 = ani_vec3{s.t0, static_cast<double>(m), static_cast<double>(out.size())};
        t[m] = s.t1;
        out.push_back(s);
    }
    return out;
}

void same(const SegmentStore &store, const Lists &lists) {
    REQUIRE(store.models() == lists.size());
    std::size_t total = 0;
    for (std::size_t m = 0; m < lists.size(); ++m) {
        const SegmentSpan s = store[m];
        CAPTURE(m);
        REQUIRE(s.size() == lists[m].size());
        for (std::size_t k = 0; k < s.size(); ++k) {
            CHECK(s[k].t0 == lists[m][k].t0);
            CHECK(s[k].t1 == lists[m][k].t1);
            CHECK(s[k].p0.z == lists[m][k].p0.z);
        }
        total += s.size();
    }
    CHECK(store.segment_count() == total);
}

} // namespace

TEST_CASE("the segment store keeps each model's segments as a list per model would") {
    std::mt19937_64 rng(11);
    const std::size_t models = 300;
    SegmentStore store(models);
    Lists lists(models);
    double until = 0.0;
    for (int step = 0; step < 60; ++step) {
        CAPTURE(step);
        if (step % 7 == 6) { // a re-bake from an earlier time
            const double from = until * 0.6;
            store.truncate(from);
            for (auto &l : lists) {
                while (!l.empty() && l.back().t0 >= from) l.pop_back();
                if (!l.empty() && l.back().t1 > from) l.back().t1 = from;
            }
            until = from;
        }
        const double from = until;
        until += 0.25;
        const std::vector<ani_motion_segment> call = bake_call(rng, models, from, until);
        for (const auto &s : call) store.log(s);
        if (step % 5 == 4) { // a cancelled call: dropped from where it started, logged or filed
            store.truncate(from);
            until = from;
            same(store, lists);
            continue;
        }
        store.file();
        for (const auto &s : call) lists[s.model].push_back(s);
        same(store, lists);
    }
    // Runs moved to grow leave space behind; the store is compacted before that space passes
    // twice what is used (and a margin of 65,536 segments).
    CHECK(store.capacity() <= 2 * store.segment_count() + (std::size_t{1} << 16) + 5 * models);
    CHECK(store.logged() <= 2 * store.segment_count() + (std::size_t{1} << 16));
    // Through a bake's file and back.
    SegmentStore copy;
    copy.assign(store.lists());
    same(copy, lists);
    store.reset(models);
    same(store, Lists(models));
}

TEST_CASE("the segment store compacts once moved runs leave more space than they use") {
    // One segment per model per call, for many calls: every run outgrows its room again and
    // again; the array stays within a bound of what it holds.
    const std::size_t models = 20000;
    SegmentStore store(models);
    Lists lists(models);
    for (int call = 0; call < 40; ++call) {
        for (std::size_t m = 0; m < models; ++m) {
            ani_motion_segment s{};
            s.model = static_cast<std::uint32_t>(m);
            s.t0 = call;
            s.t1 = call + 1;
            s.p0.z = static_cast<double>(call * 100000 + static_cast<int>(m));
            store.log(s);
            lists[m].push_back(s);
        }
        store.file();
        CAPTURE(call, store.capacity(), store.segment_count());
        CHECK(store.capacity() <= 2 * store.segment_count() + (std::size_t{1} << 16) + 2 * models);
    }
    same(store, lists);
}

TEST_CASE("the segment store's log drops what re-bakes left behind, keeping every run's segments") {
    // Each call logs three segments per model over [call, call + 1] and the next re-bake keeps
    // only its first: more than 65,536 dropped segments a call, so the log is rebuilt (with the
    // call's segments not yet filed carried along) and stays within a bound of what is kept.
    const std::size_t models = 30000;
    SegmentStore store(models);
    Lists lists(models);
    for (int call = 0; call < 12; ++call) {
        for (int part = 0; part < 3; ++part)
            for (std::size_t m = 0; m < models; ++m) {
                ani_motion_segment s{};
                s.model = static_cast<std::uint32_t>(m);
                s.t0 = call + part / 3.0;
                s.t1 = call + (part + 1) / 3.0;
                s.p0.z = static_cast<double>((call * 3 + part) * 100000 + static_cast<int>(m));
                store.log(s);
                lists[m].push_back(s);
            }
        store.file();
        const double from = call + 1.0 / 3.0;
        store.truncate(from);
        for (auto &l : lists) {
            while (!l.empty() && l.back().t0 >= from) l.pop_back();
            if (!l.empty() && l.back().t1 > from) l.back().t1 = from;
        }
        CAPTURE(call, store.logged(), store.segment_count());
        CHECK(store.logged() <= 2 * store.segment_count() + 3 * models + (std::size_t{1} << 16));
    }
    same(store, lists);
    store.truncate(0.0); // a bake from the start: nothing kept, the log starts again
    CHECK(store.logged() == 0);
    same(store, Lists(models));
}
