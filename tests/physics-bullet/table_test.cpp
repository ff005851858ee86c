// Prints the measured errors and bake times of every scene at the three steps (and finer ones),
// for docs/physics-bullet.md: physics_bullet_tests "[.table]".
#include "bullet_support.hpp"
#include "scenes.hpp"

#include <catch2/catch.hpp>

#include <cstdio>

using namespace animator::bullet_test;

namespace {
void row(const char *scene, double dt, const Measured &m) {
    std::printf("| %-34s | 1/%-5.0f | %9.3g | %9.3g | %8.1f | %6zu | %8zu |\n", scene, 1.0 / dt,
                m.error, m.error2, m.ms, m.events, m.segments);
    std::fflush(stdout);
}
} // namespace

TEST_CASE("the table of errors and times", "[.table]") {
    const double steps[] = {1.0 / 60, 1.0 / 240, 1.0 / 1000, 1.0 / 4000};
    std::printf("| scene | step | error | error2 | ms | events | segments |\n");
    for (double dt : steps) row("1 drop: apex, period", dt, drop_on_plane(dt));
    for (double dt : steps) row("2 spheres head-on", dt, two_spheres(dt, 0.0, 2.0, -1.0));
    for (double dt : steps) row("2 spheres oblique", dt, two_spheres(dt, 0.6, 2.0, -1.0));
    for (double dt : steps) row("2 spheres slow (0.15 m/s)", dt, two_spheres(dt, 0.3, 0.1, -0.05));
    for (double dt : steps) row("3 cradle: velocity, position", dt, cradle(dt));
    for (double dt : steps) row("4 box 1000 s: energy, outside", dt, ball_in_box(dt, 1000.0));
    for (double dt : steps) row("4 box 30000 s: energy, outside", dt, ball_in_box(dt, 30000.0));
    for (double speed : {1.0, 20.0, 1e3, 1e5})
        for (double dt : steps) {
            char name[64];
            std::snprintf(name, sizeof name, "5 wall ccd %g m/s: lag, time", speed);
            row(name, dt, thin_wall(dt, speed, true));
        }
    for (double speed : {20.0, 1e3})
        for (double dt : steps) {
            char name[64];
            std::snprintf(name, sizeof name, "5 wall no ccd %g m/s: lag, time", speed);
            row(name, dt, thin_wall(dt, speed, false));
        }
    for (double dt : steps) row("6 paddle: velocity, rest place", dt, keyed_paddle(dt));
    for (double dt : steps) row("7 stone: stop height, time", dt, stone(dt));
    for (double dt : steps) row("8 drop.ani custom vs bullet", dt, cross_check("drop.ani", dt));
    for (double dt : steps) row("8 cradle.ani custom vs bullet", dt, cross_check("cradle.ani", dt));
}
