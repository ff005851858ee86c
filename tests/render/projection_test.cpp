// A model moved by a keyframe is drawn where the camera's projection puts it: the pixel is
// computed here independently of the renderer (glm::lookAt and glm::perspective from the camera's
// position, rotation and field of view), and the model's colour must be found there.
#include "render_support.hpp"

#include "timeline/timeline.hpp"

#include <catch2/catch.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

using namespace animator;
using namespace animator::test;

namespace {

const int kWidth = 160, kHeight = 120;

glm::ivec2 expected_pixel(const CameraState &camera, const glm::dvec3 &world) {
    const glm::dvec3 forward = camera.rotation * glm::dvec3(0, 0, -1);
    const glm::dvec3 up = camera.rotation * glm::dvec3(0, 1, 0);
    const glm::dmat4 view = glm::lookAt(camera.position, camera.position + forward, up);
    const glm::dmat4 projection =
        glm::perspective(glm::radians(camera.fov_degrees), double(kWidth) / kHeight, 0.1, 100.0);
    const glm::dvec4 clip = projection * view * glm::dvec4(world, 1.0);
    const glm::dvec2 ndc = glm::dvec2(clip) / clip.w;
    return {int((ndc.x + 1.0) / 2.0 * kWidth), int((1.0 - ndc.y) / 2.0 * kHeight)};
}

bool is_green(const glm::ivec3 &c) {
    return c.g > 60 && c.g > 3 * c.r && c.g > 3 * c.b;
}

} // namespace

TEST_CASE("a model moved by a keyframe appears where the camera projection says") {
    const CameraState camera = make_camera({0.5, 1.0, 9.0}, 10, -5, 40);
    Document doc = make_document(camera);
    doc.add_model(make_model("mover", "sphere", {0.0, 1.0, 0.0}),
                  make_state({-2, 0, 0}, glm::dvec3(0.3)));
    Keyframe later;
    later.time_ms = 2000;
    later.states = {make_state({2.5, 1.5, -1}, glm::dvec3(0.3))};
    doc.insert_keyframe(later);

    Timeline timeline(doc, environment().plugins);
    timeline.bake(2.0);
    const Frame start = timeline.evaluate(0.0), middle = timeline.evaluate(1.0);
    // Linear interpolation: half way at t = 1 s.
    REQUIRE(middle.models[0].center.x == Approx(0.25));
    REQUIRE(middle.models[0].center.y == Approx(0.75));
    REQUIRE(middle.models[0].center.z == Approx(-0.5));

    const glm::ivec2 at_start = expected_pixel(camera, {-2, 0, 0});
    const glm::ivec2 at_middle = expected_pixel(camera, middle.models[0].center);
    REQUIRE(at_start != at_middle);
    for (auto p : {at_start, at_middle}) {
        REQUIRE(p.x > 2);
        REQUIRE(p.x < kWidth - 3);
        REQUIRE(p.y > 2);
        REQUIRE(p.y < kHeight - 3);
    }

    const Image first = render_frame(doc, start, kWidth, kHeight).image;
    const Image second = render_frame(doc, middle, kWidth, kHeight).image;
    CAPTURE(at_start.x, at_start.y, at_middle.x, at_middle.y);
    CHECK(is_green(pixel(first, at_start.x, at_start.y)));
    CHECK_FALSE(is_green(pixel(first, at_middle.x, at_middle.y)));
    CHECK(is_green(pixel(second, at_middle.x, at_middle.y)));
    CHECK_FALSE(is_green(pixel(second, at_start.x, at_start.y)));
    // The ball's radius of 0.3 covers a few pixels around its center at this distance.
    for (auto [dx, dy] : {std::pair{2, 0}, {-2, 0}, {0, 2}, {0, -2}})
        CHECK(is_green(pixel(second, at_middle.x + dx, at_middle.y + dy)));
}
