// Run time against error on physics.md's exact scenes (tests/physics-bullet/scenes.cpp, each
// baked at four phases of its contact against Bullet's step grid, the worst phase counting),
// physics.custom once and physics.bullet at steps from 1/60 to 1/16000 s; and the long run of a
// ball in a box.
#include "bench.hpp"

#include "scenes.hpp"

#include <cmath>
#include <iostream>
#include <map>

namespace animator::bench {

namespace bt = animator::bullet_test;

namespace {

const std::string kCustom = "physics.custom", kBullet = "physics.bullet";

// One scene: how to bake it, and which errors of its Measured it reports (the first is the one
// the curves and the ratio use).
struct Scene {
    std::string name;
    std::function<bt::Measured(double dt, const std::string &backend)> bake;
    std::vector<std::pair<std::string, double bt::Measured::*>> measures;
    std::string what; // the measures' meaning, for the table
};

// Pass-throughs of the thin wall: at how many of the speeds the ball went through (any phase).
double passes(double dt, bool ccd, const std::string &backend, const std::vector<double> &speeds) {
    double through = 0.0;
    for (double v : speeds) through += bt::thin_wall(dt, v, ccd, backend).error == bt::kThrough;
    return through;
}

struct Point {
    double step = 0.0; // 0: physics.custom (no step)
    std::vector<double> errors;
    double ms = 0.0;
    double events = 0.0;
};

// Interpolates, on log-log axes, the time Bullet's curve needs to reach `target`.
struct Reach {
    bool reached = false;
    double ms = 0.0; // at the target, or at Bullet's best error
    double best_error = 0.0, best_step = 0.0, best_ms = 0.0;
};

Reach reach(const std::vector<Point> &bullet, double target) {
    Reach r;
    r.best_error = 1e300;
    for (const Point &p : bullet)
        if (p.errors[0] < r.best_error) {
            r.best_error = p.errors[0];
            r.best_step = p.step;
            r.best_ms = p.ms;
        }
    // The cheapest point at or below the target, interpolated back to the one before it.
    for (size_t k = 0; k < bullet.size(); ++k) {
        if (bullet[k].errors[0] > target) continue;
        r.reached = true;
        r.ms = bullet[k].ms;
        if (k > 0 && bullet[k - 1].errors[0] > target && target > 0.0 && bullet[k].errors[0] > 0.0) {
            const double e0 = std::log(bullet[k - 1].errors[0]), e1 = std::log(bullet[k].errors[0]);
            const double t0 = std::log(bullet[k - 1].ms), t1 = std::log(bullet[k].ms);
            const double f = (std::log(target) - e0) / (e1 - e0);
            r.ms = std::exp(t0 + f * (t1 - t0));
        }
        return r;
    }
    r.ms = r.best_ms;
    return r;
}

} // namespace

void run_exact(const Options &o) {
    const double box_seconds = o.quick ? 100.0 : 1000.0;
    const std::vector<double> steps =
        o.quick ? std::vector<double>{1.0 / 60.0, 1.0 / 240.0}
                : std::vector<double>{1.0 / 60.0, 1.0 / 240.0, 1.0 / 1000.0, 1.0 / 4000.0,
                                      1.0 / 16000.0};
    const std::vector<double> wall_speeds = {1.0, 20.0, 1000.0, 1e5};
    using M = bt::Measured;
    const std::vector<Scene> scenes = {
        {"drop",
         [](double dt, const std::string &b) { return bt::drop_on_plane(dt, b); },
         {{"apex (relative)", &M::error}, {"period (relative)", &M::error2}},
         "ball r 0.5 dropped 3 m on a plane, 4.5 bounce periods"},
        {"restitution",
         [](double dt, const std::string &b) { return bt::restitution_drop(dt, b); },
         {{"contact times (relative)", &M::error},
          {"apexes (relative)", &M::error2},
          {"off rest after T (m or m/s)", &M::error3}},
         "ball r 0.5, e 0.8, dropped 1 m on a plane, 1 s past the accumulation time"},
        {"tumbling",
         [](double dt, const std::string &b) { return bt::tumbling_cube(dt, b); },
         {{"1st contact time (relative)", &M::error},
          {"2nd contact time (relative)", &M::error2},
          {"energy after (relative)", &M::error3}},
         "cube side 1 dropped corner first, Rotates on, e 1, mu 0 (Bullet's margin 0.001)"},
        {"oblique",
         [](double dt, const std::string &b) { return bt::two_spheres(dt, 0.6, 2.0, -1.0, b); },
         {{"velocity (relative)", &M::error}},
         "two spheres, masses 1 and 3, offset 0.6 r, 3 m/s apart"},
        {"cradle",
         [](double dt, const std::string &b) { return bt::cradle(dt, b); },
         {{"position (m)", &M::error2}, {"velocity (relative)", &M::error}},
         "cradle.ani at 5 s"},
        {"box",
         [box_seconds](double dt, const std::string &b) {
             return bt::ball_in_box(dt, box_seconds, b);
         },
         {{"position (m)", &M::error3},
          {"energy (relative)", &M::error},
          {"beyond the wall (m)", &M::error2}},
         "ball r 0.5 at 1.5 m/s in a closed box (half 5 m)"},
        {"wall",
         [](double dt, const std::string &b) { return bt::thin_wall(dt, 20.0, true, b); },
         {{"lag at 20 m/s (m)", &M::error}},
         "ball r 0.1 against a 2-triangle wall at 20 m/s (Bullet with CCD)"},
        {"floor",
         [](double dt, const std::string &b) { return bt::sliding_on_floor(dt, b); },
         {{"vertical speed (m/s)", &M::error2}, {"height (m)", &M::error}},
         "ball r 0.25 sliding 2 s across floor_fine (8,192 triangles)"},
    };

    Csv csv(o.out / "exact.csv",
            {"scene", "measure", "backend", "step", "error", "ms", "runs", "events"});
    Csv ratios(o.out / "exact_ratio.csv",
               {"scene", "measure", "custom_error", "custom_ms", "bullet_reaches",
                "bullet_ms_at_custom_error", "ratio", "bullet_best_error", "bullet_best_step",
                "bullet_best_ms"});
    Csv through(o.out / "exact_passes.csv",
                {"backend", "step", "ccd", "speeds", "passes"});

    // A point: `runs` timed bakes, the median time; the errors are the same at every run.
    auto measure = [&](const Scene &s, double dt, const std::string &backend) {
        Point p;
        p.step = backend == kCustom ? 0.0 : dt;
        std::vector<double> ms;
        for (int r = 0; r < o.runs; ++r) {
            const M m = s.bake(dt, backend);
            ms.push_back(m.ms);
            if (r == 0) {
                for (const auto &[name, field] : s.measures)
                    p.errors.push_back(std::abs(m.*field));
                p.events = static_cast<double>(m.events);
            }
        }
        p.ms = median(ms);
        for (size_t k = 0; k < s.measures.size(); ++k) {
            csv << s.name << s.measures[k].first << backend << p.step << p.errors[k] << p.ms
                << static_cast<double>(o.runs) << p.events;
            csv.end_row();
        }
        return p;
    };

    std::cout << "Each point: the scene baked at 4 phases of its contact against Bullet's step "
                 "grid (worst error, time of the 4 bakes), median of "
              << o.runs << " runs.\n\n";
    std::cout << "| scene | measure | physics.custom: error | ms | Bullet: error at";
    for (double dt : steps) std::cout << " 1/" << std::lround(1.0 / dt);
    std::cout << " | Bullet ms at";
    for (double dt : steps) std::cout << " 1/" << std::lround(1.0 / dt);
    std::cout << " | Bullet ms / custom ms at custom's error |\n";
    for (const Scene &s : scenes) {
        // physics.custom has no step: one point (the scenes' phases use 1/1000 s).
        const Point custom = measure(s, 1.0 / 1000.0, kCustom);
        std::vector<Point> bullet;
        for (double dt : steps) bullet.push_back(measure(s, dt, kBullet));
        for (size_t k = 0; k < s.measures.size(); ++k) {
            std::cout << "| " << s.name << " | " << s.measures[k].first << " | "
                      << fmt(custom.errors[k]) << " | " << fmt(custom.ms) << " |";
            for (const Point &p : bullet) std::cout << " " << fmt(p.errors[k]);
            std::cout << " |";
            for (const Point &p : bullet) std::cout << " " << fmt(p.ms);
            std::cout << " | ";
            if (k == 0) {
                const Reach r = reach(bullet, custom.errors[0]);
                const double ratio = r.ms / custom.ms;
                if (r.reached)
                    std::cout << fmt(ratio) << "x";
                else
                    std::cout << "never reached (best " << fmt(r.best_error) << " at 1/"
                              << std::lround(1.0 / r.best_step) << ", " << fmt(ratio)
                              << "x the time)";
                ratios << s.name << s.measures[0].first << custom.errors[0] << custom.ms
                       << (r.reached ? 1.0 : 0.0) << (r.reached ? r.ms : r.best_ms) << ratio
                       << r.best_error << r.best_step << r.best_ms;
                ratios.end_row();
            }
            std::cout << " |\n";
        }
    }

    // Pass-throughs of the thin wall, at every speed (v dt / r from 0.17 to 1.7e7).
    std::cout << "\nThin wall, ball r 0.1 at " << wall_speeds.size()
              << " speeds (1, 20, 1000, 1e5 m/s): how many pass through (any of 4 phases)\n";
    std::cout << "| backend | step | CCD on | CCD off |\n";
    {
        const double c = passes(1.0 / 1000.0, true, kCustom, wall_speeds);
        through << kCustom << 0.0 << 1.0 << static_cast<double>(wall_speeds.size()) << c;
        through.end_row();
        std::cout << "| physics.custom | exact | " << c << " | (no such option) |\n";
    }
    for (double dt : steps) {
        const double on = passes(dt, true, kBullet, wall_speeds),
                     off = passes(dt, false, kBullet, wall_speeds);
        for (int ccd = 1; ccd >= 0; --ccd) {
            through << kBullet << dt << static_cast<double>(ccd)
                    << static_cast<double>(wall_speeds.size()) << (ccd ? on : off);
            through.end_row();
        }
        std::cout << "| physics.bullet | 1/" << std::lround(1.0 / dt) << " | " << on << " | "
                  << off << " |\n";
    }
}

void run_long(const Options &o) {
    const double seconds = o.quick ? 1000.0 : 300000.0;
    const std::vector<std::pair<std::string, double>> runs = {
        {kCustom, 1.0 / 1000.0}, {kBullet, 1.0 / 240.0}, {kBullet, 1.0 / 4000.0}};
    Csv csv(o.out / "long.csv", {"backend", "step", "seconds", "wall_s", "runs", "peak_rss_mb",
                                 "baseline_rss_mb", "collisions", "segments",
                                 "energy_error", "position_error_m"});
    const double baseline = resident_mb();
    std::cout << "A ball (r 0.5, 1.5 m/s) in a closed box for " << seconds
              << " s. Memory: the peak resident size of a process that did only this (the "
                 "program before it: "
              << fmt(baseline) << " MB).\n";
    std::cout << "| backend | step | wall s | peak MB | collisions | segments | energy error "
                 "(relative) | position error (m) |\n";
    for (const auto &[backend, dt] : runs) {
        double peak = 0.0;
        const int n = backend == kCustom ? o.runs : std::min(o.runs, 3);
        const std::vector<double> r = in_child(
            [&, backend = backend, dt = dt] {
                std::vector<double> ms;
                bt::Measured first;
                for (int k = 0; k < n; ++k) {
                    const bt::Measured m = bt::ball_in_box(dt, seconds, backend);
                    ms.push_back(m.ms);
                    if (k == 0) first = m;
                }
                return std::vector<double>{median(ms) / 1000.0,
                                           static_cast<double>(first.events),
                                           static_cast<double>(first.segments), first.error,
                                           first.error3};
            },
            peak);
        if (r.size() != 5) throw std::runtime_error("the long run with " + backend + " failed");
        csv << backend << (backend == kCustom ? 0.0 : dt) << seconds << r[0]
            << static_cast<double>(n) << peak << baseline << r[1] << r[2] << r[3] << r[4];
        csv.end_row();
        std::cout << "| " << backend << " | "
                  << (backend == kCustom ? std::string("exact")
                                         : "1/" + std::to_string(std::lround(1.0 / dt)))
                  << " | " << fmt(r[0]) << " | " << fmt(peak) << " | " << r[1] << " | " << r[2]
                  << " | " << fmt(r[3]) << " | " << fmt(r[4]) << " |\n";
    }
}

} // namespace animator::bench
