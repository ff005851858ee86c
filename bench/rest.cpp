// Run time against error on the scenes of contacts that last (docs/physics.md, "Sliding,
// skidding and rolling", "Tipping", "Resting on other models", "Riding a keyed platform" and
// "Sticking to a platform that accelerates"):
// each shipped scene baked by physics.custom once and by physics.bullet at steps from 1/60 to
// 1/4000 s, its errors against the closed forms (for the tip, the pendulum equation integrated
// finely) that tests/physics/sliding_test.cpp and carrier_test.cpp check physics.custom with.
#include "bench.hpp"

#include "bullet_support.hpp"
#include "physics/platform_lift.hpp"
#include "physics/platform_ride.hpp"
#include "physics/tipping_pendulum.hpp"

#include <glm/geometric.hpp>

#include <cmath>
#include <iostream>
#include <tuple>

namespace animator::bench {

namespace bt = animator::bullet_test;

namespace {

constexpr double G = 9.81;

struct RestScene {
    std::string name, file, what; // file: under assets/
    double until = 3.0;
    std::vector<std::string> measures;
    // The errors of a bake (one per measure).
    std::function<std::vector<double>(const Timeline &, const Document &)> errors;
    double bullet_margin = 0.0; // Bullet's collision margin (m) when not its default
    int bullet_iterations = 0;  // Bullet's solver iterations when not its default (10)
};

using bt::energy;
using bt::model_named;
using bt::start_of;
using bt::worst;

// The angle (degrees past the vertical through its edge) of a cube of side 1 m tipping from 15
// degrees at rest, at t (tests/physics/tipping_pendulum.hpp), until the face lands at 45 degrees.
double tipped(double t) {
    const double w2 = tipping::pendulum_rate(G, 1.0), h = 1e-6, end = glm::radians(45.0);
    double phi = glm::radians(15.0), rate = 0.0, s = 0.0;
    for (; s + h <= t && phi < end; s += h) tipping::step(w2, h, phi, rate);
    if (phi < end && t > s) tipping::step(w2, t - s, phi, rate); // the last piece, to t exactly
    return glm::degrees(std::min(phi, end));
}

std::vector<RestScene> scenes() {
    return {
        {"puck",
         "scenes/sliding_puck.lua",
         "cylinder pushed at 3 m/s, mu 0.3: x(t) to the stop",
         3.0,
         {"position (m)", "still after the stop (m/s)"},
         [](const Timeline &t, const Document &doc) {
             const int m = model_named(doc, "puck");
             const double x0 = start_of(doc, m).x, v0 = 3.0, mu = 0.3, ts = v0 / (mu * G);
             auto x = [&](double s) {
                 s = std::min(s, ts);
                 return x0 + v0 * s - 0.5 * mu * G * s * s;
             };
             return std::vector<double>{
                 worst(3.0, [&](double s) {
                     return std::abs(t.evaluate(s).models[static_cast<size_t>(m)].center.x - x(s));
                 }),
                 worst(3.0, [&](double s) {
                     return s < ts + 0.05
                                ? 0.0
                                : glm::length(t.evaluate(s).models[static_cast<size_t>(m)].velocity);
                 })};
         }},
        {"ramp",
         "scenes/ramp_boxes.lua",
         "boxes on 20 degree ramps, mu 0.2 (slides) and 0.5 (sticks)",
         3.0,
         {"sliding position (m)", "sticking creep (m)"},
         [](const Timeline &t, const Document &doc) {
             const int sliding = model_named(doc, "sliding"), sticking = model_named(doc, "sticking");
             const double theta = glm::radians(20.0), a = G * (std::sin(theta) - 0.2 * std::cos(theta));
             const glm::dvec3 down(-std::cos(theta), -std::sin(theta), 0.0);
             const glm::dvec3 c0 = start_of(doc, sliding), s0 = start_of(doc, sticking);
             return std::vector<double>{
                 worst(3.0, [&](double s) {
                     return glm::length(t.evaluate(s).models[static_cast<size_t>(sliding)].center -
                                        (c0 + 0.5 * a * s * s * down));
                 }),
                 worst(3.0, [&](double s) {
                     return glm::length(t.evaluate(s).models[static_cast<size_t>(sticking)].center - s0);
                 })};
         },
         0.0,
         1000}, // with 10, the sliding box's friction falls short at every step (physics-bullet.md)
        {"rolling",
         "scenes/rolling_ball.lua",
         "ball launched at 4 m/s without spin, mu 0.2: rolls at 5/7 v0",
         3.0,
         {"speed once rolling (relative)"},
         [](const Timeline &t, const Document &doc) {
             const int m = model_named(doc, "ball");
             const double v1 = 5.0 / 7.0 * 4.0, ts = 2.0 * 4.0 / (7.0 * 0.2 * G);
             return std::vector<double>{worst(3.0, [&](double s) {
                 return s < ts + 0.05
                            ? 0.0
                            : std::abs(glm::length(t.evaluate(s).models[static_cast<size_t>(m)].velocity) -
                                       v1) / v1;
             })};
         }},
        {"tipping",
         "scenes/tipping_cube.lua",
         "cube on its edge at 30 degrees tips onto its face (to 2 s)",
         2.0,
         {"angle while it tips (degrees)", "off its face at rest (m)"},
         [](const Timeline &t, const Document &doc) {
             const int m = model_named(doc, "box");
             // Its turn about z is 45 degrees less phi while it tips (to 0.5 s: the face lands
             // at 0.5526 s).
             return std::vector<double>{
                 worst(0.5, [&](double s) {
                     const double z = t.evaluate(s).models[static_cast<size_t>(m)].angles.z;
                     return std::abs(std::remainder(z - (45.0 - tipped(s)), 360.0));
                 }),
                 std::abs(t.evaluate(2.0).models[static_cast<size_t>(m)].center.y - 0.5)};
         },
         0.001}, // its default, 0.04, rounds the edge it tips about: 3.5 degrees off at every step
        {"stack",
         "scenes/box_stack.lua",
         "three boxes standing, a ball dropped on them (to 3 s)",
         3.0,
         {"boxes' largest move (m)", "ball at rest on top (m)"},
         [](const Timeline &t, const Document &doc) {
             const int ball = model_named(doc, "ball");
             double moved = 0.0;
             for (const char *name : {"bottom", "middle", "top"}) {
                 const int m = model_named(doc, name);
                 moved = std::max(moved, worst(3.0, [&](double s) {
                                      return glm::length(
                                          t.evaluate(s).models[static_cast<size_t>(m)].center -
                                          start_of(doc, m));
                                  }));
             }
             const double r = 0.3 * bt::unit_sphere_radius();
             return std::vector<double>{
                 moved, std::abs(t.evaluate(3.0).models[static_cast<size_t>(ball)].center.y - (3.0 + r))};
         },
         0.0,
         1000}, // with 10, the blow leaks into the boxes at every step
        {"knock",
         "scenes/stack_knock.lua",
         "ball dropped on a stack's edge knocks its top box off, e 1, mu 0 (to 2 s)",
         2.0,
         {"energy drift (relative)", "boxes under it moved (m)"},
         [](const Timeline &t, const Document &doc) {
             const std::vector<std::tuple<std::string, double, double>> models = {
                 {"ball", 2.0, 0.4 * 2.0 * 0.09},
                 {"top", 1.0, 1.0 / 6.0},
                 {"middle", 1.0, 1.0 / 6.0},
                 {"bottom", 1.0, 1.0 / 6.0}};
             const double e0 = energy(t, doc, 0.0, models);
             double moved = 0.0;
             for (const char *name : {"bottom", "middle"}) {
                 const int m = model_named(doc, name);
                 moved = std::max(moved, worst(2.0, [&](double s) {
                                      return glm::length(
                                          t.evaluate(s).models[static_cast<size_t>(m)].center -
                                          start_of(doc, m));
                                  }));
             }
             return std::vector<double>{
                 worst(2.0,
                       [&](double s) { return std::abs(energy(t, doc, s, models) - e0) / e0; }),
                 moved};
         },
         0.0,
         1000}, // with 10, the blow leaks into the boxes at every step
        {"stairs",
         "animations/stairs_tumble.ani",
         "cube pushed off a step tumbles down the stairs, e 0.4, mu 0.5 (to 6 s)",
         6.0,
         {"slide to the nose (m)", "energy gained (J)"},
         [](const Timeline &t, const Document &doc) {
             const int m = model_named(doc, "cube");
             const double a = 0.5 * G, nose = (4.0 - std::sqrt(16.0 - 2.0 * a * 0.7)) / a;
             const std::vector<std::tuple<std::string, double, double>> models = {
                 {"cube", 1.0, 0.25 / 6.0}};
             const double e0 = energy(t, doc, 0.0, models);
             return std::vector<double>{
                 worst(nose,
                       [&](double s) {
                           return std::abs(t.evaluate(s).models[static_cast<size_t>(m)].center.x -
                                           (0.3 + 4.0 * s - 0.5 * a * s * s));
                       }),
                 worst(6.0,
                       [&](double s) { return std::max(0.0, energy(t, doc, s, models) - e0); })};
         }},
        {"platform",
         "animations/platform_ride.ani",
         "box placed on a platform keyed at 3 m/s, paused and back, mu 0.5 (to 7 s)",
         7.0,
         {"box's position (m)"},
         [](const Timeline &t, const Document &doc) {
             // The closed form (physics/platform_ride.hpp): the box slips at mu g relative to the
             // platform for 3 / (mu g) after each change of its velocity, and moves with it between.
             const int m = model_named(doc, "box");
             return std::vector<double>{worst(7.0, [&](double s) {
                 const glm::dvec3 c = t.evaluate(s).models[static_cast<size_t>(m)].center;
                 return glm::length(c - glm::dvec3(platform_ride::box_x(s, G), 1.35, 0.0));
             })};
         }},
        {"lift",
         "animations/platform_lift.ani",
         "box stuck to a platform eased across and lifted 2 m, mu 0.5 (to 7 s)",
         7.0,
         {"box's position (m)"},
         [](const Timeline &t, const Document &doc) {
             // The closed form (physics/platform_lift.hpp): the platform's eased keys, which the
             // box follows 0.35 m above its centre.
             const int m = model_named(doc, "box");
             return std::vector<double>{worst(7.0, [&](double s) {
                 const glm::dvec3 c = t.evaluate(s).models[static_cast<size_t>(m)].center;
                 return glm::length(c - glm::dvec3(platform_lift::box_x(s), platform_lift::box_y(s), 0.0));
             })};
         }},
    };
}

} // namespace

void run_rest(const Options &o) {
    const std::vector<double> steps =
        o.quick ? std::vector<double>{1.0 / 60.0, 1.0 / 240.0}
                : std::vector<double>{1.0 / 60.0, 1.0 / 240.0, 1.0 / 1000.0, 1.0 / 4000.0};
    Csv csv(o.out / "rest.csv", {"scene", "measure", "backend", "step", "error", "ms", "runs"});
    std::cout << "Each point: the shipped scene baked whole, median of " << o.runs
              << " runs; errors against the closed forms.\n\n";
    std::cout << "| scene | measure | physics.custom: error | ms | Bullet: error at";
    for (double dt : steps) std::cout << " 1/" << std::lround(1.0 / dt);
    std::cout << " | Bullet ms at";
    for (double dt : steps) std::cout << " 1/" << std::lround(1.0 / dt);
    std::cout << " |\n";
    for (const RestScene &s : scenes()) {
        const Document doc =
            open_document(bt::env().plugins,
                          std::filesystem::path(ANIMATOR_SOURCE_DIR) / "assets" / s.file)
                .document;
        struct Point {
            std::vector<double> errors;
            double ms = 0.0;
        };
        auto measure = [&](const std::string &backend, double dt) {
            Point p;
            std::vector<double> ms;
            for (int r = 0; r < o.runs; ++r) {
                Document d = bt::with_param(doc, "step", dt);
                if (s.bullet_margin > 0.0) d = bt::with_param(d, "margin", s.bullet_margin);
                if (s.bullet_iterations > 0)
                    d = bt::with_param(d, "solver_iterations", s.bullet_iterations);
                auto t = bt::timeline_of(d, backend);
                const auto start = std::chrono::steady_clock::now();
                t->bake(s.until);
                ms.push_back(1e3 * seconds_since(start));
                if (r == 0) p.errors = s.errors(*t, doc);
            }
            p.ms = median(ms);
            for (size_t k = 0; k < s.measures.size(); ++k) {
                csv << s.name << s.measures[k] << backend << (backend == "physics.custom" ? 0.0 : dt)
                    << p.errors[k] << p.ms << static_cast<double>(o.runs);
                csv.end_row();
            }
            return p;
        };
        const Point custom = measure("physics.custom", 1.0 / 1000.0);
        std::vector<Point> bullet;
        for (double dt : steps) bullet.push_back(measure("physics.bullet", dt));
        for (size_t k = 0; k < s.measures.size(); ++k) {
            std::cout << "| " << s.name << " | " << s.measures[k] << " | " << fmt(custom.errors[k])
                      << " | " << fmt(custom.ms) << " |";
            for (const Point &p : bullet) std::cout << " " << fmt(p.errors[k]);
            std::cout << " |";
            for (const Point &p : bullet) std::cout << " " << fmt(p.ms);
            std::cout << " |\n";
        }
    }
}

} // namespace animator::bench
