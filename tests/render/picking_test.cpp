// Picking for the editor: the model under a pixel, from the ID pass.
#include "render_support.hpp"

#include "render/scene_math.hpp"

#include <catch2/catch.hpp>

using namespace animator;
using namespace animator::test;

TEST_CASE("pick names the model under a pixel, the nearest one where they overlap") {
    gl_context();
    Document doc = make_document(make_camera({0, 0, 8}));
    doc.add_model(make_model("left", "sphere", {1, 0, 0}), make_state({-2, 0, 0}, glm::dvec3(0.6)));
    doc.add_model(make_model("right", "cube", {0, 1, 0}), make_state({2, 0, 0}, glm::dvec3(0.6)));
    doc.add_model(make_model("back", "sphere", {0, 0, 1}), make_state({0, 0, -3}, glm::dvec3(1.5)));
    doc.add_model(make_model("front", "sphere", {1, 1, 0}), make_state({0, 0, 0}, glm::dvec3(0.5)));
    Renderer renderer(environment().plugins, environment().assets);
    renderer.set_document(doc, meshes_of(doc));
    const Frame frame = first_frame(doc);

    const int width = 200, height = 100;
    const glm::dmat4 vp = projection_matrix(50.0, 2.0, 0.1, 1000.0) * view_matrix(frame.camera);
    auto pick_at = [&](const glm::dvec3 &world) {
        const auto p = project_to_pixel(vp, world, width, height);
        REQUIRE(p);
        return renderer.pick(frame, width, height, int(p->x), int(p->y));
    };
    CHECK(pick_at({-2, 0, 0}) == 0);
    CHECK(pick_at({2, 0, 0}) == 1);
    CHECK(pick_at({0, 0, 0}) == 3);                          // in front of "back"
    CHECK(pick_at({0, 1.0, -3}) == 2);                       // "back" above "front"
    CHECK(renderer.pick(frame, width, height, 2, 2) == -1);  // nothing in the corner
    CHECK(renderer.pick(frame, width, height, -1, 5) == -1); // outside the target
    CHECK(renderer.pick(frame, width, height, 5, height) == -1);
    // A smaller target (a resized window) picks the same models at its own pixels.
    CHECK(renderer.pick(frame, width / 2, height / 2, width / 4, height / 4) == 3);
}

TEST_CASE("hidden models are neither drawn, outlined nor picked, the others are as before") {
    gl_context();
    Document doc = make_document(make_camera({0, 0, 8}));
    doc.add_model(make_model("back", "sphere", {0, 0, 1}), make_state({0, 0, -3}, glm::dvec3(1.5)));
    doc.add_model(make_model("front", "sphere", {1, 1, 0}), make_state({0, 0, 0}, glm::dvec3(0.5)));
    Renderer renderer(environment().plugins, environment().assets);
    renderer.set_document(doc, meshes_of(doc));
    const Frame frame = first_frame(doc);
    const int width = 200, height = 100;
    OffscreenFramebuffer framebuffer(width, height);
    Image image;
    image.width = width;
    image.height = height;

    CHECK(renderer.pick(frame, width, height, width / 2, height / 2) == 1);
    renderer.draw(frame, framebuffer.target(), {1});
    CHECK(renderer.stats().models_drawn == 2);
    framebuffer.read_rgb(image.rgb);
    const glm::ivec3 front = pixel(image, width / 2, height / 2);
    CHECK(front.r > front.b + 40); // the yellow front sphere, tinted as selected

    // "front" hidden: the click goes through to "back", and "back" is what the middle shows.
    renderer.set_hidden({1});
    CHECK(renderer.pick(frame, width, height, width / 2, height / 2) == 0);
    renderer.draw(frame, framebuffer.target(), {1}, {1});
    CHECK(renderer.stats().models_drawn == 1);
    CHECK(renderer.stats().models_culled == 0); // hidden is not culled: it is left out
    framebuffer.read_rgb(image.rgb);
    const glm::ivec3 back = pixel(image, width / 2, height / 2);
    CHECK(back.b > back.r + 40);
    // Nor its selection outline or flag ring: the image is that of "back" alone.
    Document alone = make_document(make_camera({0, 0, 8}));
    alone.add_model(make_model("back", "sphere", {0, 0, 1}), make_state({0, 0, -3}, glm::dvec3(1.5)));
    const Rendered expected = render_document(alone, width, height);
    CHECK(image.rgb == expected.image.rgb);

    // Both hidden: nothing to pick; shown again, as at first.
    renderer.set_hidden({0, 1});
    CHECK(renderer.pick(frame, width, height, width / 2, height / 2) == -1);
    renderer.set_hidden({});
    CHECK(renderer.pick(frame, width, height, width / 2, height / 2) == 1);
}
