// A shading plugin whose shader does not compile is reported (plugin, stage, the driver's log),
// and its models are drawn with the host's built-in Phong rather than not at all.
#include "render_support.hpp"
#include "support.hpp"

#include "render/framebuffer.hpp"

#include <catch2/catch.hpp>

using namespace animator;
using namespace animator::test;

TEST_CASE("a shader that does not compile is reported and drawn with the built-in Phong") {
    gl_context();
    Environment env(AssetPaths::default_roots(), std::vector<std::filesystem::path>{
                                                     test::bin_dir(), ANIMATOR_RENDER_PLUGIN_DIR});
    Document doc = make_document(make_camera({0, 0, 5}));
    doc.add_model(make_model("ball", "sphere", {0.9, 0.1, 0.1}), make_state({0, 0, 0}));
    std::vector<std::string> log;
    RenderOptions options;
    options.shading = "shading.broken";
    Renderer renderer(env.plugins, env.assets, options,
                      [&](const std::string &m) { log.push_back(m); });
    renderer.set_document(doc, meshes_of(doc));
    OffscreenFramebuffer framebuffer(80, 60);
    renderer.draw(first_frame(doc), framebuffer.target());
    renderer.draw(first_frame(doc), framebuffer.target()); // reported once, not every frame

    REQUIRE(log.size() == 1);
    CHECK_THAT(log[0], Catch::Contains("shading.broken"));
    CHECK_THAT(log[0], Catch::Contains("the fragment shader does not compile"));
    CHECK_THAT(log[0], Catch::Contains("error")); // Mesa's own words
    CHECK_THAT(log[0], Catch::Contains("built-in Phong"));
    CHECK(renderer.programs().fallbacks() == 1);
    CHECK(renderer.stats().models_drawn == 1);

    Image image;
    image.width = 80;
    image.height = 60;
    framebuffer.read_rgb(image.rgb);
    const glm::ivec3 centre = pixel(image, 40, 30);
    CAPTURE(centre.r, centre.g, centre.b);
    CHECK(centre.r > 100); // the red ball, lit by the built-in Phong
    CHECK(centre.g < 60);
}

TEST_CASE("a shading plugin that is not there is named with those that are") {
    gl_context();
    RenderOptions options;
    options.shading = "shading.nope";
    CHECK_THROWS_WITH(Renderer(environment().plugins, environment().assets, options),
                      Catch::Contains("no shading plugin 'shading.nope'") &&
                          Catch::Contains("shading.phong"));
}
