// A scene pays only for what it uses: the renderer's counts (RenderStats) show which feature
// sets it asked the shading plugin for and every texture and cube map it bound.
#include "render_support.hpp"

#include "render/scene_math.hpp"

#include <catch2/catch.hpp>

using namespace animator;
using namespace animator::test;

namespace {

Document plain_scene() {
    Document doc = make_document(make_camera({0, 1, 6}, 0, -8));
    doc.add_model(make_model("floor", "plane", {0.5, 0.5, 0.5}), make_state({0, -1, 0}, {5, 1, 5}));
    doc.add_model(make_model("a", "sphere", {0.9, 0.1, 0.1}, {1, 1, 1}, 30),
                  make_state({-1, 0, 0}));
    doc.add_model(make_model("b", "cube", {0.1, 0.9, 0.1}), make_state({1, 0, 0}, glm::dvec3(0.5)));
    return doc;
}

// The feature sets asked for, but for the shadow maps' count (shadows are on by default) and the
// lights' (every model's program says how many lights it adds up).
uint32_t effects_used(const Rendered &r) {
    return r.stats.features_used & ~uint32_t(ANI_SHADE_SHADOW_MAPS_MASK | ANI_SHADE_LIGHTS_MASK);
}

void set_model(Document &doc, const std::string &name, const std::function<void(Model &)> &edit) {
    const int index = doc.find_model(name);
    Model m = doc.models()[static_cast<size_t>(index)];
    edit(m);
    doc.set_model(index, m);
}

} // namespace

TEST_CASE("a scene without effects binds no skybox and no texture and asks for no feature") {
    RenderOptions no_shadows;
    no_shadows.shadows = false;
    const Rendered r = render_document(plain_scene(), 160, 120, {}, no_shadows);
    CHECK(r.log.empty());
    CHECK(r.stats.models_drawn == 3);
    // (The one light, the camera's: the program adds up exactly one, shading.h, ABI 1.11.)
    CHECK(r.stats.features_used == uint32_t(ANI_SHADE_LIGHTS(1)));
    CHECK(r.stats.texture_binds == 0);
    CHECK(r.stats.cube_map_binds == 0);
    CHECK_FALSE(r.stats.skybox_drawn);
    CHECK(r.stats.program_binds == 1); // one program for all three
    // Shadows on (the default): the camera's light has a map, and every program reads that one
    // map, no more (shading.h, ABI 1.10).
    const Rendered shadowed = render_document(plain_scene());
    CHECK(shadowed.stats.shadow_maps == 1);
    CHECK(shadowed.stats.features_used == uint32_t(ANI_SHADE_SHADOW_MAPS(1) | ANI_SHADE_LIGHTS(1)));
    CHECK(shadowed.stats.program_binds == 1);
}

TEST_CASE("each effect binds what it needs, once") {
    SECTION("a texture") {
        Document doc = plain_scene();
        set_model(doc, "b", [](Model &m) { m.texture = "brick"; });
        set_model(doc, "floor", [](Model &m) { m.texture = "brick"; });
        const Rendered r = render_document(doc);
        CHECK(effects_used(r) == uint32_t(ANI_SHADE_TEXTURE));
        CHECK(r.stats.texture_binds == 1); // the same texture for both
        CHECK(r.stats.cube_map_binds == 0);
        // Opaque models are drawn grouped by program: the floor and the cube (textured) one
        // after the other, and the sphere (plain); two binds, not three in the document's order.
        CHECK(r.stats.program_binds == 2);
    }
    SECTION("a skybox, shared with reflection") {
        Document doc = plain_scene();
        Settings s = doc.settings();
        s.skybox = "night";
        doc.set_settings(s);
        set_model(doc, "a", [](Model &m) { m.reflectivity = 0.7; });
        RenderOptions skybox_only;
        skybox_only.reflection_size = 0;
        const Rendered r = render_document(doc, 160, 120, {}, skybox_only);
        CHECK(r.stats.skybox_drawn);
        CHECK(effects_used(r) == uint32_t(ANI_SHADE_SKYBOX_PASS | ANI_SHADE_REFLECTION));
        CHECK(r.stats.cube_map_binds == 1);
        CHECK(r.stats.texture_binds == 0);
        CHECK(r.stats.reflection_maps == 0);
    }
    SECTION("a reflective model's view of the others: one cube map, bound once") {
        Document doc = plain_scene();
        Settings s = doc.settings();
        s.skybox = "night";
        doc.set_settings(s);
        set_model(doc, "a", [](Model &m) { m.reflectivity = 0.7; });
        const Rendered r = render_document(doc);
        CHECK(r.stats.reflection_maps == 1);
        // Its own (for it, in the view), then the skybox (behind the opaque models, drawn after
        // them); and the skybox first in its cube map where it is drawn there, not copied.
        CHECK(r.stats.cube_map_binds == (r.stats.skies_copied ? 2 : 3));
        CHECK(r.stats.texture_binds == 0);
    }
    SECTION("cel shading and a selection") {
        Document doc = plain_scene();
        Settings s = doc.settings();
        s.cel_shading = true;
        doc.set_settings(s);
        const Rendered r = render_document(doc, 160, 120, {2});
        CHECK(effects_used(r) == uint32_t(ANI_SHADE_CEL | ANI_SHADE_SELECTED));
        CHECK(r.stats.texture_binds + r.stats.cube_map_binds == 0);
    }
}

TEST_CASE("reflection without a skybox reflects the background colour") {
    Document doc = plain_scene();
    set_model(doc, "a", [](Model &m) { m.reflectivity = 1.0; });
    RenderOptions options;
    options.background = {0.0f, 0.5f, 1.0f};
    const Rendered r = render_document(doc, 160, 120, {}, options);
    CHECK(r.stats.cube_map_binds == 1);
    CHECK_FALSE(r.stats.skybox_drawn);
    // Sphere "a" at (-1, 0, 0) is a perfect mirror of a sky-blue world.
    const Frame frame = first_frame(doc);
    const auto at =
        project_to_pixel(projection_matrix(frame.camera.fov_degrees, 160.0 / 120.0, 0.1, 1000.0) *
                             view_matrix(frame.camera),
                         {-1, 0, 0}, 160, 120);
    REQUIRE(at);
    const glm::ivec3 c = pixel(r.image, int(at->x), int(at->y));
    CHECK(std::abs(c.r - 0) <= 2);
    CHECK(std::abs(c.g - 128) <= 2);
    CHECK(std::abs(c.b - 255) <= 2);
}

TEST_CASE("models outside the view are culled, not drawn") {
    Document doc = plain_scene();
    doc.add_model(make_model("behind", "sphere", {1, 1, 1}), make_state({0, 1, 20}));
    doc.add_model(make_model("far_left", "torus", {1, 1, 1}), make_state({-40, 0, 0}));
    const Rendered r = render_document(doc);
    CHECK(r.stats.models_drawn == 3);
    CHECK(r.stats.models_culled == 2);
}

TEST_CASE("a skybox or texture that cannot be loaded is reported and left out") {
    Document doc = plain_scene();
    Settings s = doc.settings();
    s.skybox = "no_such_sky";
    doc.set_settings(s);
    set_model(doc, "b", [](Model &m) { m.texture = "no_such_texture"; });
    const Rendered r = render_document(doc);
    REQUIRE(r.log.size() == 2);
    CHECK_THAT(r.log[0], Catch::Contains("skybox 'no_such_sky' cannot be loaded"));
    CHECK_THAT(r.log[1], Catch::Contains("texture 'no_such_texture' cannot be loaded"));
    CHECK_FALSE(r.stats.skybox_drawn);
    CHECK(effects_used(r) == 0u);
    CHECK(r.stats.models_drawn == 3);
}

TEST_CASE("closed meshes seen from outside are drawn one-sided, and seen from within, two-sided") {
    // The sphere and the cube are closed: their back faces are left out; the floor is open.
    const Rendered outside = render_document(plain_scene());
    CHECK(outside.stats.one_sided == 2);
    CHECK(outside.stats.models_drawn == 3);
    // A camera inside a large closed cube sees its inside walls all round (their back faces):
    // no pixel is the background.
    Document room = make_document(make_camera({0, 0, 0}, 20, 10));
    room.add_model(make_model("room", "cube", {0.7, 0.6, 0.4}), make_state({0.5, 0.2, -0.3}, glm::dvec3(5.0)));
    RenderOptions options;
    options.background = {0.0f, 0.0f, 1.0f};
    const Rendered inside = render_document(room, 160, 120, {}, options);
    CHECK(inside.stats.one_sided == 0);
    int background = 0;
    for (int y = 0; y < 120; ++y)
        for (int x = 0; x < 160; ++x) {
            const glm::ivec3 c = pixel(inside.image, x, y);
            background += c.b > 200 && c.r < 20 && c.g < 20;
        }
    CHECK(background == 0);
}
