// The mouse's transformations against the projection the renderer draws with: what is dragged
// stays under the cursor, turns are recorded in the direction the user turned.
#include "editor/manipulation.hpp"
#include "render/scene_math.hpp"

#include <catch2/catch.hpp>

#include <glm/gtc/quaternion.hpp>

using namespace animator;
using Catch::Matchers::WithinAbs;

namespace {

constexpr int kWidth = 1280, kHeight = 720;

glm::dvec2 pixel_of(const CameraState &camera, const glm::dvec3 &p) {
    const glm::dmat4 vp = projection_matrix(camera.fov_degrees, double(kWidth) / kHeight, 0.1, 1000.0) *
                          view_matrix(camera);
    const auto px = project_to_pixel(vp, p, kWidth, kHeight);
    REQUIRE(px.has_value());
    return *px;
}

} // namespace

TEST_CASE("a model dragged in Translate mode stays under the cursor", "[manipulation]") {
    CameraState camera;
    camera.position = {0.0, 1.0, 12.0};
    ModelState start;
    start.center = {1.5, 0.5, 2.0};
    const double depth = camera.position.z - start.center.z;
    const double mpp = metres_per_pixel(depth, camera.fov_degrees, kHeight);
    const glm::dvec2 before = pixel_of(camera, start.center);
    for (const glm::dvec2 delta : {glm::dvec2(120.0, 0.0), glm::dvec2(-35.0, 80.0), glm::dvec2(3.0, -200.0)}) {
        const ModelState s = drag_model(start, EditMode::Translate, DragButton::Right, delta, mpp);
        const glm::dvec2 after = pixel_of(camera, s.center);
        CHECK_THAT(after.x - before.x, WithinAbs(delta.x, 1e-6));
        CHECK_THAT(after.y - before.y, WithinAbs(delta.y, 1e-6));
        CHECK(s.center.z == start.center.z);
        CHECK(s.angles == start.angles);
        CHECK(s.scale == start.scale);
    }
    // The middle button moves along z only, towards the default camera when dragged down.
    const ModelState z = drag_model(start, EditMode::Translate, DragButton::Middle, {40.0, 60.0}, mpp);
    CHECK_THAT(z.center.z - start.center.z, WithinAbs(60.0 * mpp, 1e-12));
    CHECK(z.center.x == start.center.x);
    CHECK(z.center.y == start.center.y);
}

TEST_CASE("the scene follows the cursor when the camera is dragged with the left button", "[manipulation]") {
    CameraState camera;
    camera.position = {2.0, 1.0, 10.0};
    camera.rotation = glm::angleAxis(glm::radians(20.0), glm::dvec3(0, 1, 0));
    const glm::dvec3 forward = camera.rotation * glm::dvec3(0, 0, -1);
    const glm::dvec3 point = camera.position + forward * 8.0; // on the view axis, 8 m away
    const double mpp = metres_per_pixel(8.0, camera.fov_degrees, kHeight);
    const glm::dvec2 before = pixel_of(camera, point);
    const glm::dvec2 delta(-70.0, 45.0);
    const CameraState moved = drag_camera(camera, DragButton::Left, delta, mpp);
    const glm::dvec2 after = pixel_of(moved, point);
    CHECK_THAT(after.x - before.x, WithinAbs(delta.x, 1e-6));
    CHECK_THAT(after.y - before.y, WithinAbs(delta.y, 1e-6));
    CHECK(moved.rotation == camera.rotation);
}

TEST_CASE("camera turns: middle rolls about the view axis, right turns the scene with the cursor", "[manipulation]") {
    const CameraState camera;
    const CameraState rolled = drag_camera(camera, DragButton::Middle, {0.0, 90.0}, 0.01);
    const glm::dvec3 forward = rolled.rotation * glm::dvec3(0, 0, -1);
    CHECK_THAT(forward.z, WithinAbs(-1.0, 1e-12)); // still looking down -z
    const glm::dvec3 up = rolled.rotation * glm::dvec3(0, 1, 0);
    CHECK_THAT(glm::degrees(std::acos(up.y)), WithinAbs(90.0 * kDegreesPerPixel, 1e-9));
    CHECK(rolled.position == camera.position);

    // A point ahead and slightly right of centre moves further right when dragged right.
    const glm::dvec3 point(0.5, 0.0, -10.0);
    const CameraState turned = drag_camera(camera, DragButton::Right, {30.0, 0.0}, 0.01);
    CHECK(pixel_of(turned, point).x > pixel_of(camera, point).x + 1.0);
    CHECK_THAT(glm::degrees(glm::angle(turned.rotation)), WithinAbs(30.0 * kDegreesPerPixel, 1e-9));
}

TEST_CASE("the scroll wheel moves the camera along its view by a tenth of the distance", "[manipulation]") {
    CameraState camera;
    camera.position = {0.0, 0.0, 10.0};
    const CameraState in = scroll_camera(camera, 2.0, 10.0);
    CHECK_THAT(in.position.z, WithinAbs(10.0 - 2.0 * kScrollStep * 10.0, 1e-12));
    const CameraState out = scroll_camera(camera, -1.0, 10.0);
    CHECK_THAT(out.position.z, WithinAbs(10.0 + kScrollStep * 10.0, 1e-12));
}

TEST_CASE("Rotate mode turns the seed's axes and records the direction of the turn", "[manipulation]") {
    ModelState start;
    start.angles = {10.0, 350.0, 0.0};
    // Right drag: x by the vertical movement, z by the horizontal one.
    const ModelState r = drag_model(start, EditMode::Rotate, DragButton::Right, {-40.0, 60.0}, 0.01);
    CHECK_THAT(r.angles.x, WithinAbs(10.0 + 60.0 * kDegreesPerPixel, 1e-12));
    CHECK_THAT(r.angles.z, WithinAbs(360.0 - 40.0 * kDegreesPerPixel, 1e-12)); // wrapped into [0, 360)
    CHECK(r.angles.y == 350.0);
    CHECK(r.turn.x < 0.0); // the angle increased: counter-clockwise, the seed's ccw (docs/interpolation.md)
    CHECK(r.turn.z > 0.0);
    CHECK(r.turn.y == 0.0);
    // Middle drag: y by the vertical movement, through 360.
    const ModelState m = drag_model(start, EditMode::Rotate, DragButton::Middle, {0.0, 40.0}, 0.01);
    CHECK_THAT(m.angles.y, WithinAbs(10.0, 1e-9));
    CHECK(m.turn.y < 0.0);
    CHECK(m.center == start.center);
}

TEST_CASE("Scale mode scales by exp(0.01 px), right and up growing", "[manipulation]") {
    ModelState start;
    start.scale = {1.0, 2.0, 0.5};
    const ModelState s = drag_model(start, EditMode::Scale, DragButton::Right, {69.0, -69.0}, 0.01);
    CHECK_THAT(s.scale.x, WithinAbs(std::exp(0.69), 1e-12));
    CHECK_THAT(s.scale.y, WithinAbs(2.0 * std::exp(0.69), 1e-12));
    CHECK(s.scale.z == 0.5);
    // Dragging down shrinks, and never through zero into a mirror image.
    const ModelState z = drag_model(start, EditMode::Scale, DragButton::Middle, {0.0, 500.0}, 0.01);
    CHECK_THAT(z.scale.z, WithinAbs(0.5 * std::exp(-5.0), 1e-15));
    // The left button selects; it transforms nothing.
    CHECK(drag_model(start, EditMode::Scale, DragButton::Left, {50.0, 50.0}, 0.01) == start);
}
