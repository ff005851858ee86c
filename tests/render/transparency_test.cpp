// Beyond the seed: a transparent model shows the models behind it (blended by its transparency),
// and keeps the seed's refracted skybox where nothing else is behind it.
#include "render_support.hpp"

#include <catch2/catch.hpp>

using namespace animator;
using namespace animator::test;

namespace {
Document glass_box(double transparency) {
    Document doc = make_document(make_camera({0, 0, 6}));
    Model box = make_model("box", "cube", {0.6, 0.6, 0.6});
    box.transparency = transparency;
    doc.add_model(box, make_state({0, 0, 0}, glm::dvec3(1.5)));
    doc.add_model(make_model("ball", "sphere", {1, 0, 0}), make_state({0, 0, -3}, glm::dvec3(0.6)));
    return doc;
}
} // namespace

TEST_CASE("a transparent model lets the models behind it show through") {
    const Rendered clear = render_document(glass_box(0.8));
    const glm::ivec3 centre = pixel(clear.image, 80, 60);
    CAPTURE(centre.r, centre.g, centre.b);
    CHECK(centre.r > 2 * centre.g); // the red ball, through the box
    CHECK(clear.stats.models_drawn == 2);

    // Beside the ball only the background is behind the box: the seed's refraction of it (here
    // a cube map of the background colour), 80% of the colour.
    const glm::ivec3 side = pixel(clear.image, 80 - 30, 60 - 30);
    const glm::vec3 background = RenderOptions{}.background * 255.0f;
    CAPTURE(side.r, side.g, side.b);
    CHECK(std::abs(static_cast<float>(side.b) - background.b) < 40.0f);
    CHECK(std::abs(side.r - side.g) < 8);

    const Rendered opaque = render_document(glass_box(0.0));
    const glm::ivec3 hidden = pixel(opaque.image, 80, 60);
    CHECK(hidden.r < hidden.g + 8); // an opaque box hides it
}
