// Golden images of every shading effect on Mesa's llvmpipe, each a small scene built in code and
// drawn at 160x120 (docs/rendering.md lists them and how to update them). A failure writes the
// rendering and a difference image under build/tests/tmp/render_golden/.
#include "image_compare.hpp"
#include "render_support.hpp"
#include "support.hpp"

#include <catch2/catch.hpp>

using namespace animator;
using namespace animator::test;

namespace {

// llvmpipe gives the same pixels run after run on one machine. Elsewhere (another CPU, another
// Mesa) a few pixels along edges and outlines may flip and colours may round differently, so up
// to 0.5% of the pixels (96 of 19,200) may differ by more than 48 of 255, and the mean difference
// may reach 1 of 255. A missing or wrong effect changes thousands of pixels (the tests below
// check that the tolerance tells cel shading on from off, and a selected model from one that is
// not).
const Tolerance kTolerance{48.0, 0.005, 1.0};

// These goldens show each effect on its own, as before shadows, anti-aliasing and reflections
// of other models came (each has goldens of their own: shadow_test, antialiasing_test,
// reflection_probes_test), so they draw without shadows, single-sampled, and reflect and refract
// the skybox only.
RenderOptions without_shadows() {
    RenderOptions o;
    o.shadows = false;
    o.reflection_size = 0;
    return o;
}

Image check(const std::string &name, const Document &doc, const std::set<int> &selected = {}) {
    const Rendered r = render_document(doc, 160, 120, selected, without_shadows());
    for (const std::string &line : r.log) UNSCOPED_INFO(line);
    CHECK(r.log.empty());
    const std::string problem = check_golden(name, r.image, kTolerance);
    INFO(problem);
    CHECK(problem.empty());
    return r.image;
}

// The rendering must not pass for another golden: the tolerance sees the effect. (Compared here,
// not through check_golden, which with ANIMATOR_UPDATE_GOLDENS=1 would overwrite that golden.)
void check_differs(const std::string &other, const Image &image) {
    const Image golden = load_image(test::source_dir() / "tests/render/golden" / (other + ".png"));
    REQUIRE(golden.width == image.width);
    REQUIRE(golden.height == image.height);
    const ImageDifference d = compare_images(image, golden, kTolerance.max);
    CAPTURE(other, d.over, d.mean);
    CHECK((d.over > kTolerance.outliers || d.mean > kTolerance.mean));
}

void add_floor(Document &doc) {
    doc.add_model(make_model("floor", "plane", {0.55, 0.55, 0.55}),
                  make_state({0, -1, 0}, {6, 1, 6}));
}

} // namespace

TEST_CASE("golden: Phong with specular highlights, and shininess at its maximum turns them off") {
    Document doc = make_document(make_camera({0, 1.2, 6}, 0, -10));
    add_floor(doc);
    doc.add_model(make_model("shiny", "sphere", {0.8, 0.15, 0.1}, {1, 1, 1}, 40),
                  make_state({-1.3, 0, 0}));
    doc.add_model(make_model("matte", "sphere", {0.8, 0.15, 0.1}, {1, 1, 1}, ANI_SHININESS_MAX),
                  make_state({1.3, 0, 0}));
    check("phong_specular", doc);
}

TEST_CASE("golden: texture mapping with the model's UVs, tinted by kd") {
    Document doc = make_document(make_camera({0, 1.0, 5.5}, 0, -10));
    add_floor(doc);
    Model plain = make_model("plain", "cube", {0.1, 0.3, 0.9});
    plain.texture = "checker";
    Model tinted = plain;
    tinted.name = "tinted";
    tinted.tint = 0.5;
    doc.add_model(plain, make_state({-1.3, 0, 0}, glm::dvec3(0.8), {0, 30, 0}));
    doc.add_model(tinted, make_state({1.3, 0, 0}, glm::dvec3(0.8), {0, 30, 0}));
    check("texture_tint", doc);
}

TEST_CASE("golden: each skybox, turned by the camera's rotation only") {
    struct Sky {
        const char *name;
        CameraState camera;
    };
    // Towards what each skybox shows (docs/assets.md): the day's clouds over the horizon, the
    // sunset's sun towards -Z, the night's moon 35 degrees up towards +X. The camera stands far
    // from the origin: a skybox does not move with it.
    const Sky skies[] = {
        {"day", make_camera({40, 3, -25}, 0, 15, 70)},
        {"sunset", make_camera({-30, 1, 60}, 0, 5, 70)},
        {"night", make_camera({5, 2, 80}, -90, 30, 70)},
    };
    for (const Sky &sky : skies) {
        CAPTURE(sky.name);
        Document doc = make_document(sky.camera, false, sky.name);
        // A model in front, to show the skybox stays behind everything.
        const glm::dvec3 ahead =
            sky.camera.position + glm::normalize(sky.camera.rotation) * glm::dvec3(0.6, -0.5, -4);
        doc.add_model(make_model("ball", "sphere", {0.7, 0.7, 0.7}, {0.5, 0.5, 0.5}, 30),
                      make_state(ahead, glm::dvec3(0.5)));
        check(std::string("skybox_") + sky.name, doc);
    }
}

TEST_CASE("golden: reflection mapping samples the skybox along the reflected ray") {
    Document doc = make_document(make_camera({0, 0.3, 4.5}, 0, -5), false, "day");
    Model mirror = make_model("mirror", "sphere", {0.5, 0.5, 0.5});
    mirror.reflectivity = 1.0;
    Model half = make_model("half", "sphere", {0.8, 0.1, 0.1}, {1, 1, 1}, 40);
    half.reflectivity = 0.5;
    doc.add_model(mirror, make_state({-1.2, 0, 0}));
    doc.add_model(half, make_state({1.2, 0, 0}));
    check("reflection", doc);
}

TEST_CASE("golden: refraction with ratio 1 / refractive index, blended by transparency") {
    Document doc = make_document(make_camera({0, 0.5, 4.5}, 0, 0), false, "sunset");
    Model water = make_model("water", "sphere", {0.5, 0.5, 0.5});
    water.transparency = 1.0;
    water.refractive_index = 1.33;
    Model glass = make_model("glass", "sphere", {0.1, 0.2, 0.8}, {1, 1, 1}, 60);
    glass.transparency = 0.6;
    glass.refractive_index = 1.5;
    doc.add_model(water, make_state({-1.2, 0.5, 0}));
    doc.add_model(glass, make_state({1.2, 0.5, 0}));
    check("refraction", doc);
}

namespace {
Document cel_scene(bool cel) {
    Document doc = make_document(make_camera({0, 1.5, 6}, 0, -12), cel);
    add_floor(doc);
    doc.add_model(make_model("ball", "sphere", {0.9, 0.5, 0.1}, {1, 1, 1}, 30),
                  make_state({-1.2, 0, 0}));
    doc.add_model(make_model("ring", "torus", {0.2, 0.6, 0.3}, {0.3, 0.3, 0.3}, 20),
                  make_state({1.3, 0, 0}, glm::dvec3(1.0), {70, 0, 0}));
    return doc;
}
} // namespace

TEST_CASE("golden: cel shading off and on (the seed's step10)") {
    const Image off = check("cel_off", cel_scene(false));
    const Image on = check("cel_on", cel_scene(true));
    check_differs("cel_on", off);
    check_differs("cel_off", on);
}

TEST_CASE("golden: cel shading with 4 bands and the outline (shading.phong parameters)") {
    Document doc = cel_scene(true);
    Settings s = doc.settings();
    s.params["shading.phong"]["cel_bands"] = {4, 0, 0, 0};
    s.params["shading.phong"]["cel_outline"] = {1, 0, 0, 0};
    doc.set_settings(s);
    check("cel_outline", doc);
}

TEST_CASE("golden: a selected model is tinted yellow and outlined") {
    Document doc = make_document(make_camera({0, 1.2, 6}, 0, -10));
    add_floor(doc);
    for (int i = 0; i < 3; ++i)
        doc.add_model(
            make_model("ball" + std::to_string(i), "sphere", {0.2, 0.4, 0.8}, {0.5, 0.5, 0.5}, 30),
            make_state({-2.2 + 2.2 * i, 0, 0}, glm::dvec3(0.9)));
    check("selected", doc, {2}); // the middle ball (the floor is model 0)
    check_differs("selected", render_document(doc, 160, 120, {}, without_shadows()).image);
}

namespace {
// An A4-style scene (the CS488 ray tracer's nonhier.lua, smaller): spheres of a few materials and
// a box on a floor, with or without the document's two coloured lights with falloff.
Document lit_scene(bool lights) {
    Document doc = make_document(make_camera({0, 1.6, 6.5}, 0, -14));
    add_floor(doc);
    doc.add_model(make_model("red", "sphere", {0.8, 0.2, 0.15}, {0.6, 0.6, 0.6}, 25),
                  make_state({-1.8, -0.3, 0.2}, glm::dvec3(0.7)));
    doc.add_model(make_model("jade", "sphere", {0.2, 0.7, 0.4}, {0.3, 0.5, 0.3}, 60),
                  make_state({0.2, 0.0, -1.0}, glm::dvec3(1.0)));
    doc.add_model(make_model("pearl", "sphere", {0.85, 0.85, 0.8}, {0.9, 0.9, 0.9}, 90),
                  make_state({1.9, -0.55, 0.8}, glm::dvec3(0.45)));
    doc.add_model(make_model("box", "cube", {0.5, 0.45, 0.7}),
                  make_state({-0.4, -0.6, 1.3}, glm::dvec3(0.4), {0, 35, 0}));
    if (lights) {
        Settings s = doc.settings();
        s.lights = {Light{"warm", {-3.0, 4.0, 3.0}, {1.3, 0.9, 0.5}, {1.0, 0.05, 0.02}},
                    Light{"violet", {3.0, 2.0, 1.5}, {0.6, 0.3, 1.4}, {1.0, 0.0, 0.08}}};
        s.ambient = {0.12, 0.12, 0.18};
        doc.set_settings(s);
    }
    return doc;
}
} // namespace

TEST_CASE("golden: the document's two coloured lights with falloff and its ambient") {
    check("lights_two", lit_scene(true));
    // Not the camera's light: the same scene without the document's lights looks otherwise.
    check_differs("lights_two",
                  render_document(lit_scene(false), 160, 120, {}, without_shadows()).image);
}
