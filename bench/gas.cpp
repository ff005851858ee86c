// Scaling: a gas of N spheres in a closed box at a fixed density, N = 100 .. 1,000,000, baked through
// the timeline by each backend in a process of its own (for its memory), and run by the reference
// gas (gas_reference.hpp, a compact event-driven program) on the same spheres over the same time:
// physics.custom's collisions per second against the reference's.
#include "bench.hpp"
#include "gas_reference.hpp"

#include "bullet_support.hpp"

#include <glm/geometric.hpp>

#include <cmath>
#include <iostream>
#include <random>

namespace animator::bench {

namespace bt = animator::bullet_test;

namespace {

// N balls of radius 0.2 on a jittered cubic lattice of spacing 0.5 (a volume fraction of 0.27),
// random velocities up to 1 m/s per axis, masses in [0.5, 2], inside a closed box (the cube mesh)
// just wider than the lattice; no gravity. Model 0 is the box.
Document gas(int n, double bullet_step, uint64_t seed) {
    Document doc;
    Settings s = doc.settings();
    s.gravity = 0.0;
    s.max_time_ms = 1000000;
    s.params["physics.bullet"]["step"] = {bullet_step, 0.0, 0.0, 0.0};
    doc.set_settings(s);
    const int side = static_cast<int>(std::ceil(std::cbrt(static_cast<double>(n))));
    const double spacing = 0.5, scale = 0.2;
    const double r = bt::unit_sphere_radius() * scale;
    doc.add_model(bt::model("box", "cube", false, false),
                  bt::placed({0, 0, 0}, glm::dvec3(0.5 * side * spacing + 0.1)));
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> jitter(-0.1, 0.1), velocity(-1.0, 1.0), mass(0.5, 2.0);
    for (int k = 0; k < n; ++k) {
        Model ball = bt::model("ball" + std::to_string(k), "sphere", true, false);
        ball.mass = mass(rng);
        ball.initial_velocity = {velocity(rng), velocity(rng), velocity(rng)};
        const glm::dvec3 cell(k % side, (k / side) % side, k / (side * side));
        doc.add_model(ball, bt::placed((cell - glm::dvec3(0.5 * (side - 1))) * spacing +
                                           glm::dvec3(jitter(rng), jitter(rng), jitter(rng)) *
                                               (spacing - 2.0 * r),
                                       glm::dvec3(scale)));
    }
    return doc;
}

struct Totals {
    double energy = 0.0;
    double overlap = 0.0; // the deepest overlap of two balls, relative to the radius
};

// The deepest overlap of balls of radius r at `centres`, relative to r (0: none): every pair in
// the same or neighbouring cells of side 2r, found by sorting the balls by cell (1,000,000 balls:
// every pair would be 5e11, and a sweep along x alone 1e10).
double deepest_overlap(const std::vector<glm::dvec3> &centres, double r) {
    const double side = 2.0 * r;
    const auto cell = [&](const glm::dvec3 &c) {
        return glm::i64vec3(std::floor(c.x / side), std::floor(c.y / side), std::floor(c.z / side));
    };
    // Cells ordered by (x, y, z); a key per ball, sorted with it.
    std::vector<std::pair<glm::i64vec3, size_t>> order(centres.size());
    for (size_t k = 0; k < centres.size(); ++k) order[k] = {cell(centres[k]), k};
    const auto before = [](const glm::i64vec3 &a, const glm::i64vec3 &b) {
        return a.x != b.x ? a.x < b.x : a.y != b.y ? a.y < b.y : a.z < b.z;
    };
    std::sort(order.begin(), order.end(),
              [&](const auto &a, const auto &b) { return before(a.first, b.first); });
    double deepest = 0.0;
    for (const auto &[c, a] : order)
        for (int dx = -1; dx <= 1; ++dx)
            for (int dy = -1; dy <= 1; ++dy)
                for (int dz = -1; dz <= 1; ++dz) {
                    const glm::i64vec3 n = c + glm::i64vec3(dx, dy, dz);
                    auto it = std::lower_bound(
                        order.begin(), order.end(), n,
                        [&](const auto &x, const glm::i64vec3 &key) { return before(x.first, key); });
                    for (; it != order.end() && it->first == n; ++it) {
                        const size_t b = it->second;
                        if (b <= a) continue; // each pair once
                        const double d = glm::length(centres[a] - centres[b]);
                        if (d < side) deepest = std::max(deepest, (side - d) / r);
                    }
                }
    return deepest;
}

Totals totals(const Document &doc, const Timeline &t, double time) {
    const Frame f = t.evaluate(time);
    Totals out;
    const size_t n = doc.models().size();
    std::vector<glm::dvec3> centres;
    for (size_t k = 1; k < n; ++k) {
        const double m = doc.models()[k].mass;
        const glm::dvec3 v = f.models[k].velocity;
        out.energy += 0.5 * m * glm::dot(v, v);
        centres.push_back(f.models[k].center);
    }
    // (The momentum is not kept: the walls take it.)
    out.overlap = deepest_overlap(centres, 0.2 * bt::unit_sphere_radius());
    return out;
}

// The document's gas for the reference: model 0 is the box (the cube mesh, -1 to 1, scaled), the
// others the balls.
reference::Gas reference_gas(const Document &doc) {
    reference::Gas g;
    const ModelState &box = *doc.keyframes().front().states[0];
    for (int a = 0; a < 3; ++a) {
        g.lo[a] = box.center[a] - box.scale[a];
        g.hi[a] = box.center[a] + box.scale[a];
    }
    g.radius = 0.2 * bt::unit_sphere_radius();
    for (size_t k = 1; k < doc.models().size(); ++k) {
        const glm::dvec3 c = bt::start_of(doc, static_cast<int>(k));
        const glm::dvec3 v = doc.models()[k].initial_velocity;
        g.position.push_back({c.x, c.y, c.z});
        g.velocity.push_back({v.x, v.y, v.z});
        g.mass.push_back(doc.models()[k].mass);
    }
    return g;
}

// As totals(), of the reference's gas.
Totals totals(const reference::Gas &g) {
    Totals out;
    const size_t n = g.position.size();
    const auto vec = [](const std::array<double, 3> &a) { return glm::dvec3(a[0], a[1], a[2]); };
    std::vector<glm::dvec3> centres;
    for (size_t k = 0; k < n; ++k) {
        const glm::dvec3 v = vec(g.velocity[k]);
        out.energy += 0.5 * g.mass[k] * glm::dot(v, v);
        centres.push_back(vec(g.position[k]));
    }
    out.overlap = deepest_overlap(centres, g.radius);
    return out;
}

double count(const Timeline &t, const char *name) {
    const auto &c = t.stats().backend_counts;
    const auto it = c.find(name);
    return it == c.end() ? 0.0 : it->second;
}

} // namespace

void run_gas(const Options &o) {
    const std::vector<int> sizes =
        !o.sizes.empty() ? o.sizes
        : o.quick        ? std::vector<int>{100, 300}
                         : std::vector<int>{100, 300, 1000, 3000, 10000, 100000, 1000000};
    // Bullet to 10,000 balls: at 100,000 a run would take minutes and gigabytes for 25 steps.
    const int bullet_up_to = 10000;
    // Bullet's step for the gas: the largest of 1/240 .. 1/4000 s keeping its energy error near
    // 1e-3 (measured: see docs/performance.md).
    const double bullet_step = 1.0 / 1000.0;
    // The reference has a row of its own (its memory, in a process of its own); physics.custom runs
    // it again beside itself, in its process, for the ratio of the two.
    const std::vector<std::string> backends = {"reference", "physics.custom", "physics.bullet"};
    Csv csv(o.out / "gas.csv",
            {"backend", "n", "step", "sim_seconds", "wall_s", "wall_per_sim_s", "runs",
             "collisions", "collisions_per_s", "energy_error", "overlap", "peak_rss_mb",
             "baseline_rss_mb", "pair_tests_done", "pair_tests_skipped"});
    Csv ratios(o.out / "gas_ratio.csv",
               {"n", "custom_collisions_per_s", "reference_collisions_per_s", "ratio"});
    const double baseline = resident_mb();
    std::cout
        << "N balls (r 0.2, volume fraction 0.27, up to 1 m/s per axis) in a closed box. "
           "Simulated time: about "
        << (o.quick ? "20,000" : "100,000")
        << " collisions' worth, at least 0.2 s, for physics.custom and the reference "
           "(bench/gas_reference.hpp, on the same balls, in the same process); for Bullet (step 1/"
        << std::lround(1.0 / bullet_step)
        << " s) as much but at most 2,500 / N s, to N = 10,000. Energy error and overlap at the "
           "end.\n";
    std::cout << "| backend | N | sim s | wall s | wall s per sim s | collisions/s | energy "
                 "error | deepest overlap / r | peak MB | pair tests skipped | collisions/s over "
                 "the reference's |\n";
    // (log N, log wall time per simulated second) per backend
    std::vector<std::vector<std::pair<double, double>>> fit(backends.size());
    for (int n : sizes) {
        for (size_t b = 0; b < backends.size(); ++b) {
            const std::string &backend = backends[b];
            const bool bullet = backend == "physics.bullet", reference = backend == "reference";
            if ((bullet && n > bullet_up_to) ||
                (!o.backends.empty() &&
                 std::find(o.backends.begin(), o.backends.end(), backend) == o.backends.end()))
                continue;
            // About 4.7 collisions per ball per second at this density: physics.custom and the
            // reference run about 100,000 collisions (20,000 in a quick run); Bullet (about 3.5
            // us per ball and step at 1/1000 s here) at most that, and at most 2,500 / N s.
            // At least 0.2 s: the balls start on a lattice, about 0.04 s from their first
            // contacts (1,000,000 balls: 0.2 s, about a million collisions).
            const double sim_custom = std::max((o.quick ? 2e4 : 1e5) / (4.7 * n), 0.2);
            const double sim =
                bullet ? std::min(sim_custom, (o.quick ? 25.0 : 2500.0) / n) : sim_custom;
            const int runs = o.runs;
            double peak = 0.0;
            const bool custom = backend == "physics.custom";
            const std::vector<double> r = in_child(
                [&] {
                    const Document doc = gas(n, bullet_step, 7);
                    const reference::Gas g = reference_gas(doc);
                    // One run of the reference on the document's gas, timed; the first one's
                    // totals in `out`. Collisions counted as the plugins' events are: pair and
                    // wall.
                    const auto reference_run = [&](bool first, std::vector<double> &out) {
                        const auto start = std::chrono::steady_clock::now();
                        const reference::Result z = reference::run(g, sim);
                        const double seconds = seconds_since(start);
                        if (first) {
                            const Totals at0 = totals(g), at1 = totals(z.final_state);
                            out = {static_cast<double>(z.pair_collisions + z.wall_collisions),
                                   std::abs(at1.energy - at0.energy) / at0.energy, at1.overlap,
                                   static_cast<double>(z.predictions), 0.0};
                        }
                        return seconds;
                    };
                    std::vector<double> wall, beside; // beside: the reference in this process
                    std::vector<double> out, reference_out;
                    for (int k = 0; k < runs; ++k) {
                        if (reference) {
                            wall.push_back(reference_run(k == 0, out));
                            continue;
                        }
                        auto t = bt::timeline_of(doc, backend);
                        const auto start = std::chrono::steady_clock::now();
                        t->bake(sim);
                        wall.push_back(seconds_since(start));
                        if (k == 0) {
                            const Totals a = totals(doc, *t, 0.0), z = totals(doc, *t, sim);
                            out = {static_cast<double>(t->events().size()),
                                   std::abs(z.energy - a.energy) / a.energy, z.overlap,
                                   count(*t, "pair tests done"), count(*t, "pair tests skipped")};
                        }
                        // physics.custom's runs alternate with the reference's, in this
                        // process: the ratio of the two is measured in one run, on one machine
                        // state.
                        if (custom) beside.push_back(reference_run(k == 0, reference_out));
                    }
                    out.insert(out.begin(), median(wall));
                    if (custom) out.insert(out.end(), {median(beside), reference_out[0]});
                    return out;
                },
                peak);
            if (r.size() != (custom ? 8u : 6u))
                throw std::runtime_error("the gas with " + backend + " failed");
            const double wall = r[0], collisions = r[1], rate = collisions / wall;
            csv << backend << static_cast<double>(n) << (bullet ? bullet_step : 0.0) << sim << wall
                << wall / sim << static_cast<double>(runs) << collisions << rate << r[2] << r[3]
                << peak << baseline << r[4] << r[5];
            csv.end_row();
            fit[b].emplace_back(std::log(static_cast<double>(n)), std::log(wall / sim));
            // The reference's rate beside physics.custom's, in the same process (its own row's
            // process measures its memory).
            const double reference_rate = custom ? r[7] / r[6] : 0.0;
            if (custom) {
                ratios << static_cast<double>(n) << rate << reference_rate << rate / reference_rate;
                ratios.end_row();
            }
            const double skipped = r[4] + r[5] > 0.0 ? r[5] / (r[4] + r[5]) : 0.0;
            std::cout << "| " << backend << " | " << n << " | " << fmt(sim) << " | " << fmt(wall)
                      << " | " << fmt(wall / sim) << " | " << fmt(rate) << " | " << fmt(r[2])
                      << " | " << fmt(r[3]) << " | " << fmt(peak) << " | "
                      << (custom ? fmt(100.0 * skipped) + "%" : std::string("-")) << " | "
                      << (custom ? fmt(rate / reference_rate) : std::string("-")) << " |\n";
        }
    }
    // Least squares of log(wall time per simulated second) against log N.
    Csv exponents(o.out / "gas_fit.csv", {"backend", "exponent", "points"});
    for (size_t b = 0; b < backends.size(); ++b) {
        const auto &pts = fit[b];
        const auto m = static_cast<double>(pts.size());
        double sx = 0, sy = 0, sxx = 0, sxy = 0;
        for (const auto &[x, y] : pts) {
            sx += x;
            sy += y;
            sxx += x * x;
            sxy += x * y;
        }
        const double slope = m > 1 ? (m * sxy - sx * sy) / (m * sxx - sx * sx) : 0.0;
        exponents << backends[b] << slope << m;
        exponents.end_row();
        std::cout << backends[b] << ": wall time per simulated second ~ N^" << fmt(slope)
                  << " (N log N over this range would be about N^1.1)\n";
    }
}

} // namespace animator::bench
