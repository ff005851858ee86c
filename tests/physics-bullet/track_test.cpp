// The pieces of physics.bullet that need no Bullet world: the track that turns Bullet's steps
// into closed-form segments, and the mesh analysis that picks shapes.
#include "shapes.hpp"
#include "track.hpp"

#include "bullet_support.hpp"

#include <catch2/catch.hpp>
#include <glm/geometric.hpp>

#include <cmath>
#include <memory>
#include <vector>

using namespace animator;
using namespace animator::bullet_test;
using physics_bullet::Track;

namespace {

glm::dvec3 vec(const ani_vec3 &v) {
    return {v.x, v.y, v.z};
}

glm::dvec3 at(const ani_motion_segment &s, double t) {
    const double tau = t - s.t0;
    return vec(s.p0) + vec(s.v0) * tau + 0.5 * tau * tau * vec(s.a);
}

struct Recorder {
    std::vector<ani_motion_segment> segments;
    Track track{7, [this](const ani_motion_segment &s) { segments.push_back(s); }};
};

} // namespace

TEST_CASE("the track reports Bullet's semi-implicit Euler steps of a free flight as one parabola "
          "through every step") {
    const double dt = 1.0 / 240.0;
    const glm::dvec3 a(0.0, -9.81, 0.0);
    glm::dvec3 x(1.0, 20.0, -3.0), v(2.0, 5.0, 0.5);
    Recorder r;
    r.track.start_stepping(0.0, x, v, a, dt);
    std::vector<glm::dvec3> positions = {x};
    for (int k = 1; k <= 2400; ++k) { // v' = v + a h, x' = x + v' h, as Bullet does
        v += a * dt;
        x += v * dt;
        const Track::State s = r.track.step(k * dt, dt, true, x, v);
        x = s.x;
        v = s.v;
        positions.push_back(x);
    }
    r.track.close(2400 * dt);
    REQUIRE(r.segments.size() == 1);
    const ani_motion_segment &s = r.segments[0];
    CHECK(s.model == 7);
    CHECK(s.motion == ANI_MOTION_FREE);
    for (size_t k = 0; k < positions.size(); k += 97)
        CHECK(glm::length(at(s, static_cast<double>(k) * dt) - positions[k]) <= 1e-12 * 300.0);
}

TEST_CASE("a step off the parabola (a contact) ends the segment, and segments stay continuous") {
    const double dt = 0.01;
    const glm::dvec3 a(0.0, -9.81, 0.0);
    glm::dvec3 x(0.0, 1.0, 0.0), v(0.0, 0.0, 0.0);
    Recorder r;
    r.track.start_stepping(0.0, x, v, a, dt);
    std::vector<glm::dvec3> positions = {x};
    for (int k = 1; k <= 100; ++k) {
        v += a * dt;
        if (x.y < 0.0 && v.y < 0.0) v.y = -v.y; // a bounce
        x += v * dt;
        const Track::State s = r.track.step(k * dt, dt, true, x, v);
        x = s.x;
        v = s.v;
        positions.push_back(x);
    }
    r.track.close(1.0);
    REQUIRE(r.segments.size() >= 3);
    CHECK(r.segments.size() <= 6);
    CHECK(r.segments.front().t0 == 0.0);
    CHECK(r.segments.back().t1 == 1.0);
    for (size_t k = 1; k < r.segments.size(); ++k) {
        CHECK(r.segments[k].t0 == r.segments[k - 1].t1);
        CHECK(glm::length(at(r.segments[k - 1], r.segments[k - 1].t1) - vec(r.segments[k].p0)) <=
              1e-12);
    }
    // Every step's position is on the segment covering it.
    for (size_t k = 0; k < positions.size(); ++k) {
        const double t = static_cast<double>(k) * dt;
        for (const ani_motion_segment &s : r.segments)
            if (s.t0 <= t && t <= s.t1) CHECK(glm::length(at(s, t) - positions[k]) <= 1e-12);
    }
}

TEST_CASE(
    "a body at rest without acceleration is reported at rest, and coasting extends the stretch") {
    Recorder r;
    r.track.start_stepping(0.0, glm::dvec3(1, 2, 3), glm::dvec3(0.0), glm::dvec3(0.0), 0.5);
    r.track.step(0.5, 0.5, true, glm::dvec3(1, 2, 3), glm::dvec3(0.0));
    const Track::State s = r.track.coast(1000.5, 2000);
    CHECK(s.x == glm::dvec3(1, 2, 3));
    r.track.close(1000.5);
    REQUIRE(r.segments.size() == 1);
    CHECK(r.segments[0].motion == ANI_MOTION_REST);
    CHECK(r.segments[0].t1 == 1000.5);
}

TEST_CASE("the mesh analysis: which meshes are closed and convex") {
    auto info = [](const std::string &id) {
        const Mesh mesh = load_mesh(env().assets.resolve(ANI_ASSET_MESH, id).value()).mesh;
        std::vector<double> positions;
        for (const glm::dvec3 &p : mesh.positions)
            positions.insert(positions.end(), {p.x, p.y, p.z});
        ani_mesh_view view{};
        view.struct_size = sizeof view;
        view.positions = positions.data();
        view.vertex_count = static_cast<uint32_t>(mesh.positions.size());
        view.triangles = mesh.triangles.data();
        view.triangle_count = static_cast<uint32_t>(mesh.triangle_count());
        return physics_bullet::analyse_mesh(view);
    };
    for (const char *convex : {"cube", "sphere", "sphere_low", "cylinder", "cone"}) {
        CAPTURE(convex);
        const auto i = info(convex);
        CHECK(i.closed);
        CHECK(i.convex);
    }
    for (const char *concave : {"torus", "stairs"}) {
        CAPTURE(concave);
        const auto i = info(concave);
        CHECK(i.closed);
        CHECK_FALSE(i.convex);
    }
    const auto plane = info("plane"); // open: its triangles, not a hull
    CHECK_FALSE(plane.closed);
    CHECK_FALSE(plane.convex);
    CHECK(plane.has_area);
    CHECK(info("cube").reach == Approx(std::sqrt(3.0)).epsilon(1e-7));
}

TEST_CASE(
    "a mesh that is a box along its own axes gets a box shape, any other convex mesh a hull") {
    struct View {
        std::vector<double> positions;
        std::vector<uint32_t> triangles;
        ani_mesh_view view{};
    };
    auto view_of = [](const std::string &id) {
        const Mesh mesh = load_mesh(env().assets.resolve(ANI_ASSET_MESH, id).value()).mesh;
        auto v = std::make_unique<View>();
        for (const glm::dvec3 &p : mesh.positions)
            v->positions.insert(v->positions.end(), {p.x, p.y, p.z});
        v->triangles = mesh.triangles;
        v->view.struct_size = sizeof v->view;
        v->view.positions = v->positions.data();
        v->view.vertex_count = static_cast<uint32_t>(mesh.positions.size());
        v->view.triangles = v->triangles.data();
        v->view.triangle_count = static_cast<uint32_t>(mesh.triangle_count());
        return v;
    };
    const auto cube = view_of("cube"); // the generated cube: corners at +-1
    const auto box = physics_bullet::box_shape(cube->view, {10.0, 0.25, 1.5}, 0.04);
    REQUIRE(box);
    CHECK(box->kind == physics_bullet::ShapeKind::kBox);
    CHECK(box->describe() == "box shape (20 x 0.5 x 3, margin 0.04)");
    CHECK(box->inner == 0.25);
    CHECK(box->margin == 0.04); // min(0.04, 0.2 x 0.25)
    CHECK(box->reach == Approx(std::sqrt(100.0 + 0.0625 + 2.25)));
    // A thin box: its margin a fifth of its half thickness, inside its faces.
    CHECK(physics_bullet::box_shape(cube->view, {1.0, 0.05, 1.0}, 0.04)->margin == Approx(0.01));
    // Centred on the point it turns about, or not at all (a hull keeps the offset).
    CHECK_FALSE(physics_bullet::box_shape(cube->view, glm::dvec3(1.0), 0.04, {0.0, 0.5, 0.0}));
    // One corner moved: eight corners, but not those of their bounds.
    cube->positions[0] *= 0.5;
    CHECK_FALSE(physics_bullet::box_shape(cube->view, glm::dvec3(1.0), 0.04));
    for (const char *other : {"sphere", "cylinder", "cone", "plane"}) {
        CAPTURE(other);
        CHECK_FALSE(physics_bullet::box_shape(view_of(other)->view, glm::dvec3(1.0), 0.04));
    }
}
