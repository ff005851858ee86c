// evaluate receives sorted times and sweeps the keys once: many times at once give exactly what
// each time alone gives.
#include "interp_support.hpp"

#include "segments.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <thread>

using namespace interp_test;

TEST_CASE("SegmentSweep locates sorted times before, at, inside and after the keys") {
    const std::vector<ani_key> keys = {key(1, {}), key(2, {}), key(4, {})};
    interp::SegmentSweep sweep(keys.data(), 3);
    auto at = sweep.locate(0.5);
    CHECK(at.kind == interp::Location::before);
    at = sweep.locate(1.0);
    CHECK((at.kind == interp::Location::at_key && at.key == 0));
    at = sweep.locate(1.5);
    CHECK((at.kind == interp::Location::inside && at.key == 0 && at.tau == 0.5));
    at = sweep.locate(1.5); // a repeated time
    CHECK((at.kind == interp::Location::inside && at.key == 0));
    at = sweep.locate(3.0); // skips key 1's time
    CHECK((at.kind == interp::Location::inside && at.key == 1 && at.tau == 1.0));
    at = sweep.locate(4.0);
    CHECK((at.kind == interp::Location::at_key && at.key == 2));
    at = sweep.locate(9.0);
    CHECK(at.kind == interp::Location::after);
    CHECK_THROWS(sweep.locate(3.0));
}

TEST_CASE("evaluating 100000 sorted times at once equals evaluating each alone") {
    std::mt19937 rng(314);
    std::uniform_real_distribution<double> gap(0.05, 1.5), value(0.0, 359.0);
    std::normal_distribution<double> normal(0.0, 1.0);
    std::vector<ani_key> keys;
    std::vector<ani_key> rotations;
    double t = -2.0;
    for (int k = 0; k < 200; ++k) {
        t += gap(rng);
        keys.push_back(key(t, {value(rng), value(rng), value(rng), 0},
                           {double(k % 3 - 1), 0.0, double((k + 1) % 3 - 1), 0}));
        double q[4] = {normal(rng), normal(rng), normal(rng), normal(rng)};
        const double n = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
        rotations.push_back(key(t, {q[0] / n, q[1] / n, q[2] / n, q[3] / n}));
    }
    // Random times over and beyond the keys, every key time, and some repeated times.
    std::uniform_real_distribution<double> when(-5.0, t + 5.0);
    std::vector<double> times;
    for (int i = 0; i < 100000 - 400; ++i) times.push_back(when(rng));
    for (const ani_key &k : keys) times.push_back(k.time);
    for (int i = 0; i < 200; ++i) times.push_back(times[static_cast<size_t>(i)]);
    std::sort(times.begin(), times.end());
    REQUIRE(times.size() == 100000);

    struct Case {
        const char *plugin;
        ani_channel_kind kind;
        const std::vector<ani_key> *keys;
    };
    const Case cases[] = {
        {"interpolation.linear", ANI_CHANNEL_POSITION, &keys},
        {"interpolation.linear", ANI_CHANNEL_ANGLES, &keys},
        {"interpolation.linear", ANI_CHANNEL_CAMERA_ROTATION, &rotations},
        {"interpolation.kinematic", ANI_CHANNEL_POSITION, &keys},
        {"interpolation.smooth", ANI_CHANNEL_SCALE, &keys},
        {"interpolation.smooth", ANI_CHANNEL_ANGLES, &keys},
        {"interpolation.smooth", ANI_CHANNEL_CAMERA_ROTATION, &rotations},
    };
    for (const Case &c : cases) {
        CAPTURE(c.plugin, c.kind);
        Interpolator plugin(c.plugin);
        if (std::string(c.plugin) == "interpolation.smooth") plugin.set_param("tension", 0.2);
        const ani_channel ch = channel(c.kind, *c.keys, {0.5, -0.25, 1.0, 0});
        const Evaluation all = plugin.evaluate(ch, times);
        REQUIRE(all.code == ANI_OK);
        size_t mismatches = 0;
        // Every 7th time alone (all 100000 alone would take long under the sanitizers).
        for (size_t i = 0; i < times.size(); i += 7) {
            const Evaluation one = plugin.at(ch, times[i]);
            REQUIRE(one.code == ANI_OK);
            for (int k = 0; k < 4; ++k)
                if (one.value(0, k) != all.value(i, k) || one.rate(0, k) != all.rate(i, k)) ++mismatches;
        }
        CHECK(mismatches == 0);
        // And everything is finite.
        CHECK(std::all_of(all.values.begin(), all.values.end(), [](double x) { return std::isfinite(x); }));
        CHECK(std::all_of(all.rates.begin(), all.rates.end(), [](double x) { return std::isfinite(x); }));
    }
}

TEST_CASE("one instance evaluates from several threads at once with the same results") {
    // evaluate is [thread: any]: the host may render and bake from different threads.
    Interpolator smooth("interpolation.smooth");
    smooth.set_param("tension", 0.4);
    std::vector<ani_key> keys;
    for (int k = 0; k < 50; ++k) keys.push_back(key(0.5 * k, {double(k % 7), double(k * k % 11), 1.0, 0}));
    const ani_channel ch = channel(ANI_CHANNEL_POSITION, keys);
    const std::vector<double> times = linspace(-1.0, 26.0, 20000);
    const Evaluation expected = smooth.evaluate(ch, times);
    REQUIRE(expected.code == ANI_OK);
    std::vector<Evaluation> results(4);
    std::vector<std::thread> threads;
    for (size_t i = 0; i < results.size(); ++i)
        threads.emplace_back([&, i] { results[i] = smooth.evaluate(ch, times); });
    for (std::thread &t : threads) t.join();
    for (const Evaluation &r : results) {
        CHECK(r.code == ANI_OK);
        CHECK(r.values == expected.values);
        CHECK(r.rates == expected.rates);
    }
}
