// physics.bullet as a plugin: its parameters through the host, the shapes it picks, overlaps at the
// start, rotation on contact, resumed and cancelled bakes, values that are not finite, and long
// runs that must not cost a segment per step.
#include "bullet_support.hpp"
#include "scenes.hpp"

#include "plugin/instance.hpp"

#include <catch2/catch.hpp>
#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>

using namespace animator;
using namespace animator::bullet_test;

namespace {

bool logged(const std::vector<std::string> &lines, const std::string &a,
            const std::string &b = "") {
    return std::any_of(lines.begin(), lines.end(), [&](const std::string &l) {
        return l.find(a) != std::string::npos && l.find(b) != std::string::npos;
    });
}

Document long_document() {
    Document doc;
    Settings s = doc.settings();
    s.max_time_ms = 300000000;
    doc.set_settings(s);
    return doc;
}

double count(const Timeline &t, const std::string &name) {
    const auto &counts = t.stats().backend_counts;
    const auto it = counts.find(name);
    return it == counts.end() ? -1.0 : it->second;
}

} // namespace

TEST_CASE("the step set in a document's parameters changes how many steps a bake takes") {
    Document doc;
    doc.add_model(model("floor", "plane", false, false), placed({0, 0, 0}, glm::dvec3(10.0)));
    doc.add_model(model("ball", "sphere", true, true), placed({0, 3, 0}, glm::dvec3(0.5)));
    auto by_default = timeline_of(doc);
    by_default->bake(2.0);
    CHECK(count(*by_default, "steps") == 480); // 1/240 s
    auto coarse = timeline_of(with_param(doc, "step", 0.01));
    coarse->bake(2.0);
    CHECK(count(*coarse, "steps") == 200);
    // A bake that ends off the step's grid steps on along the grid past its end (a slice that
    // follows goes on from there); the steps counted are those that end by 1 s (to 0.96 s).
    auto odd = timeline_of(with_param(doc, "step", 0.08));
    odd->bake(1.0);
    CHECK(count(*odd, "steps") == 12);
    CHECK(odd->baked_until() == 1.0);
    // The counts the backend reports.
    for (const char *name : {"contacts", "sphere shapes", "box shapes", "convex hulls",
                             "triangle meshes", "steps coasted", "releases from keys"})
        CHECK(count(*by_default, name) >= 0.0);
    CHECK(count(*by_default, "contacts") == 1); // the first bounce, at 0.71 s
}

TEST_CASE("a parameter out of range is refused by the host with a message naming it") {
    Document doc;
    doc.add_model(model("ball", "sphere", true, true), placed({0, 3, 0}));
    CHECK_THROWS_WITH(timeline_of(with_param(doc, "step", 1.0)),
                      Catch::Contains("parameter 'step' of plugin 'physics.bullet'") &&
                          Catch::Contains("outside"));
    CHECK_THROWS_WITH(timeline_of(with_param(doc, "step", 0.0)), Catch::Contains("'step'"));
    CHECK_THROWS_WITH(timeline_of(with_param(doc, "solver_iterations", 2.5)),
                      Catch::Contains("'solver_iterations'") && Catch::Contains("whole number"));
    CHECK_THROWS_WITH(timeline_of(with_param(doc, "restitution", 1.5)),
                      Catch::Contains("'restitution'"));
    CHECK_THROWS_WITH(timeline_of(with_param(doc, "ccd", 2.0)), Catch::Contains("'ccd'"));
    CHECK_THROWS_WITH(timeline_of(with_param(doc, "no_such_thing", 1.0)),
                      Catch::Contains("no parameter 'no_such_thing'"));
    // The defaults, as the descriptor gives them.
    const PluginInfo *info = env().plugins.find("physics.bullet");
    REQUIRE(info);
    PluginInstance instance(*info, env().plugins.host());
    CHECK(instance.get_param("step")[0] == Approx(1.0 / 240.0));
    CHECK(instance.get_param("solver_iterations")[0] == 10.0);
    CHECK(instance.get_param("ccd")[0] == 1.0);
    CHECK(instance.get_param("rotate_on_contact")[0] == 0.0);
    CHECK(instance.get_param("friction")[0] == 0.0);
    CHECK(instance.get_param("restitution")[0] == 1.0);
}

TEST_CASE("each model's shape is chosen from its mesh, logged and counted") {
    take_log();
    Document doc;
    doc.add_model(model("floor", "plane", false, false), placed({0, 0, 0}, glm::dvec3(10.0)));
    doc.add_model(model("ball", "sphere", true, true), placed({0, 3, 0}, glm::dvec3(0.5)));
    doc.add_model(model("egg", "sphere", true, true), placed({3, 3, 0}, {0.3, 0.5, 0.3}));
    doc.add_model(model("block", "cube", false, false), placed({-3, 0.5, 0}, glm::dvec3(0.5)));
    doc.add_model(model("ring", "torus", true, true), placed({0, 6, 3}));
    doc.add_model(model("steps", "stairs", false, false), placed({0, 0, -6}));
    auto t = timeline_of(doc);
    t->bake(0.1);
    const auto log = take_log();
    CHECK(logged(log, "model 'ball'", "sphere shape (radius 0.5"));
    CHECK(logged(log, "model 'egg'", "convex hull"));            // a sphere scaled unevenly
    CHECK(logged(log, "model 'block'", "box shape (1 x 1 x 1")); // a cube: box against box
    CHECK(logged(log, "model 'floor'", "BVH triangle mesh"));
    CHECK(logged(log, "model 'steps'", "BVH triangle mesh"));    // concave, static
    CHECK(logged(log, "model 'ring'", "GImpact triangle mesh")); // concave, moving
    CHECK(count(*t, "sphere shapes") == 1);
    CHECK(count(*t, "convex hulls") == 1);
    CHECK(count(*t, "box shapes") == 1);
    CHECK(count(*t, "triangle meshes") == 3);
}

TEST_CASE("a closed convex static model a ball starts inside is a room of triangles") {
    take_log();
    Document doc = no_gravity();
    doc.add_model(model("box", "cube", false, false), placed({0, 0, 0}, glm::dvec3(5.0)));
    Model ball = model("ball", "sphere", true, false);
    ball.initial_velocity = {3, 0, 0};
    doc.add_model(ball, placed({0, 0, 0}, glm::dvec3(0.5)));
    auto t = timeline_of(doc);
    t->bake(5.0);
    CHECK(logged(take_log(), "model 'box'", "a room"));
    // Off the inside of x = 5 at 1.5 s, then of x = -5 at 4.5 s.
    const double r = 0.5 * unit_sphere_radius();
    REQUIRE(t->events().size() == 2);
    CHECK(t->events()[0].t == Approx((5.0 - r) / 3.0).margin(1.0 / 240.0));
    CHECK(t->events()[0].normal.x == Approx(-1.0)); // from the wall towards the ball
    CHECK(t->events()[1].t == Approx((5.0 - r) / 3.0 + 2.0 * (5.0 - r) / 3.0).margin(2.0 / 240.0));
    CHECK(t->events()[1].normal.x == Approx(1.0));
    CHECK(t->evaluate(5.0).models[1].velocity.x == Approx(3.0).epsilon(1e-12));
}

TEST_CASE("models overlapping at the start are reported once and ignored until they separate") {
    take_log();
    Document doc = no_gravity();
    // b starts inside a, moving out; it bounces off a wall at x = 3 and meets a again.
    doc.add_model(model("wall", "plane", false, false),
                  placed({3, 0, 0}, glm::dvec3(2.0), {0, 0, 90}));
    doc.add_model(model("a", "sphere", true, false), placed({0, 0, 0}, glm::dvec3(0.5)));
    Model b = model("b", "sphere", true, false);
    b.initial_velocity = {1, 0, 0};
    doc.add_model(b, placed({0.5, 0, 0}, glm::dvec3(0.5)));
    auto t = timeline_of(doc);
    t->bake(5.0);
    const auto log = take_log();
    CHECK(std::count_if(log.begin(), log.end(), [](const std::string &l) {
              return l.find("'a' and 'b' overlap") != std::string::npos;
          }) == 1);
    const double r = 0.5 * unit_sphere_radius();
    REQUIRE(t->events().size() == 2);
    CHECK(t->events()[0].b == 0); // the wall, at x = 3 - r
    CHECK(t->events()[0].t == Approx(3.0 - r - 0.5).margin(1.0 / 240.0));
    // Back at 1 m/s, b meets a (at rest at x = 0) when 2 r apart: a takes its velocity.
    const double meet = (3.0 - r - 0.5) + (3.0 - r - 2.0 * r);
    CHECK(t->events()[1].t == Approx(meet).margin(2.0 / 240.0));
    CHECK(t->evaluate(5.0).models[1].velocity.x == Approx(-1.0).margin(1e-9));
    CHECK(t->evaluate(5.0).models[2].velocity.x == Approx(0.0).margin(1e-9));
}

TEST_CASE("parts of a jointed model never collide with each other") {
    take_log();
    Document doc = no_gravity();
    Model arm = model("arm", "cube", true, false);
    arm.initial_velocity = {1, 0, 0};
    doc.add_model(arm, placed({0, 0, 0}));
    Model hand = model("hand", "sphere", true, false);
    hand.parent = 0;
    doc.add_model(hand, placed({1.2, 0, 0}, glm::dvec3(0.5))); // overlaps the arm
    auto t = timeline_of(doc);
    t->bake(2.0);
    CHECK(t->events().empty());
    CHECK_FALSE(logged(take_log(), "overlap"));
}

TEST_CASE("a ball resting on a floor is reported at rest, not one segment per step") {
    const double r = 0.5 * unit_sphere_radius();
    Document doc;
    doc.add_model(model("floor", "plane", false, false), placed({0, 0, 0}, glm::dvec3(10.0)));
    doc.add_model(model("ball", "sphere", true, true), placed({0.3, r, 0.2}, glm::dvec3(0.5)));
    auto t = timeline_of(doc);
    t->bake(100.0);
    CHECK(t->events().empty()); // touching at the start is no contact
    CHECK(t->segments(1).size() <= 3);
    const Frame f = t->evaluate(99.0);
    CHECK(f.motion[1] == ANI_MOTION_REST);
    // Within the band Bullet's hops stay in: 2 G dt^2.
    CHECK(std::abs(f.models[1].center.y - r) <= 2.0 * G / (240.0 * 240.0));
}

TEST_CASE("rotate on contact: a ball sliding on a rough floor starts to roll") {
    const double r = 0.5 * unit_sphere_radius();
    Document doc;
    doc.add_model(model("floor", "plane", false, false), placed({0, 0, 0}, glm::dvec3(20.0)));
    Model ball = model("ball", "sphere", true, true);
    ball.initial_velocity = {2, 0, 0};
    doc.add_model(ball, placed({-5, r, 0}, glm::dvec3(0.5)));
    SECTION("without it, models turn only by their keys") {
        auto t = timeline_of(with_param(doc, "friction", 0.4));
        t->bake(3.0);
        CHECK(t->rotations(1).empty());
        CHECK(t->evaluate(3.0).models[1].angles == glm::dvec3(0.0));
        // Friction still acts: without turning, the ball slides to a stop.
        CHECK(std::abs(t->evaluate(3.0).models[1].velocity.x) < 1e-2);
    }
    SECTION("with it, friction turns sliding into rolling: v = 5/7 v0, w = v / r") {
        auto t =
            timeline_of(with_param(with_param(doc, "friction", 0.4), "rotate_on_contact", 1.0));
        t->bake(3.0);
        const auto &turns = t->rotations(1);
        REQUIRE(!turns.empty());
        CHECK(turns.front().t0 == 0.0);
        CHECK(turns.back().t1 == 3.0);
        for (size_t k = 1; k < turns.size(); ++k) {
            CHECK(turns[k].t0 == turns[k - 1].t1); // one after the other, and continuous
            const ani_rotation_segment &p = turns[k - 1];
            const glm::dvec3 w(p.w.x, p.w.y, p.w.z);
            glm::dquat q(p.q0.w, p.q0.x, p.q0.y, p.q0.z);
            if (glm::length(w) > 0.0)
                q = glm::angleAxis(glm::length(w) * (p.t1 - p.t0), w / glm::length(w)) * q;
            const glm::dquat n(turns[k].q0.w, turns[k].q0.x, turns[k].q0.y, turns[k].q0.z);
            CHECK(std::min(glm::length(glm::dvec4(q.x - n.x, q.y - n.y, q.z - n.z, q.w - n.w)),
                           glm::length(glm::dvec4(q.x + n.x, q.y + n.y, q.z + n.z, q.w + n.w))) <
                  1e-6);
        }
        const double v = t->evaluate(3.0).models[1].velocity.x;
        CHECK(v == Approx(2.0 * 5.0 / 7.0).epsilon(2e-3));
        const ani_rotation_segment &last = turns.back();
        CHECK(last.w.z == Approx(-v / r).epsilon(2e-3)); // rolling along +x turns about -z
        CHECK(turns.size() < 100);                       // a few contacts' worth, not one per step
        CHECK(t->segments(1).size() < 100);
        CHECK(t->evaluate(3.0).models[1].angles != glm::dvec3(0.0));
    }
}

TEST_CASE("a bake resumed where another ended goes on as one bake") {
    Document doc;
    doc.add_model(model("floor", "plane", false, false), placed({0, 0, 0}, glm::dvec3(10.0)));
    doc.add_model(model("ball", "sphere", true, true), placed({0.3, 3, 0.2}, glm::dvec3(0.5)));
    auto once = timeline_of(doc), twice = timeline_of(doc);
    once->bake(10.0);
    twice->bake(3.7); // in flight, on the step's grid
    twice->bake(10.0);
    REQUIRE(once->events().size() == twice->events().size());
    for (size_t k = 0; k < once->events().size(); ++k)
        CHECK(twice->events()[k].t == Approx(once->events()[k].t).margin(1e-9));
    for (double time = 0.0; time <= 10.0; time += 0.01)
        CHECK(glm::length(twice->evaluate(time).models[1].center -
                          once->evaluate(time).models[1].center) < 1e-9);

    // And in the middle of a span where a keyed paddle rests after a contact.
    Document paddle = no_gravity();
    paddle.add_model(model("paddle", "cube", false, false), placed({-3, 0, 0}, {0.1, 1, 1}));
    paddle.add_model(model("ball", "sphere", true, false), placed({0, 0, 0}, glm::dvec3(0.5)));
    key(paddle, 2000, 0, placed({1, 0, 0}, {0.1, 1, 1}));
    key(paddle, 4000, 0, placed({3, 0, 0}, {0.1, 1, 1}));
    auto one = timeline_of(paddle), two = timeline_of(paddle);
    one->bake(6.0);
    two->bake(1.5);
    two->bake(6.0);
    for (double time = 0.0; time <= 6.0; time += 0.01)
        for (int m = 0; m < 2; ++m)
            CHECK(glm::length(two->evaluate(time).models[static_cast<size_t>(m)].center -
                              one->evaluate(time).models[static_cast<size_t>(m)].center) < 1e-9);
}

TEST_CASE("a bake that the host cancels stops with nothing new baked") {
    Document doc;
    doc.add_model(model("floor", "plane", false, false), placed({0, 0, 0}, glm::dvec3(10.0)));
    doc.add_model(model("ball", "sphere", true, true), placed({0.3, 3, 0.2}, glm::dvec3(0.5)));
    auto t = timeline_of(doc);
    int calls = 0;
    CHECK_THROWS_AS(t->bake(60.0, [&](double) { return ++calls < 3; }), BakeCancelled);
    CHECK(calls == 3);
    CHECK(t->baked_until() == 0.0);
    CHECK(t->segments(1).empty());
}

TEST_CASE("a scene that would move a model to infinity is refused, naming the model") {
    Document doc;
    Settings s = doc.settings();
    s.gravity = 1e307;
    doc.set_settings(s);
    doc.add_model(model("floor", "plane", false, false), placed({0, 0, 0}, glm::dvec3(10.0)));
    doc.add_model(model("rocket", "sphere", true, true), placed({0, 3, 0}, glm::dvec3(0.5)));
    auto t = timeline_of(doc);
    CHECK_THROWS_WITH(t->bake(10.0), Catch::Contains("'rocket'") && Catch::Contains("not finite"));
    Document falling = doc;
    falling.add_model(model("stone", "sphere", false, true), placed({5, 3, 0}));
    auto u = timeline_of(falling);
    CHECK_THROWS_WITH(u->bake(10.0), Catch::Contains("not finite"));
}

TEST_CASE("a mesh vertex that is not finite is refused, naming the model, and rotation is "
          "reported only when asked for") {
    // The plugin's interface directly, with a sink of our own.
    const PluginInfo *info = env().plugins.find("physics.bullet");
    REQUIRE(info);
    PluginInstance instance(*info, env().plugins.host());
    const auto &api = instance.api<ani_physics_api>();
    const Mesh sphere = load_mesh(env().assets.resolve(ANI_ASSET_MESH, "sphere").value()).mesh;
    std::vector<double> positions;
    for (const glm::dvec3 &p : sphere.positions) positions.insert(positions.end(), {p.x, p.y, p.z});
    ani_mesh_view mesh{};
    mesh.struct_size = sizeof mesh;
    mesh.positions = positions.data();
    mesh.vertex_count = static_cast<uint32_t>(sphere.positions.size());
    mesh.triangles = sphere.triangles.data();
    mesh.triangle_count = static_cast<uint32_t>(sphere.triangle_count());
    mesh.bound_radius = sphere.bound_radius;
    mesh.is_sphere = 1;
    ani_model_desc desc{};
    desc.struct_size = sizeof desc;
    desc.name = "pebble";
    desc.dynamics = 1;
    desc.gravity = 1;
    desc.mass = 1.0;
    ani_model_desc floor_desc = desc;
    floor_desc.name = "ground";
    floor_desc.dynamics = floor_desc.gravity = 0;
    const ani_time_span span{0.0, 0.0};
    ani_physics_model models[2]{};
    for (uint32_t k = 0; k < 2; ++k) {
        models[k].struct_size = sizeof models[k];
        models[k].desc = k == 0 ? &desc : &floor_desc;
        models[k].mesh = &mesh;
        models[k].group = k;
        models[k].keyed_spans = &span;
        models[k].keyed_span_count = 1;
        models[k].start.motion = ANI_MOTION_KEYED;
    }
    ani_physics_scene scene{};
    scene.struct_size = sizeof scene;
    scene.models = models;
    scene.model_count = 2;
    scene.gravity = 9.81;
    scene.down_axis = ANI_AXIS_Y;
    scene.evaluate_keyed = [](void *, uint32_t m, double, ani_model_state *state, ani_vec3 *v) {
        *state = ani_model_state{};
        state->center = m == 0 ? ani_vec3{0.3, 2.2, 0.0} : ani_vec3{0.0, 0.0, 0.0};
        state->scale = ani_vec3{1.0, 1.0, 1.0};
        *v = ani_vec3{0.0, 0.0, 0.0};
        return ANI_OK;
    };
    struct Counts {
        int segments = 0, events = 0, rotations = 0;
    } counts;
    ani_bake_sink sink{};
    sink.context = &counts;
    sink.segment = [](void *c, const ani_motion_segment *) {
        ++static_cast<Counts *>(c)->segments;
    };
    sink.event = [](void *c, const ani_collision_event *) { ++static_cast<Counts *>(c)->events; };
    sink.rotation = [](void *c, const ani_rotation_segment *) {
        ++static_cast<Counts *>(c)->rotations;
    };
    ani_status status{};

    REQUIRE(api.bake(instance.handle(), &scene, 0.0, 3.0, &sink, &status) == ANI_OK);
    CHECK(counts.events >= 1);
    CHECK(counts.segments > 0);
    CHECK(counts.rotations == 0); // rotate_on_contact is off

    instance.set_param("rotate_on_contact", {1.0, 0.0, 0.0, 0.0});
    counts = Counts{};
    REQUIRE(api.bake(instance.handle(), &scene, 0.0, 3.0, &sink, &status) == ANI_OK);
    CHECK(counts.rotations > 0);
    sink.rotation = nullptr; // a host without rotation segments: Bullet does not turn models
    take_log();
    REQUIRE(api.bake(instance.handle(), &scene, 0.0, 3.0, &sink, &status) == ANI_OK);
    CHECK(logged(take_log(), "needs a host that takes rotation segments"));

    positions[4] = std::nan("");
    CHECK(api.bake(instance.handle(), &scene, 0.0, 3.0, &sink, &status) ==
          ANI_ERR_INVALID_ARGUMENT);
    CHECK(std::string(status.message).find("'pebble'") != std::string::npos);
}

TEST_CASE("a keyed ball released at a floor bounces, then its next key takes it back") {
    // As physics.custom's test: Dynamics on, keys from y = 5 at 0 s (initial velocity -2 m/s) to
    // y = 0.25 at 3 s, so y(t) = 5 - 2 t + a t^2 / 2 with a = 5/18; then y = 4 at 4 s. Gravity
    // off. It meets the floor when y(t) = r, before 3 s, is released with its keys' velocity,
    // reflects, and flies until its next key.
    const double r = 0.5 * unit_sphere_radius(), a = 5.0 / 18.0;
    Document doc = no_gravity();
    doc.add_model(model("floor", "plane", false, false), placed({0, 0, 0}, glm::dvec3(10.0)));
    Model ball = model("ball", "sphere", true, false);
    ball.initial_velocity = {0, -2, 0};
    doc.add_model(ball, placed({0, 5, 0}, glm::dvec3(0.5)));
    key(doc, 3000, 1, placed({0, 0.25, 0}, glm::dvec3(0.5)));
    key(doc, 4000, 1, placed({0, 4, 0}, glm::dvec3(0.5)));
    auto t = timeline_of(doc);
    t->bake(5.0);
    const double contact = (2.0 - std::sqrt(4.0 - 2.0 * a * (5.0 - r))) / a;
    const double v_in = -2.0 + a * contact;
    REQUIRE(t->events().size() >= 1);
    // Found back along the step from the depth: off by the keys' curvature over a step.
    CHECK(t->events()[0].t == Approx(contact).margin(a / (240.0 * 240.0)));
    // The approach speed is the keys' over the step: off by a dt at most.
    CHECK(t->events()[0].speed == Approx(-v_in).margin(a / 240.0));
    const ani_motion_segment *flight = segment_at(*t, 1, 0.5 * (contact + 3.0));
    REQUIRE(flight);
    CHECK(flight->motion == ANI_MOTION_FREE);
    // Its keys' velocity where it was released, reflected.
    CHECK(flight->v0.y == Approx(-v_in).margin(a * a / (240.0 * 240.0)));
    CHECK(t->evaluate(3.0).models[1].center.y == Approx(0.25).epsilon(1e-12));
    CHECK(t->evaluate(3.5).motion[1] == ANI_MOTION_KEYED);
    CHECK(t->evaluate(4.5).motion[1] == ANI_MOTION_FREE);
    CHECK(t->stats().backend_counts.at("releases from keys") >= 1);
}

TEST_CASE("a free fall of 300000 s is one segment, on the exact parabola") {
    Document doc = long_document();
    doc.add_model(model("ball", "sphere", true, true), placed({0, 0, 0}, glm::dvec3(0.5)));
    doc.add_model(model("floor", "plane", false, false), placed({50, -10, 0}));
    auto t = timeline_of(doc);
    t->bake(300000.0);
    REQUIRE(t->segments(0).size() == 1);
    const double y = t->evaluate(300000.0).models[0].center.y;
    CHECK(y == Approx(-0.5 * G * 300000.0 * 300000.0).epsilon(1e-12));
    CHECK(count(*t, "steps") == 72000000);
    CHECK(count(*t, "steps coasted") > 71999000);
}

TEST_CASE("a ball bouncing for 300000 s costs its bounces, not its 7.2e7 steps") {
    Document doc = long_document();
    doc.add_model(model("floor", "plane", false, false), placed({0, 0, 0}, glm::dvec3(10.0)));
    doc.add_model(model("ball", "sphere", true, true), placed({0.3, 500, 0.2}, glm::dvec3(0.5)));
    auto t = timeline_of(doc);
    t->bake(300000.0);
    const double r = 0.5 * unit_sphere_radius(), period = 2.0 * std::sqrt(2.0 * (500.0 - r) / G);
    const double bounces = static_cast<double>(t->events().size());
    CHECK(bounces == Approx(300000.0 / period).epsilon(0.05));
    CHECK(t->segments(1).size() <= 2 * t->events().size() + 2);
    for (const ani_motion_segment &s : t->segments(1)) CHECK(s.p0.y <= 500.0 * (1.0 + 1e-9));
}

TEST_CASE("a ball in a closed box for 300000 s stays inside and keeps its energy") {
    const double r = 0.5 * unit_sphere_radius(), half = 5.0, L = half - r;
    Document doc = long_document();
    Settings s = doc.settings();
    s.gravity = 0.0;
    doc.set_settings(s);
    doc.add_model(model("box", "cube", false, false), placed({0, 0, 0}, glm::dvec3(half)));
    Model ball = model("ball", "sphere", true, false);
    const glm::dvec3 v0(0.13, 0.07, 0.03); // 7,666 wall hits in 300000 s
    ball.initial_velocity = v0;
    doc.add_model(ball, placed({0.5, -1.0, 2.0}, glm::dvec3(0.5)));
    auto t = timeline_of(doc);
    t->bake(300000.0);
    CHECK(t->events().size() == Approx(7666).epsilon(0.01));
    CHECK(t->segments(1).size() <= 2 * t->events().size() + 2);
    for (const ani_motion_segment &seg : t->segments(1)) {
        for (double p : {seg.p0.x, seg.p0.y, seg.p0.z})
            CHECK(std::abs(p) <= L + glm::length(v0) / 240.0);
        if (seg.t1 - seg.t0 > 2.0 / 240.0)
            CHECK(std::abs(glm::dot(glm::dvec3(seg.v0.x, seg.v0.y, seg.v0.z),
                                    glm::dvec3(seg.v0.x, seg.v0.y, seg.v0.z)) -
                           glm::dot(v0, v0)) <= 1e-12 * glm::dot(v0, v0));
    }
}
