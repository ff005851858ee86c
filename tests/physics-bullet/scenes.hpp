// physics.md's scenes with an exact answer, baked with physics.bullet at a given step, and how
// far the bake is from the answer. The tests assert on these; the hidden test "[.table]" prints
// them for docs/physics-bullet.md. The benchmark (bench/, docs/performance.md) bakes the same
// scenes with either backend (`backend`; physics.custom ignores the step) and its own
// implementation of bullet_support.hpp.
#pragma once

#include <cstddef>

#include <string>

namespace animator::bullet_test {

inline const std::string kBullet = "physics.bullet";

// Every scene is baked at four phases of its contact against Bullet's steps; the worst counts.
struct Measured {
    double error = 0.0;  // the scene's main error measure (see each function)
    double error2 = 0.0; // a second one where the scene has it
    double error3 = 0.0; // a third one where the scene has it
    double ms = 0.0;     // wall time of the bake
    std::size_t events = 0, segments = 0;
};

// 1. A ball (r = 0.5) dropped from 3 m on a floor, e = 1, 4.5 bounce periods. error: largest
//    relative apex error |y* - h| / h; error2: relative error of the mean bounce period against
//    2 sqrt(2 (h - r) / G).
Measured drop_on_plane(double dt, const std::string &backend = kBullet);
// 1b. A ball (r = 0.5) with restitution 0.8 (the floor keeps 1: the lower counts) dropped from
//    1.5 m (d = h - r = 1 m above its contact height) on a floor, baked 1 s past the accumulation
//    time T = t0 (1 + e) / (1 - e), t0 = sqrt(2 d / G). error: largest relative error of the
//    first kRestitutionBounces contact times (the timeline's events) against t_k = t0 (1 + 2 e
//    (1 - e^k) / (1 - e)), k = 0, 1, ..., event k against t_k (a bounce not reported shifts the
//    rest: large errors), or 1 when fewer are reported; error2: largest relative error of the
//    first 5 apexes (the highest point between the exact t_(k-1) and t_k) against e^(2k) d above
//    the contact height; error3: how far it is
//    from resting on the floor after T, the larger of |height - r| (m) and |v| (m/s), at 1/100 s
//    samples.
constexpr int kRestitutionBounces = 8;
Measured restitution_drop(double dt, const std::string &backend = kBullet);
// 1c. A cube (side 1, 1 kg) dropped corner first on a floor with Rotates on, e = 1, mu = 0
//    (assets/scenes/tumbling_cube.lua's, its corner about 1.19 m up), against tests/cube_drop.hpp:
//    error: relative error of the first contact time (closed form); error2: relative error of
//    the second contact time (its own root finding); 1 when fewer contacts are reported;
//    error3: relative error of the kinetic plus potential energy 0.1 s after the second contact.
//    Baked to 0.5 s after the second contact. Bullet with its collision margin `margin` (its
//    own 0.04 rounds the cube's corners: it lands 5 ms late and does not converge).
Measured tumbling_cube(double dt, const std::string &backend = kBullet, double margin = 0.001);
// 2. Two spheres (r = 0.5, masses 1 and 3) meeting without gravity: head-on (offset 0), oblique
//    (offset 0.6 r) and slowly (relative speed 0.15 m/s, offset 0.3 r). error: largest velocity
//    error after the contact over both, relative to the relative speed.
Measured two_spheres(double dt, double offset_in_radii, double u1, double u2,
                     const std::string &backend = kBullet);
// 3. Newton's cradle (assets/animations/cradle.ani) at 5 s. error: largest velocity error of any
//    ball relative to the striker's 2 m/s; error2: largest position error (m).
Measured cradle(double dt, const std::string &backend = kBullet);
// 4. A ball (r = 0.5) in a closed box (cube scaled 5) for `seconds`. error: largest relative
//    kinetic energy error between contacts; error2: largest distance a center goes beyond the
//    box's inside (m); error3: largest distance from the exact triangle wave on each axis, at
//    1001 times spread over the run (m).
Measured ball_in_box(double dt, double seconds, const std::string &backend = kBullet);
// 5. A ball (r = 0.1) at `speed` against a two-triangle wall. error: how far behind the exact
//    path it is 2 steps after the contact (m), or kThrough when it passed the wall (at any
//    phase); error2: the event's time error (s), kThrough without an event.
extern const double kThrough;
Measured thin_wall(double dt, double speed, bool ccd, const std::string &backend = kBullet);
// 6. A keyed paddle at 2 m/s strikes a resting ball. error: the larger of the relative error of
//    the ball's velocity after (2u) and the error of where the paddle rests (m); error2: the
//    ball's position error half a second after the contact (m).
Measured keyed_paddle(double dt);
// 7. A model without Dynamics, with Gravity, dropped on a floor. error: how far from touching it
//    stops (m); error2: the landing event's time error (s).
Measured stone(double dt);
// 6b. A ball (r = 0.25) placed on floor_fine (8,192 triangles, scaled 4) sliding across it at
//    (1.5, 0, 0.45) m/s for 2 s under gravity. error: largest height off the floor's surface (m); error2: largest
//    vertical speed (m/s); both at 1/100 s samples, and 0 for the exact answer.
Measured sliding_on_floor(double dt, const std::string &backend = kBullet);
// 8. physics.custom against physics.bullet on an animation: largest distance between the two
//    backends' centers over 1/100 s samples (m).
Measured cross_check(const char *animation, double dt);

} // namespace animator::bullet_test
