// The free view (editor/free_view.hpp) and the session's use of it: orbiting keeps the distance
// to the pivot and looks at it, panning keeps what is at the pivot's depth under the cursor,
// framing puts every bounding sphere inside the renderer's own frustum, and none of it touches
// the document (no edit, no keyframe, the exported file byte for byte the same).
#include "editor/editor_session.hpp"
#include "editor/free_view.hpp"
#include "render/renderer.hpp"
#include "render/scene_math.hpp"

#include "support.hpp"

#include <catch2/catch.hpp>

#include <fstream>
#include <sstream>
#include <unistd.h>

using namespace animator;
using namespace animator::test;
using Catch::Matchers::WithinAbs;

namespace fs = std::filesystem;

namespace {

glm::dvec3 forward(const CameraState &c) { return glm::normalize(c.rotation) * glm::dvec3(0, 0, -1); }

glm::dmat4 view_projection(const CameraState &c, double aspect) {
    const RenderOptions o; // the renderer's own near and far planes
    return projection_matrix(c.fov_degrees, aspect, o.near_plane, o.far_plane) * view_matrix(c);
}

// A sphere is wholly inside the frustum when it is on the inner side of each of the six planes
// (Gribb and Hartmann: the planes are sums and differences of the matrix's rows) by its radius.
bool inside_frustum(const glm::dmat4 &m, const Sphere &s) {
    const glm::dvec4 row[4] = {{m[0][0], m[1][0], m[2][0], m[3][0]},
                               {m[0][1], m[1][1], m[2][1], m[3][1]},
                               {m[0][2], m[1][2], m[2][2], m[3][2]},
                               {m[0][3], m[1][3], m[2][3], m[3][3]}};
    for (int axis = 0; axis < 3; ++axis)
        for (double sign : {1.0, -1.0}) {
            const glm::dvec4 p = row[3] + sign * row[axis];
            const double len = glm::length(glm::dvec3(p));
            if ((glm::dot(glm::dvec3(p), s.center) + p.w) / len < s.radius) return false;
        }
    return true;
}

std::string read_all(const fs::path &p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

} // namespace

TEST_CASE("the free view camera looks at its pivot from its distance", "[free_view]") {
    FreeView v;
    v.pivot = {1, 2, 3};
    v.distance = 7;
    v.yaw = 30;
    v.pitch = 20;
    const CameraState c = free_view_camera(v);
    CHECK_THAT(glm::length(c.position - v.pivot), WithinAbs(7.0, 1e-9));
    CHECK_THAT(glm::dot(forward(c), glm::normalize(v.pivot - c.position)), WithinAbs(1.0, 1e-12));
    CHECK(c.position.y > v.pivot.y); // a positive pitch looks down on the pivot
    // Yaw 0, pitch 0 is the default camera's orientation: looking down -Z.
    FreeView straight;
    CHECK_THAT(glm::length(forward(free_view_camera(straight)) - glm::dvec3(0, 0, -1)), WithinAbs(0.0, 1e-12));
}

TEST_CASE("orbiting keeps the distance to the pivot and keeps looking at it", "[free_view]") {
    FreeView v;
    v.pivot = {0.5, -1, 2};
    v.distance = 12;
    for (glm::dvec2 d : {glm::dvec2(100, 0), glm::dvec2(0, 80), glm::dvec2(-350, 1000), glm::dvec2(37, -41)}) {
        const FreeView o = orbit(v, d);
        const CameraState c = free_view_camera(o);
        CHECK_THAT(glm::length(c.position - v.pivot), WithinAbs(12.0, 1e-9));
        CHECK_THAT(glm::dot(forward(c), glm::normalize(v.pivot - c.position)), WithinAbs(1.0, 1e-12));
        CHECK(o.pitch <= 89.0);
        CHECK(o.pitch >= -89.0);
    }
    // A horizontal drag turns about the vertical only: the height stays.
    CHECK_THAT(free_view_camera(orbit(v, {120, 0})).position.y, WithinAbs(free_view_camera(v).position.y, 1e-9));
}

TEST_CASE("panning keeps the point at the pivot's depth under the cursor", "[free_view]") {
    FreeView v;
    v.pivot = {0, 0, 0};
    v.distance = 12;
    v.yaw = 25;
    v.pitch = 15;
    const int width = 1280, height = 720;
    const double aspect = static_cast<double>(width) / height;
    const auto before = project_to_pixel(view_projection(free_view_camera(v), aspect), v.pivot, width, height);
    const FreeView moved = pan(v, {80, -30}, height);
    const auto after = project_to_pixel(view_projection(free_view_camera(moved), aspect), v.pivot, width, height);
    REQUIRE(before);
    REQUIRE(after);
    CHECK_THAT(after->x - before->x, WithinAbs(80.0, 1e-6));
    CHECK_THAT(after->y - before->y, WithinAbs(-30.0, 1e-6));
    CHECK_THAT(moved.distance, WithinAbs(v.distance, 1e-12));
}

TEST_CASE("zooming changes only the distance, never through the pivot", "[free_view]") {
    FreeView v;
    v.distance = 10;
    CHECK(zoom_wheel(v, 1).distance < 10);
    CHECK(zoom_wheel(v, -1).distance > 10);
    CHECK(zoom_drag(v, {0, 69}).distance < 10);
    CHECK_THAT(zoom_wheel(zoom_wheel(v, 3), -3).distance, WithinAbs(10.0, 1e-9));
    CHECK(zoom_wheel(v, 1e5).distance > 0.0);
    CHECK(zoom_drag(v, {0, 1e6}).distance > 0.0);
}

TEST_CASE("framing puts every model's bounding sphere inside the renderer's frustum", "[free_view]") {
    Environment env;
    EditorSession s(env);
    std::string error;
    for (const char *file : {"assets/animations/cradle.ani", "assets/animations/drop.ani", "assets/scenes/simple.lua"}) {
        REQUIRE(s.open(source_dir() / file, error));
        for (double aspect : {16.0 / 9.0, 0.6, 1.0}) {
            REQUIRE(s.frame_models(false, aspect));
            CHECK(s.free_view());
            const glm::dmat4 vp = view_projection(free_view_camera(s.view()), aspect);
            const auto spheres = s.model_spheres(false);
            REQUIRE_FALSE(spheres.empty());
            for (const Sphere &sphere : spheres) CHECK(inside_frustum(vp, sphere));
        }
    }
}

TEST_CASE("frame selected fits the selection only, and needs one", "[free_view]") {
    Environment env;
    EditorSession s(env);
    std::string error;
    REQUIRE(s.open(source_dir() / "assets" / "animations" / "drop.ani", error));
    CHECK_FALSE(s.frame_models(true, 1.5));
    CHECK_FALSE(s.free_view());
    const int ball = s.document().find_model("ball");
    s.click(ball, false);
    REQUIRE(s.frame_models(true, 1.5));
    const auto spheres = s.model_spheres(true);
    REQUIRE(spheres.size() == 1);
    CHECK_THAT(glm::length(s.view().pivot - spheres[0].center), WithinAbs(0.0, 1e-9));
    // Tight, up to the margin: 1.3 times closer, the ball no longer fits.
    for (double aspect : {1.5, 0.5}) {
        REQUIRE(s.frame_models(true, aspect));
        CHECK(inside_frustum(view_projection(free_view_camera(s.view()), aspect), spheres[0]));
        FreeView closer = s.view();
        closer.distance /= 1.3;
        CHECK_FALSE(inside_frustum(view_projection(free_view_camera(closer), aspect), spheres[0]));
    }
}

TEST_CASE("looking around touches nothing of the document: no edit, no keyframe, the same file", "[free_view]") {
    char tmpl[] = "/tmp/free-view-XXXXXX";
    REQUIRE(mkdtemp(tmpl));
    const fs::path dir = tmpl;
    fs::copy_file(source_dir() / "assets" / "animations" / "drop.ani", dir / "drop.ani");
    Environment env;
    EditorSession s(env);
    std::string error;
    REQUIRE(s.open(dir / "drop.ani", error));
    REQUIRE(s.export_animation().ok);
    const std::string before = read_all(dir / "drop.ani");
    const std::uint64_t version = s.version();
    const CameraState animated = s.frame().camera;

    s.set_time_ms(1500); // away from any keyframe, where a camera move would make one
    s.set_free_view(true);
    // Turned on, it starts from what the animated camera shows.
    CHECK_THAT(glm::length(free_view_camera(s.view()).position - animated.position), WithinAbs(0.0, 1e-9));
    s.set_view(orbit(s.view(), {200, 60}));
    s.set_view(pan(s.view(), {-40, 25}, 720));
    s.set_view(zoom_wheel(s.view(), 3));
    REQUIRE(s.frame_models(false, 16.0 / 9.0));
    CHECK(s.shown_frame().camera.position != s.frame().camera.position);
    s.set_free_view(false);
    CHECK(s.shown_frame().camera == s.frame().camera);

    CHECK(s.version() == version);
    CHECK_FALSE(s.dirty());
    CHECK_FALSE(s.can_undo());
    CHECK(s.document().keyframes().size() == 1);
    CHECK(s.frame().camera == animated);
    REQUIRE(s.export_animation().ok);
    CHECK(read_all(dir / "drop.ani") == before);
    fs::remove_all(dir);
}
