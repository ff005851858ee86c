#include "scenes.hpp"

#include "bullet_support.hpp"
#include "cube_drop.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>

namespace animator::bullet_test {

namespace {

double milliseconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
        .count();
}

glm::dvec3 vec(const ani_vec3 &v) {
    return {v.x, v.y, v.z};
}

// Bakes and times.
template <class F> Measured timed_bake(Timeline &t, double until, F &&then) {
    Measured m;
    const auto start = std::chrono::steady_clock::now();
    t.bake(until);
    m.ms = milliseconds_since(start);
    m.events = t.events().size();
    for (size_t k = 0; k < t.document().models().size(); ++k)
        m.segments += t.segments(static_cast<int>(k)).size();
    then(m);
    return m;
}

// Where Bullet's steps fall relative to a contact decides much of its error at that contact: each
// scene is baked at four phases (its contact moved by 0, 0.29, 0.58 and 0.87 of a step) and the
// worst is kept.
constexpr int kPhases = 4;
constexpr double kPhase = 0.29;

template <class F> Measured worst_phase(F &&bake_at_phase) {
    Measured worst;
    for (int j = 0; j < kPhases; ++j) {
        const Measured m = bake_at_phase(kPhase * j);
        worst.error = std::max(worst.error, m.error);
        worst.error2 = std::max(worst.error2, m.error2);
        worst.error3 = std::max(worst.error3, m.error3);
        worst.ms += m.ms;
        worst.events = std::max(worst.events, m.events);
        worst.segments = std::max(worst.segments, m.segments);
    }
    return worst;
}

} // namespace

Measured drop_on_plane(double dt, const std::string &backend) {
    return worst_phase([&](double phase) {
        const double r = 0.5 * unit_sphere_radius();
        // About 3 m, placed so the ball reaches the floor `phase` of a step later.
        const double first = std::sqrt(2.0 * (3.0 - r) / G) + phase * dt, period = 2.0 * first;
        const double h = r + 0.5 * G * first * first;
        Document doc;
        doc.add_model(model("floor", "plane", false, false), placed({0, 0, 0}, glm::dvec3(10.0)));
        doc.add_model(model("ball", "sphere", true, true), placed({0.3, h, 0.2}, glm::dvec3(0.5)));
        auto t = timeline_of(with_param(doc, "step", dt), backend);
        return timed_bake(*t, first + 4.5 * period, [&](Measured &m) {
            // Each apex: the vertex of a free segment's parabola, where it lies within the segment.
            for (const ani_motion_segment &s : t->segments(1)) {
                if (s.motion != ANI_MOTION_FREE || s.a.y == 0.0) continue;
                const double at = -s.v0.y / s.a.y;
                if (at <= 1e-9 || at > s.t1 - s.t0) continue;
                const double apex = s.p0.y + s.v0.y * at + 0.5 * s.a.y * at * at;
                m.error = std::max(m.error, std::abs(apex - h) / h);
            }
            const auto &events = t->events();
            if (events.size() >= 2) {
                const double mean =
                    (events.back().t - events.front().t) / static_cast<double>(events.size() - 1);
                m.error2 = std::abs(mean - period) / period;
            } else {
                m.error2 = 1.0;
            }
        });
    });
}

Measured tumbling_cube(double dt, const std::string &backend, double margin) {
    return worst_phase([&](double phase) {
        const glm::dvec3 angles(30.0, 0.0, 20.0); // the scene's: turned about x, then about z
        const double half = 0.5, mass = 1.0;
        double below = 0.0; // the lowest corner, below the centre
        for (const glm::dvec3 &p : cube_drop::corners(half))
            below = std::max(below, -(cube_drop::turn_of(angles) * p).y);
        // About 1.19 m above the floor, placed so the corner reaches it `phase` of a step later.
        const double t1 = std::sqrt(2.0 * 1.19 / G) + phase * dt;
        const glm::dvec3 center(0.0, 0.5 * G * t1 * t1 + below, 0.0);
        const cube_drop::Drop exact = cube_drop::drop(center, angles, half, mass, G);
        Document doc;
        doc.add_model(model("floor", "plane", false, false), placed({0, 0, 0}, glm::dvec3(10.0)));
        Model cube = model("cube", "cube", true, true);
        cube.mass = mass;
        cube.rotates = true;
        doc.add_model(cube, placed(center, glm::dvec3(half), angles));
        auto t = timeline_of(with_param(with_param(doc, "step", dt), "margin", margin), backend);
        const double at = exact.t2 + 0.1;
        return timed_bake(*t, exact.t2 + 0.5, [&](Measured &m) {
            const auto &events = t->events();
            m.error = events.empty() ? 1.0 : std::abs(events[0].t - exact.t1) / exact.t1;
            m.error2 = events.size() < 2 ? 1.0 : std::abs(events[1].t - exact.t2) / exact.t2;
            const Frame f = t->evaluate(at);
            const ani_rotation_segment *turn = t->rotation_at(1, at);
            const glm::dvec3 v = f.models[1].velocity, w = turn ? vec(turn->w) : glm::dvec3(0.0);
            const double e0 = mass * G * center.y;
            const double energy = 0.5 * mass * glm::dot(v, v) +
                                  0.5 * exact.inertia * glm::dot(w, w) +
                                  mass * G * f.models[1].center.y;
            m.error3 = std::abs(energy - e0) / e0;
        });
    });
}

Measured restitution_drop(double dt, const std::string &backend) {
    return worst_phase([&](double phase) {
        const double r = 0.5 * unit_sphere_radius(), e = 0.8;
        // About 1 m above the contact height, placed so the ball reaches the floor `phase` of a
        // step later.
        const double t0 = std::sqrt(2.0 * 1.0 / G) + phase * dt;
        const double d = 0.5 * G * t0 * t0, h = r + d;
        const double rest = t0 * (1.0 + e) / (1.0 - e); // the accumulation time
        Document doc;
        doc.add_model(model("floor", "plane", false, false), placed({0, 0, 0}, glm::dvec3(10.0)));
        Model ball = model("ball", "sphere", true, true);
        ball.restitution = e;
        doc.add_model(ball, placed({0.3, h, 0.2}, glm::dvec3(0.5)));
        auto t = timeline_of(with_param(doc, "step", dt), backend);
        const double until = rest + 1.0;
        return timed_bake(*t, until, [&](Measured &m) {
            const auto &events = t->events();
            // Contact k (from 0) comes after the first fall t0 and k flights of 2 t0 e^j, j = 1..k.
            m.error = events.size() < static_cast<size_t>(kRestitutionBounces) ? 1.0 : 0.0;
            auto contact_time = [&](size_t k) {
                return t0 *
                       (1.0 + 2.0 * e * (1.0 - std::pow(e, static_cast<double>(k))) / (1.0 - e));
            };
            for (size_t k = 0; k < events.size() && k < static_cast<size_t>(kRestitutionBounces);
                 ++k) {
                const double exact = contact_time(k);
                m.error = std::max(m.error, std::abs(events[k].t - exact) / exact);
            }
            // Apex k (from 1): the highest point of the free segments between the exact contact
            // times k - 1 and k (segment ends, and the parabola's vertex where it lies within the
            // segment); the exact times, not the events, so that a bounce the timeline does not
            // report (Bullet at some phases) still has its apex measured.
            constexpr int kApexes = 5;
            for (size_t k = 1; k <= kApexes; ++k) {
                const double from = contact_time(k - 1), to = contact_time(k);
                double top = -1e300;
                for (const ani_motion_segment &s : t->segments(1)) {
                    if (s.t1 <= from || s.t0 >= to) continue;
                    const double a = std::max(s.t0, from) - s.t0, b = std::min(s.t1, to) - s.t0;
                    auto y = [&](double at) {
                        return s.p0.y + s.v0.y * at + 0.5 * s.a.y * at * at;
                    };
                    top = std::max({top, y(a), y(b)});
                    if (s.a.y != 0.0) {
                        const double at = -s.v0.y / s.a.y;
                        if (at > a && at < b) top = std::max(top, y(at));
                    }
                }
                const double exact = std::pow(e, 2.0 * static_cast<double>(k)) * d;
                m.error2 = std::max(m.error2, std::abs(top - r - exact) / exact);
            }
            // At rest on the floor after the accumulation time.
            for (int j = 1; j <= 100; ++j) {
                const double at = rest + (until - rest) * j / 100.0;
                const Frame f = t->evaluate(at);
                m.error3 = std::max({m.error3, std::abs(f.models[1].center.y - r),
                                     glm::length(f.models[1].velocity)});
            }
        });
    });
}

Measured two_spheres(double dt, double offset_in_radii, double u1, double u2,
                     const std::string &backend) {
    return worst_phase([&](double phase) {
        const double r = 0.5 * unit_sphere_radius(), m1 = 1.0, m2 = 3.0;
        const double b = offset_in_radii * r;
        Document doc = no_gravity();
        Model a = model("a", "sphere", true, false), c = model("b", "sphere", true, false);
        a.mass = m1;
        c.mass = m2;
        a.initial_velocity = {u1, 0, 0};
        c.initial_velocity = {u2, 0, 0};
        const double shift = phase * dt * (u1 - u2);
        doc.add_model(a, placed({-1.0 - shift, b, 0}, glm::dvec3(0.5)));
        doc.add_model(c, placed({1.0, 0, 0}, glm::dvec3(0.5)));
        auto t = timeline_of(with_param(doc, "step", dt), backend);
        // Contact when the centers are 2 r apart: along x, 2 + shift - (u1 - u2) t = sqrt(4 r^2 -
        // b^2).
        const double along = std::sqrt(4.0 * r * r - b * b);
        const double contact = (2.0 + shift - along) / (u1 - u2);
        const double until = contact + 0.25 / (u1 - u2) + 10.0 * dt;
        return timed_bake(*t, until, [&](Measured &m) {
            const glm::dvec3 n =
                glm::normalize(glm::dvec3(-along, b, 0.0)); // from b's center to a's
            const glm::dvec3 v1(u1, 0, 0), v2(u2, 0, 0);
            const double v1n = glm::dot(v1, n), v2n = glm::dot(v2, n);
            const double w1n = ((m1 - m2) * v1n + 2.0 * m2 * v2n) / (m1 + m2);
            const double w2n = ((m2 - m1) * v2n + 2.0 * m1 * v1n) / (m1 + m2);
            const glm::dvec3 w1 = v1 + (w1n - v1n) * n, w2 = v2 + (w2n - v2n) * n;
            const Frame f = t->evaluate(until);
            const double scale = std::abs(u1 - u2);
            m.error = std::max(glm::length(f.models[0].velocity - w1),
                               glm::length(f.models[1].velocity - w2)) /
                      scale;
            if (m.events != 1) m.error = std::max(m.error, 1.0);
        });
    });
}

Measured cradle(double dt, const std::string &backend) {
    return worst_phase([&](double phase) {
        Document doc = load("cradle.ani");
        const int striker = doc.find_model("striker");
        ModelState start = *doc.keyframes()[0].states[static_cast<size_t>(striker)];
        const double x_striker = start.center.x - phase * dt * 2.0;
        start.center.x = x_striker;
        doc.set_state(0, striker, start);
        auto t = timeline_of(with_param(doc, "step", dt), backend);
        return timed_bake(*t, 5.0, [&](Measured &m) {
            // The striker (2 m/s) meets ball1 (x = 0) when 2 r apart; each ball then moves by the
            // gap between surfaces (the centers are 1.001 apart) and stops; ball4 leaves with 2 m/s
            // once three gaps are crossed.
            const double r = 0.5 * unit_sphere_radius(), gap = 1.001 - 2.0 * r;
            const double first = (-2.0 * r - x_striker) / 2.0, leave = first + 3.0 * gap / 2.0;
            const Frame f = t->evaluate(5.0);
            for (int k = 0; k < static_cast<int>(doc.models().size()); ++k) {
                const Model &mk = doc.models()[static_cast<size_t>(k)];
                if (!mk.dynamics) continue;
                const bool last = mk.name == "ball4";
                const glm::dvec3 v = f.models[static_cast<size_t>(k)].velocity;
                m.error =
                    std::max(m.error, glm::length(v - glm::dvec3(last ? 2.0 : 0.0, 0, 0)) / 2.0);
                const double x0 = doc.keyframes()[0].states[static_cast<size_t>(k)]->center.x;
                const double x = k == striker ? -2.0 * r
                                 : last       ? x0 + 2.0 * (5.0 - leave)
                                              : x0 + gap;
                m.error2 =
                    std::max(m.error2, std::abs(f.models[static_cast<size_t>(k)].center.x - x));
            }
        });
    });
}

Measured ball_in_box(double dt, double seconds, const std::string &backend) {
    const double r = 0.5 * unit_sphere_radius(), half = 5.0, L = half - r;
    Document doc = no_gravity();
    Settings s = doc.settings();
    s.max_time_ms = 300000000;
    doc.set_settings(s);
    doc.add_model(model("box", "cube", false, false), placed({0, 0, 0}, glm::dvec3(half)));
    Model ball = model("ball", "sphere", true, false);
    const glm::dvec3 v0(1.3, 0.7, 0.3);
    ball.initial_velocity = v0;
    doc.add_model(ball, placed({0.5, -1.0, 2.0}, glm::dvec3(0.5)));
    auto t = timeline_of(with_param(doc, "step", dt), backend);
    return timed_bake(*t, seconds, [&](Measured &m) {
        const double e0 = glm::dot(v0, v0);
        for (const ani_motion_segment &seg : t->segments(1)) {
            // Between contacts (stretches of more than one step) the velocity is Bullet's.
            if (seg.t1 - seg.t0 > 1.5 * dt) {
                const glm::dvec3 v = vec(seg.v0);
                m.error = std::max(m.error, std::abs(glm::dot(v, v) - e0) / e0);
            }
            // Straight segments: the extremes are at the ends.
            const glm::dvec3 ends[2] = {vec(seg.p0), vec(seg.p0) + vec(seg.v0) * (seg.t1 - seg.t0)};
            for (const glm::dvec3 &p : ends)
                for (int c = 0; c < 3; ++c) m.error2 = std::max(m.error2, std::abs(p[c]) - L);
        }
        // The exact path: each coordinate unfolded (x0 + v t) and folded back into [-L, L].
        const glm::dvec3 x0(0.5, -1.0, 2.0);
        for (int k = 0; k <= 1000; ++k) {
            const double time = seconds * k / 1000.0;
            const glm::dvec3 at = t->evaluate(time).models[1].center;
            for (int c = 0; c < 3; ++c) {
                const double w = std::fmod(x0[c] + v0[c] * time + L, 4.0 * L);
                const double exact = w < 2.0 * L ? w - L : 3.0 * L - w;
                m.error3 = std::max(m.error3, std::abs(at[c] - exact));
            }
        }
    });
}

const double kThrough = 1e300;

Measured thin_wall(double dt, double speed, bool ccd, const std::string &backend) {
    return worst_phase([&](double phase) {
        const double r = 0.1 * unit_sphere_radius();
        Document doc = no_gravity();
        // The plane stood up: rotated 90 degrees about Z, its face is the plane x = 0.
        doc.add_model(model("wall", "plane", false, false),
                      placed({0, 0, 0}, glm::dvec3(2.0), {0, 0, 90}));
        Model ball = model("ball", "sphere", true, false);
        ball.initial_velocity = {-speed, 0, 0};
        const double x0 = 1.0 + phase * dt * speed;
        doc.add_model(ball, placed({x0, 0.1, 0.1}, glm::dvec3(0.1)));
        auto t =
            timeline_of(with_param(with_param(doc, "step", dt), "ccd", ccd ? 1.0 : 0.0), backend);
        const double hit = (x0 - r) / speed;
        const double until = hit + 2.0 * dt;
        return timed_bake(*t, until, [&](Measured &m) {
            const double x = t->evaluate(until).models[1].center.x;
            const double exact = r + speed * (until - hit);
            m.error = x > 0.0 ? exact - x : kThrough; // how far behind, or through
            m.error2 = m.events ? std::abs(t->events()[0].t - hit) : kThrough;
        });
    });
}

Measured keyed_paddle(double dt) {
    return worst_phase([&](double phase) {
        // The paddle: a cube 0.2 wide (scale 0.1), keyed from x = -3 to x = 1 over 2 s (2 m/s),
        // then to x = 3 at 4 s; the ball at rest at x = 0. They touch when the paddle's face (x =
        // center + 0.1) reaches -r: at (3 - r - 0.1) / 2 s.
        const double r = 0.5 * unit_sphere_radius(), u = 2.0;
        Document doc = no_gravity();
        doc.add_model(model("paddle", "cube", false, false), placed({-3, 0, 0}, {0.1, 1, 1}));
        const double x_ball = phase * dt * u;
        doc.add_model(model("ball", "sphere", true, false),
                      placed({x_ball, 0, 0}, glm::dvec3(0.5)));
        key(doc, 2000, 0, placed({1, 0, 0}, {0.1, 1, 1}));
        key(doc, 4000, 0, placed({3, 0, 0}, {0.1, 1, 1}));
        auto t = timeline_of(with_param(doc, "step", dt));
        const double contact = (3.0 + x_ball - r - 0.1) / u;
        return timed_bake(*t, 6.0, [&](Measured &m) {
            const ModelPose ball = t->evaluate(contact + 0.5).models[1];
            m.error = std::abs(ball.velocity.x - 2.0 * u) / (2.0 * u);
            const ani_motion_segment *rest = segment_at(*t, 0, 1.9);
            m.error = std::max(m.error, rest && rest->motion == ANI_MOTION_REST
                                            ? std::abs(rest->p0.x - (x_ball - r - 0.1))
                                            : 1.0);
            m.error2 = std::abs(ball.center.x - (x_ball + 2.0 * u * 0.5));
        });
    });
}

Measured stone(double dt) {
    return worst_phase([&](double phase) {
        const double r = unit_sphere_radius();
        const double landing = std::sqrt(2.0 * (3.0 - r) / G) + phase * dt;
        const double h = r + 0.5 * G * landing * landing;
        Document doc;
        doc.add_model(model("floor", "plane", false, false), placed({0, 0, 0}, glm::dvec3(10.0)));
        doc.add_model(model("stone", "sphere", false, true), placed({0, h, 0}));
        auto t = timeline_of(with_param(doc, "step", dt));
        return timed_bake(*t, 3.0, [&](Measured &m) {
            const Frame f = t->evaluate(2.5);
            m.error = std::abs(f.models[1].center.y - r);
            if (f.models[1].velocity != glm::dvec3(0.0) || f.motion[1] != ANI_MOTION_REST)
                m.error = 1.0;
            m.error2 = t->events().size() == 1 ? std::abs(t->events()[0].t - landing) : 1.0;
        });
    });
}

Measured sliding_on_floor(double dt, const std::string &backend) {
    return worst_phase([&](double phase) {
        const double r = 0.25 * unit_sphere_radius(), u = 1.5, until = 2.0;
        Document doc;
        doc.add_model(model("floor", "floor_fine", false, false),
                      placed({0, 0, 0}, glm::dvec3(4.0)));
        Model ball = model("ball", "sphere", true, true);
        ball.initial_velocity = {u, 0, 0.3 * u};
        // Its path crosses the floor's grid lines at `phase` of a step later.
        doc.add_model(ball, placed({-1.7 + phase * dt * u, r, -0.4}, glm::dvec3(0.25)));
        auto t = timeline_of(with_param(doc, "step", dt), backend);
        return timed_bake(*t, until, [&](Measured &m) {
            for (int k = 0; k <= 100 * static_cast<int>(until); ++k) {
                const ModelPose p = t->evaluate(0.01 * k).models[1];
                m.error = std::max(m.error, std::abs(p.center.y - r));
                m.error2 = std::max(m.error2, std::abs(p.velocity.y));
            }
        });
    });
}

Measured cross_check(const char *animation, double dt) {
    const Document doc = load(animation);
    const double until = static_cast<double>(doc.settings().max_time_ms) / 1000.0;
    auto custom = timeline_of(doc, "physics.custom");
    custom->bake(until);
    auto bullet = timeline_of(with_param(doc, "step", dt));
    return timed_bake(*bullet, until, [&](Measured &m) {
        for (int k = 0; k <= 100 * static_cast<int>(until); ++k) {
            const double time = 0.01 * k;
            const Frame a = custom->evaluate(time), b = bullet->evaluate(time);
            for (size_t i = 0; i < a.models.size(); ++i)
                m.error = std::max(m.error, glm::length(a.models[i].center - b.models[i].center));
        }
    });
}

} // namespace animator::bullet_test
