// A model's rest shape (Model::rest: the shear a course scene gives a node scaled unevenly after
// it was rotated) is the shape physics collides with, not only the one drawn: a sheared box lands
// when its lowest sheared corner reaches the floor.
#include "scene_support.hpp"

#include <catch2/catch.hpp>

#include <cmath>

using namespace animator;
using namespace physics_test;

TEST_CASE("a sheared box falls until its lowest sheared corner meets the floor, in either backend") {
    // The cube mesh spans -1..1, scaled by 0.5 about a centre 3 m up. The rest shape adds 0.75 z
    // to y (and 0.5 y to x, which moves no corner down): its lowest corners are at
    // y = -0.5 (1 + 0.75) below the centre, so it drops h = 3 - 0.875 = 2.125 m, not the
    // unsheared 2.5 m, and meets the floor at t = sqrt(2 h / g).
    for (const char *backend : {"physics.custom", "physics.bullet"}) {
        CAPTURE(backend);
        Document doc;
        doc.add_model(model("floor", "plane", false, false), placed({0, 0, 0}, 10.0));
        Model box = model("sheared", "cube", true, true);
        box.rest[2][1] = 0.75; // column z, row y
        box.rest[1][0] = 0.5;  // column y, row x
        doc.add_model(box, placed({0, 3, 0}, 0.5));
        auto timeline = timeline_of(doc, backend);
        timeline->bake(1.0);
        REQUIRE_FALSE(timeline->events().empty());
        const double expected = std::sqrt(2.0 * (3.0 - 0.5 * 1.75) / G);
        const double unsheared = std::sqrt(2.0 * (3.0 - 0.5) / G);
        const double t = timeline->events().front().t;
        CAPTURE(t, expected, unsheared);
        // The exact backend to rounding; Bullet's to its steps (it reports contacts at the end of one).
        CHECK(std::abs(t - expected) < (std::string(backend) == "physics.custom" ? 1e-9 : 1e-2));
        CHECK(std::abs(t - unsheared) > 0.02);
    }
}
