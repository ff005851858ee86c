// The transform gizmo's math against the projection the renderer draws with and against hand
// computed values: a dragged arrow's point stays under the cursor and changes one coordinate, a
// ring's quarter turn is 90 degrees of one stored angle, a box scales one axis, CTRL snaps to
// steps, hit testing finds the handle under the cursor and none away from it; the Transform
// fields change only the component edited; a gizmo drag in the session is one undoable edit.
#include "editor/editor_session.hpp"
#include "editor/gizmo.hpp"
#include "editor/gizmo_drawing.hpp"
#include "editor/transform_fields.hpp"
#include "render/scene_math.hpp"
#include "support.hpp"

#include <catch2/catch.hpp>

#include <glm/gtc/quaternion.hpp>

#include <cmath>

using namespace animator;
using namespace animator::test;
using Catch::Matchers::WithinAbs;

namespace {

constexpr int kWidth = 1000, kHeight = 600;

// A camera at (0, 0, 10) looking down -Z at a model at the origin: the world's x is the
// screen's right, y its up, z points at the viewer.
GizmoView front_view() {
    GizmoView v;
    v.camera.position = {0.0, 0.0, 10.0};
    v.width = kWidth;
    v.height = kHeight;
    return v;
}

// The size of a pixel at the origin in front_view(): the view's height spans 2 * 10 * tan(25).
double front_metres_per_pixel() { return 2.0 * 10.0 * std::tan(glm::radians(25.0)) / kHeight; }

Gizmo place(const GizmoView &view, EditMode mode, const GizmoTarget &target = {}) {
    const auto g = place_gizmo(view, mode, target);
    REQUIRE(g.has_value());
    return *g;
}

glm::dvec2 pixel_of(const GizmoView &view, const glm::dvec3 &p) {
    const auto px = project_to_pixel(view.view_projection(), p, view.width, view.height);
    REQUIRE(px.has_value());
    return *px;
}

} // namespace

TEST_CASE("the gizmo keeps its size on the screen and sits on the model", "[gizmo]") {
    const GizmoView view = front_view();
    for (const double z : {0.0, -20.0, 5.0}) {
        GizmoTarget t;
        t.center = {1.0, -0.5, z};
        const Gizmo g = place(view, EditMode::Translate, t);
        const glm::dvec2 c = pixel_of(view, t.center);
        CHECK_THAT(g.center_pixel.x, WithinAbs(c.x, 1e-9));
        CHECK_THAT(g.center_pixel.y, WithinAbs(c.y, 1e-9));
        // The y arrow is parallel to the screen here: exactly kGizmoPixels long at any depth.
        const glm::dvec2 end = pixel_of(view, g.center + g.axes[1] * g.length);
        CHECK_THAT(glm::length(end - c), WithinAbs(kGizmoPixels, 1e-6));
    }
    CHECK_FALSE(place_gizmo(view, EditMode::Camera, {}).has_value());
    GizmoTarget behind;
    behind.center = {0.0, 0.0, 20.0};
    CHECK_FALSE(place_gizmo(view, EditMode::Translate, behind).has_value());
}

TEST_CASE("dragging the X arrow moves the model along x only, the grabbed point under the cursor", "[gizmo]") {
    const GizmoView view = front_view();
    const Gizmo g = place(view, EditMode::Translate);
    const glm::dvec2 c = g.center_pixel;
    const glm::dvec2 grab = c + glm::dvec2(50.0, 0.0); // on the arrow, 50 px from the centre
    REQUIRE(gizmo_hit(g, view, grab) == GizmoHandle::AxisX);
    // Along the arrow by 120 px.
    const GizmoChange change = gizmo_drag(g, view, GizmoHandle::AxisX, grab, grab + glm::dvec2(120.0, 0.0), false);
    ModelState start;
    start.center = {0.0, 0.0, 0.0};
    start.angles = {10.0, 20.0, 30.0};
    const ModelState s = apply_gizmo_change(start, glm::dmat3(1.0), change);
    // At the model's depth a pixel is 2 * 10 * tan(25 deg) / 600 m.
    CHECK_THAT(s.center.x, WithinAbs(120.0 * front_metres_per_pixel(), 1e-9));
    CHECK(s.center.y == 0.0);
    CHECK(s.center.z == 0.0);
    CHECK(s.angles == start.angles);
    CHECK(s.scale == start.scale);
}

TEST_CASE("an arrow seen at an angle: the model's centre moves along the projected arrow as the cursor did", "[gizmo]") {
    GizmoView view;
    view.width = kWidth;
    view.height = kHeight;
    view.camera.position = {6.0, 5.0, 9.0};
    // Turned towards the origin: yaw about y, then pitch down about x.
    const double yaw = std::atan2(6.0, 9.0), pitch = -std::atan2(5.0, std::sqrt(36.0 + 81.0));
    view.camera.rotation = glm::angleAxis(yaw, glm::dvec3(0, 1, 0)) * glm::angleAxis(pitch, glm::dvec3(1, 0, 0));
    GizmoTarget t;
    t.center = {0.5, 0.2, -0.3};
    const Gizmo g = place(view, EditMode::Translate, t);
    for (int axis = 0; axis < 3; ++axis) {
        const glm::dvec2 c = pixel_of(view, t.center);
        const glm::dvec2 end = pixel_of(view, t.center + g.axes[axis] * g.length);
        const glm::dvec2 dir = glm::normalize(end - c);
        // The grabbed point (60% along the arrow) dragged 25 px along the projected arrow: that
        // point of the axis lands under the cursor, so it moved 25 px on the screen.
        const glm::dvec3 grabbed = t.center + g.axes[axis] * (0.6 * g.length);
        const glm::dvec2 from = pixel_of(view, grabbed), to = from + dir * 25.0;
        const GizmoChange change = gizmo_drag(g, view, static_cast<GizmoHandle>(1 + axis), from, to, false);
        ModelState start;
        start.center = t.center;
        const ModelState s = apply_gizmo_change(start, glm::dmat3(1.0), change);
        const glm::dvec2 after = pixel_of(view, grabbed + (s.center - start.center));
        CHECK_THAT(after.x, WithinAbs(to.x, 1e-6));
        CHECK_THAT(after.y, WithinAbs(to.y, 1e-6));
        for (int other = 0; other < 3; ++other)
            if (other != axis) CHECK(s.center[other] == start.center[other]);
    }
}

TEST_CASE("a plane square moves the model in its plane, the centre square in the view's plane", "[gizmo]") {
    const GizmoView view = front_view();
    const Gizmo g = place(view, EditMode::Translate);
    const double mpp = front_metres_per_pixel();
    // The XY square faces the camera: the model follows the cursor exactly (y up).
    const glm::dvec2 grab = g.center_pixel + glm::dvec2(30.0, -30.0); // 0.375 of the arrow on x and y
    REQUIRE(gizmo_hit(g, view, grab) == GizmoHandle::PlaneXY);
    ModelState start;
    const ModelState s =
        apply_gizmo_change(start, glm::dmat3(1.0), gizmo_drag(g, view, GizmoHandle::PlaneXY, grab, grab + glm::dvec2(40.0, 25.0), false));
    CHECK_THAT(s.center.x, WithinAbs(40.0 * mpp, 1e-9));
    CHECK_THAT(s.center.y, WithinAbs(-25.0 * mpp, 1e-9));
    CHECK_THAT(s.center.z, WithinAbs(0.0, 1e-12));
    // The centre square: the same in this view, whose plane is the XY plane.
    REQUIRE(gizmo_hit(g, view, g.center_pixel + glm::dvec2(2.0, 3.0)) == GizmoHandle::Center);
    const ModelState c = apply_gizmo_change(
        start, glm::dmat3(1.0), gizmo_drag(g, view, GizmoHandle::Center, g.center_pixel, g.center_pixel + glm::dvec2(-60.0, 10.0), false));
    CHECK_THAT(c.center.x, WithinAbs(-60.0 * mpp, 1e-9));
    CHECK_THAT(c.center.y, WithinAbs(-10.0 * mpp, 1e-9));
    CHECK_THAT(c.center.z, WithinAbs(0.0, 1e-12));

    // The ZX square (the floor's plane) seen from above at an angle: y stays, the point grabbed
    // follows the cursor on the floor.
    GizmoView above = front_view();
    above.camera.position = {0.0, 8.0, 8.0};
    above.camera.rotation = glm::angleAxis(glm::radians(-45.0), glm::dvec3(1, 0, 0));
    const Gizmo h = place(above, EditMode::Translate);
    const glm::dvec3 on_square = (h.axes[2] * 0.4 + h.axes[0] * 0.4) * h.length;
    const glm::dvec2 from = pixel_of(above, on_square);
    REQUIRE(gizmo_hit(h, above, from) == GizmoHandle::PlaneZX);
    const glm::dvec2 to = from + glm::dvec2(35.0, -50.0);
    const ModelState f = apply_gizmo_change(start, glm::dmat3(1.0), gizmo_drag(h, above, GizmoHandle::PlaneZX, from, to, false));
    CHECK(std::abs(f.center.y) < 1e-12);
    const glm::dvec2 landed = pixel_of(above, on_square + f.center);
    CHECK_THAT(landed.x, WithinAbs(to.x, 1e-6));
    CHECK_THAT(landed.y, WithinAbs(to.y, 1e-6));
}

TEST_CASE("a quarter turn of a ring turns exactly one stored angle by 90 degrees, recording the direction", "[gizmo]") {
    const GizmoView view = front_view();
    const Gizmo g = place(view, EditMode::Rotate);
    const glm::dvec2 c = g.center_pixel;
    // The Z ring faces the viewer: a circle of kGizmoPixels about the centre.
    // Between the X and Y rings, which are seen edge on (a vertical and a horizontal line).
    const double r = kGizmoPixels * std::sqrt(0.5);
    const glm::dvec2 from = c + glm::dvec2(r, -r), to = c + glm::dvec2(-r, -r);
    REQUIRE(gizmo_hit(g, view, from) == GizmoHandle::AxisZ);
    ModelState start;
    start.angles = {0.0, 0.0, 10.0};
    // From half past one to half past ten: counter-clockwise about +z, which points at the viewer.
    const GizmoChange ccw = gizmo_drag(g, view, GizmoHandle::AxisZ, from, to, false);
    const ModelState s = apply_gizmo_change(start, glm::dmat3(1.0), ccw);
    CHECK_THAT(s.angles.z, WithinAbs(100.0, 1e-9));
    CHECK(s.angles.x == 0.0);
    CHECK(s.angles.y == 0.0);
    CHECK(s.turn.z == -1.0); // counter-clockwise: the seed's ccw
    CHECK(s.center == start.center);
    // Back the other way, a quarter turn clockwise: 10 - 90 wraps to 280.
    const ModelState back = apply_gizmo_change(start, glm::dmat3(1.0), gizmo_drag(g, view, GizmoHandle::AxisZ, to, from, false));
    CHECK_THAT(back.angles.z, WithinAbs(280.0, 1e-9));
    CHECK(back.turn.z == 1.0);

    // Past half a turn: the turn so far is carried from one update to the next.
    double turned = 0.0;
    for (int step = 1; step <= 12; ++step) { // 12 steps of 25 degrees: 300 degrees
        const double a = glm::radians(25.0 * step);
        const glm::dvec2 p = c + kGizmoPixels * glm::dvec2(std::cos(a), -std::sin(a));
        turned = gizmo_drag(g, view, GizmoHandle::AxisZ, c + glm::dvec2(kGizmoPixels, 0.0), p, false, turned).degrees;
    }
    CHECK_THAT(turned, WithinAbs(300.0, 1e-9));
}

TEST_CASE("the rings are gimbal rings: the Y ring turns angles.y about the x-turned y axis", "[gizmo]") {
    const GizmoView view = front_view();
    GizmoTarget t;
    t.angles = {90.0, 0.0, 0.0}; // Rx(90) turns y onto z: the Y ring now faces the viewer
    const Gizmo g = place(view, EditMode::Rotate, t);
    CHECK_THAT(g.axes[1].z, WithinAbs(1.0, 1e-12));
    const glm::dvec2 c = g.center_pixel;
    const glm::dvec2 right = c + glm::dvec2(kGizmoPixels, 0.0), top = c + glm::dvec2(0.0, -kGizmoPixels);
    REQUIRE(gizmo_hit(g, view, c + glm::dvec2(-kGizmoPixels * 0.7071, kGizmoPixels * 0.7071)) == GizmoHandle::AxisY);
    ModelState start;
    start.angles = t.angles;
    const ModelState s = apply_gizmo_change(start, glm::dmat3(1.0), gizmo_drag(g, view, GizmoHandle::AxisY, right, top, false));
    CHECK_THAT(s.angles.y, WithinAbs(90.0, 1e-9));
    CHECK(s.angles.x == 90.0);
    CHECK(s.angles.z == 0.0);
    // The model's matrix turned by 90 degrees about world z, as the ring showed.
    ModelPose before, after;
    before.angles = start.angles;
    after.angles = s.angles;
    const glm::dvec3 x_after = glm::dmat3(model_matrix(after)) * glm::dvec3(1, 0, 0);
    const glm::dvec3 expected = glm::dmat3(glm::mat3_cast(glm::angleAxis(glm::radians(90.0), glm::dvec3(0, 0, 1)))) *
                                (glm::dmat3(model_matrix(before)) * glm::dvec3(1, 0, 0));
    CHECK_THAT(x_after.x, WithinAbs(expected.x, 1e-9));
    CHECK_THAT(x_after.y, WithinAbs(expected.y, 1e-9));
    CHECK_THAT(x_after.z, WithinAbs(expected.z, 1e-9));
}

TEST_CASE("a scale box scales its axis by the distance dragged along it, the centre box all three", "[gizmo]") {
    const GizmoView view = front_view();
    const Gizmo g = place(view, EditMode::Scale);
    const glm::dvec2 box = g.center_pixel + glm::dvec2(kGizmoPixels, 0.0);
    REQUIRE(gizmo_hit(g, view, box + glm::dvec2(4.0, -4.0)) == GizmoHandle::AxisX);
    ModelState start;
    start.scale = {2.0, 1.0, 0.5};
    // Out by half the box's distance from the centre: x grows by half.
    const ModelState s = apply_gizmo_change(start, glm::dmat3(1.0), gizmo_drag(g, view, GizmoHandle::AxisX, box, box + glm::dvec2(40.0, 13.0), false));
    CHECK_THAT(s.scale.x, WithinAbs(3.0, 1e-12));
    CHECK(s.scale.y == 1.0);
    CHECK(s.scale.z == 0.5);
    // Never flat or mirrored, however far in it is dragged.
    const ModelState in = apply_gizmo_change(start, glm::dmat3(1.0), gizmo_drag(g, view, GizmoHandle::AxisX, box, box - glm::dvec2(500.0, 0.0), false));
    CHECK(in.scale.x > 0.0);
    // The centre box: right and up grow, all three alike.
    const ModelState u = apply_gizmo_change(
        start, glm::dmat3(1.0), gizmo_drag(g, view, GizmoHandle::Center, g.center_pixel, g.center_pixel + glm::dvec2(20.0, -20.0), false));
    CHECK_THAT(u.scale.x, WithinAbs(2.0 * 1.5, 1e-12));
    CHECK_THAT(u.scale.y, WithinAbs(1.0 * 1.5, 1e-12));
    CHECK_THAT(u.scale.z, WithinAbs(0.5 * 1.5, 1e-12));
}

TEST_CASE("CTRL snaps a move to 0.1 m, a turn to 15 degrees, a scale factor to 0.1", "[gizmo]") {
    const GizmoView view = front_view();
    const double mpp = front_metres_per_pixel();
    const Gizmo t = place(view, EditMode::Translate);
    const glm::dvec2 grab = t.center_pixel + glm::dvec2(50.0, 0.0);
    ModelState start;
    start.center = {0.03, 0.0, 0.0};
    for (const double px : {37.0, 91.0, -140.0, 3.0}) {
        const ModelState s = apply_gizmo_change(start, glm::dmat3(1.0), gizmo_drag(t, view, GizmoHandle::AxisX, grab, grab + glm::dvec2(px, 0.0), true));
        const double moved = s.center.x - start.center.x;
        CHECK_THAT(moved, WithinAbs(std::round(px * mpp / 0.1) * 0.1, 1e-12));
        CHECK_THAT(std::remainder(moved, 0.1), WithinAbs(0.0, 1e-12));
    }
    const Gizmo r = place(view, EditMode::Rotate);
    const glm::dvec2 right = r.center_pixel + glm::dvec2(kGizmoPixels, 0.0);
    for (const double deg : {40.0, 100.0, -52.0, 7.0}) {
        const glm::dvec2 to = r.center_pixel + kGizmoPixels * glm::dvec2(std::cos(glm::radians(deg)), -std::sin(glm::radians(deg)));
        const GizmoChange c = gizmo_drag(r, view, GizmoHandle::AxisZ, right, to, true);
        CHECK_THAT(c.degrees, WithinAbs(std::round(deg / 15.0) * 15.0, 1e-9));
        CHECK_THAT(std::remainder(c.degrees, 15.0), WithinAbs(0.0, 1e-9));
    }
    const Gizmo sc = place(view, EditMode::Scale);
    const glm::dvec2 box = sc.center_pixel + glm::dvec2(kGizmoPixels, 0.0);
    const GizmoChange f = gizmo_drag(sc, view, GizmoHandle::AxisX, box, box + glm::dvec2(27.0, 0.0), true);
    CHECK_THAT(f.factor.x, WithinAbs(1.3, 1e-12)); // 1 + 27/80 = 1.3375
}

TEST_CASE("hit testing picks the handle under the cursor and none away from the gizmo", "[gizmo]") {
    const GizmoView view = front_view();
    const Gizmo g = place(view, EditMode::Translate);
    const glm::dvec2 c = g.center_pixel;
    CHECK(gizmo_hit(g, view, c) == GizmoHandle::Center);
    CHECK(gizmo_hit(g, view, c + glm::dvec2(60.0, 4.0)) == GizmoHandle::AxisX);
    CHECK(gizmo_hit(g, view, c + glm::dvec2(-3.0, -70.0)) == GizmoHandle::AxisY);
    CHECK(gizmo_hit(g, view, c + glm::dvec2(60.0, 12.0)) == GizmoHandle::None);
    CHECK(gizmo_hit(g, view, c + glm::dvec2(200.0, 200.0)) == GizmoHandle::None);
    CHECK(gizmo_hit(g, view, c + glm::dvec2(-60.0, 0.0)) == GizmoHandle::None);
    // The rings: on a ring, and inside it (away from the others) nothing.
    const Gizmo r = place(view, EditMode::Rotate);
    CHECK(gizmo_hit(r, view, c + (kGizmoPixels + 3.0) * glm::dvec2(0.7071, 0.7071)) == GizmoHandle::AxisZ);
    CHECK(gizmo_hit(r, view, c + glm::dvec2(40.0, 40.0)) == GizmoHandle::None);
    // The X ring is seen edge on here: a vertical line through the centre.
    CHECK(gizmo_hit(r, view, c + glm::dvec2(2.0, 50.0)) == GizmoHandle::AxisX);
    // What is drawn is what is hit: the X arrow's pixels are red, the hovered one yellow.
    const OverlayTriangles t = gizmo_triangles(gizmo_shapes(g, view), GizmoHandle::AxisY);
    bool red = false, yellow = false;
    for (const OverlayVertex &v : t.vertices) {
        red = red || v.colour == gizmo_colour(0, false);
        yellow = yellow || v.colour == gizmo_colour(1, true);
    }
    CHECK(red);
    CHECK(yellow);
}

TEST_CASE("a child's arrows are its parent's axes: an arrow changes one stored coordinate", "[gizmo]") {
    const GizmoView view = front_view();
    GizmoTarget t;
    // The parent is turned 90 degrees about z and doubled: the child's x points up the screen.
    t.parent = glm::dmat3(glm::mat3_cast(glm::angleAxis(glm::radians(90.0), glm::dvec3(0, 0, 1)))) * 2.0;
    const Gizmo g = place(view, EditMode::Translate, t);
    CHECK_THAT(g.axes[0].y, WithinAbs(1.0, 1e-12));
    const glm::dvec2 grab = g.center_pixel + glm::dvec2(0.0, -50.0);
    REQUIRE(gizmo_hit(g, view, grab) == GizmoHandle::AxisX);
    ModelState start;
    start.center = {1.0, 2.0, 3.0};
    const ModelState s = apply_gizmo_change(start, t.parent, gizmo_drag(g, view, GizmoHandle::AxisX, grab, grab + glm::dvec2(0.0, -100.0), false));
    // 100 px up is 100 * mpp metres in the world, half that in the doubled parent's frame.
    CHECK_THAT(s.center.x - start.center.x, WithinAbs(50.0 * front_metres_per_pixel(), 1e-9));
    CHECK(s.center.y == 2.0);
    CHECK(s.center.z == 3.0);
}

TEST_CASE("the Transform fields change only the component edited, on every selected model", "[gizmo]") {
    ModelState a, b;
    a.center = {1.0, 2.0, 3.0};
    a.angles = {10.0, 0.0, 0.0};
    b.center = {-1.0, 2.0, 5.0};
    b.scale = {2.0, 2.0, 2.0};
    const auto mixed = transform_mixed({a, b});
    CHECK(mixed[0]);
    CHECK(mixed[1]);
    CHECK(mixed[2]);
    CHECK_FALSE(transform_mixed({a, a})[0]);
    const TransformValues shown = transform_values(a);
    TransformValues edited = shown;
    edited.position.y = 7.5;
    edited.rotation.x = -20.0; // turned down past 0: wraps, clockwise
    const ModelState a2 = with_edited_components(a, shown, edited);
    const ModelState b2 = with_edited_components(b, shown, edited);
    CHECK(a2.center == glm::dvec3(1.0, 7.5, 3.0));
    CHECK(b2.center == glm::dvec3(-1.0, 7.5, 5.0));
    CHECK(a2.angles.x == 340.0);
    CHECK(b2.angles.x == 340.0);
    CHECK(a2.turn.x == 1.0);
    CHECK(b2.scale == b.scale);
    CHECK(a2.scale == a.scale);
}

TEST_CASE("a gizmo drag in the session previews, is one undoable edit keying the models, and ESC cancels it", "[gizmo][session]") {
    Environment env;
    EditorSession s(env);
    std::string error;
    REQUIRE(s.open(source_dir() / "assets" / "scenes" / "simple.lua", error));
    const int cube = s.document().find_model("cube");
    REQUIRE(cube >= 0);
    s.click(cube, false);
    s.set_mode(EditMode::Translate);
    const GizmoView view = s.gizmo_view(kWidth, kHeight);
    const auto g = s.gizmo(view);
    REQUIRE(g.has_value());
    const ModelState start = s.state_at_time(cube);
    const glm::dvec2 c = g->center_pixel;
    const glm::dvec2 end = pixel_of(view, g->center + g->axes[0] * g->length);
    const glm::dvec2 grab = c + (end - c) * 0.6;

    // Cancelled: nothing changes.
    REQUIRE(s.begin_gizmo_drag(grab, view));
    CHECK(s.gizmo_handle() == GizmoHandle::AxisX);
    s.update_drag(glm::normalize(end - c) * 50.0);
    CHECK(s.state_at_time(cube).center.x > start.center.x); // the preview
    CHECK(s.frame().models[static_cast<size_t>(cube)].center.x > start.center.x);
    s.cancel_drag();
    CHECK(s.state_at_time(cube) == start);
    CHECK_FALSE(s.dirty());

    // Not on a handle: no gizmo drag (the press selects instead).
    CHECK_FALSE(s.begin_gizmo_drag(c + glm::dvec2(300.0, 200.0), view));
    CHECK_FALSE(s.dragging());

    REQUIRE(s.begin_gizmo_drag(grab, view));
    s.update_drag(glm::normalize(end - c) * 50.0);
    const GizmoChange expected = gizmo_drag(*g, view, GizmoHandle::AxisX, grab, grab + glm::normalize(end - c) * 50.0, false);
    s.end_drag();
    const ModelState keyed = *s.document().keyframes().front().states[static_cast<size_t>(cube)];
    CHECK_THAT(keyed.center.x, WithinAbs(start.center.x + expected.move.x, 1e-12));
    CHECK(keyed.center.y == start.center.y);
    CHECK(keyed.center.z == start.center.z);
    CHECK(s.undo());
    CHECK(s.document().keyframes().front().states[static_cast<size_t>(cube)]->center == start.center);

    // The Transform fields' change: one edit at a new time, a keyframe keying the cube.
    s.set_time_ms(2000);
    REQUIRE(s.keyframe_here() < 0);
    ModelState typed = s.state_at_time(cube);
    typed.center.y = 2.5;
    REQUIRE(s.key_states({{cube, typed}}, &error));
    REQUIRE(s.keyframe_here() >= 0);
    CHECK(s.document().keyframes()[static_cast<size_t>(s.keyframe_here())].states[static_cast<size_t>(cube)]->center.y == 2.5);
    CHECK(s.undo());
    CHECK(s.keyframe_here() < 0);

    // Camera mode has no gizmo.
    s.set_mode(EditMode::Camera);
    CHECK_FALSE(s.gizmo(view).has_value());
}

TEST_CASE("every handle the gizmo draws has a tooltip saying what dragging it does", "[gizmo][tooltips]") {
    const GizmoView view = front_view();
    for (EditMode mode : {EditMode::Translate, EditMode::Rotate, EditMode::Scale}) {
        const Gizmo g = place(view, mode);
        const auto shapes = gizmo_shapes(g, view);
        REQUIRE_FALSE(shapes.empty());
        for (const GizmoShape &s : shapes) {
            const char *tip = gizmo_handle_tip(mode, s.handle);
            INFO("mode " << static_cast<int>(mode) << ", handle " << static_cast<int>(s.handle));
            REQUIRE(tip != nullptr);
            CHECK(std::string(tip).find("Drag") == 0);
        }
    }
    CHECK(gizmo_handle_tip(EditMode::Translate, GizmoHandle::None) == nullptr);
    CHECK(gizmo_handle_tip(EditMode::Camera, GizmoHandle::AxisX) == nullptr);
}
