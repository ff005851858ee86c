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
        std::vector<std::uint32_t> count(models, 0);
        for (const auto &s : call) ++count[s.model];
        store.append(count, [&](auto &&put) {
            for (const auto &s : call) put(s);
        });
        for (const auto &s : call) lists[s.model].push_back(s);
        same(store, lists);
    }
    // Runs moved to grow leave space behind; the store is compacted before that space passes
    // twice what is used (and a margin of 65,536 segments).
    CHECK(store.capacity() <= 2 * store.segment_count() + (std::size_t{1} << 16) + 5 * models);
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
    std::vector<std::uint32_t> count(models, 1);
    for (int call = 0; call < 40; ++call) {
        store.append(count, [&](auto &&put) {
            for (std::size_t m = 0; m < models; ++m) {
                ani_motion_segment s{};
                s.model = static_cast<std::uint32_t>(m);
                s.t0 = call;
                s.t1 = call + 1;
                s.p0.z = static_cast<double>(call * 100000 + static_cast<int>(m));
                put(s);
                lists[m].push_back(s);
            }
        });
        CAPTURE(call, store.capacity(), store.segment_count());
        CHECK(store.capacity() <= 2 * store.segment_count() + (std::size_t{1} << 16) + 2 * models);
    }
    same(store, lists);
}
