// Reflections and refractions of other models (reflection_probes.hpp): a mirror shows the model
// beside it where the law of reflection puts it, a glass ball shows what is behind and above it
// in its lower half (Snell's law at its front surface), only with reflections on; golden images
// of both, and of orbs seeing each other.
#include "image_compare.hpp"
#include "render_support.hpp"
#include "support.hpp"

#include "render/reflection_probes.hpp"
#include "render/scene_math.hpp"

#include <catch2/catch.hpp>
#include <glad/gl.h>
#include <glm/gtc/matrix_transform.hpp>

#include <cstdlib>
#include <vector>

using namespace animator;
using namespace animator::test;

namespace {

constexpr int kWidth = 320, kHeight = 240;

RenderOptions with_reflections(int size) {
    RenderOptions o;
    o.reflection_size = size;
    return o;
}

// Where a world point is drawn, from the top left.
glm::dvec2 pixel_of(const Document &doc, const glm::dvec3 &point) {
    const Frame frame = first_frame(doc);
    const auto at = project_to_pixel(
        projection_matrix(frame.camera.fov_degrees, double(kWidth) / kHeight, 0.1, 1000.0) *
            view_matrix(frame.camera),
        point, kWidth, kHeight);
    REQUIRE(at);
    return *at;
}

bool red(const glm::ivec3 &c) {
    return c.r > 90 && c.r > 2 * c.g + 20 && c.r > 2 * c.b + 20;
}

} // namespace

TEST_CASE("a face's camera sees what a cube map lookup along that direction finds") {
    // GL's cube-map faces (the OpenGL specification, "Cube Map Texture Selection"): a direction
    // d with major axis +X is looked up on face 0 at s = (-d.z / |d.x| + 1) / 2,
    // t = (-d.y / |d.x| + 1) / 2, t = 0 being the first row, which a framebuffer draws at its
    // bottom (window y = 0). So the face's camera must draw d at x = s, y = t in [0, 1]^2.
    const glm::dvec3 c(1.0, 2.0, 3.0);
    const glm::dmat4 projection = ReflectionProbes::face_projection(0.1, 100.0);
    const glm::dvec3 directions[] = {{1, 0.3, -0.2},  {-1, -0.4, 0.5}, {0.2, 1, 0.6},
                                     {-0.3, -1, 0.1}, {0.5, 0.25, 1},  {-0.6, 0.1, -1}};
    for (int f = 0; f < 6; ++f) {
        const glm::dvec3 d = directions[f];
        const int axis = f / 2;
        const double ma = std::abs(d[axis]);
        // sc, tc per face (Table 8.19 of the GL 4.5 specification).
        double sc = 0, tc = 0;
        switch (f) {
        case 0:
            sc = -d.z;
            tc = -d.y;
            break;
        case 1:
            sc = d.z;
            tc = -d.y;
            break;
        case 2:
            sc = d.x;
            tc = d.z;
            break;
        case 3:
            sc = d.x;
            tc = -d.z;
            break;
        case 4:
            sc = d.x;
            tc = -d.y;
            break;
        case 5:
            sc = -d.x;
            tc = -d.y;
            break;
        }
        const double s = (sc / ma + 1) / 2, t = (tc / ma + 1) / 2;
        const glm::dvec4 clip =
            projection * ReflectionProbes::face_view(f, c) * glm::dvec4(c + 5.0 * d, 1.0);
        CAPTURE(f);
        REQUIRE(clip.w > 0.0);
        CHECK(clip.x / clip.w * 0.5 + 0.5 == Approx(s).margin(1e-12));
        CHECK(clip.y / clip.w * 0.5 + 0.5 == Approx(t).margin(1e-12));
    }
}

TEST_CASE("a mirror shows the model beside it where the law of reflection says") {
    // A mirror ball of radius 1 at the origin, the camera on +Z, a red cube on +X. The point of
    // the ball that reflects the cube to the camera has the normal halfway between them.
    Document doc = make_document(make_camera({0, 0, 6}, 0, 0));
    Model mirror = make_model("mirror", "sphere", {0.5, 0.5, 0.5});
    mirror.reflectivity = 1.0;
    doc.add_model(mirror, make_state({0, 0, 0}));
    doc.add_model(make_model("cube", "cube", {1.0, 0.05, 0.05}),
                  make_state({3.5, 0, 0}, glm::dvec3(1.5)));
    REQUIRE(meshes_of(doc)[0]->bound_radius == Approx(1.0).margin(0.01));
    const glm::dvec3 n = glm::normalize(glm::dvec3(0, 0, 1) + glm::dvec3(1, 0, 0));
    const glm::dvec2 at = pixel_of(doc, n); // the point of the ball with that normal
    // Its reflected ray, from the exact eye direction, points at the cube (within 37 degrees of
    // +X, which the cube, 1.5 across from 2 away, covers).
    const glm::dvec3 reflected = glm::reflect(glm::normalize(n - glm::dvec3(0, 0, 6)), n);
    REQUIRE(glm::dot(glm::normalize(reflected), glm::dvec3(1, 0, 0)) >
            std::cos(glm::radians(30.0)));

    const Rendered on = render_document(doc, kWidth, kHeight);
    const Rendered off = render_document(doc, kWidth, kHeight, {}, with_reflections(0));
    CHECK(on.stats.reflection_maps == 1);
    CHECK(off.stats.reflection_maps == 0);
    const glm::ivec3 seen = pixel(on.image, int(at.x), int(at.y)),
                     skybox_only = pixel(off.image, int(at.x), int(at.y));
    CAPTURE(at.x, at.y, seen, skybox_only);
    CHECK(red(seen));
    CHECK_FALSE(red(skybox_only));
    // The centre reflects the camera's own direction: no cube there, on or off.
    const glm::dvec2 centre = pixel_of(doc, {0, 0, 1});
    CHECK_FALSE(red(pixel(on.image, int(centre.x), int(centre.y))));
    // Mirrored: the cube is on the right, so the left half of the ball shows none of it.
    const glm::dvec2 left = pixel_of(doc, glm::normalize(glm::dvec3(-1, 0, 1)));
    CHECK_FALSE(red(pixel(on.image, int(left.x), int(left.y))));
}

TEST_CASE("a glass ball refracts what is behind and above it into its lower half") {
    // A clear ball (index 1.5) at the origin, a red cube far behind it and above (not behind it
    // on screen: nothing shows through it directly), the camera on +Z. At a point of the lower
    // half whose normal is 55 degrees below the view axis, the ray refracted into the ball
    // (Snell, 1 / 1.5) turns upward, to the cube.
    Document doc = make_document(make_camera({0, 0, 6}, 0, 0));
    Model glass = make_model("glass", "sphere", {0.5, 0.5, 0.5});
    glass.transparency = 1.0;
    glass.refractive_index = 1.5;
    doc.add_model(glass, make_state({0, 0, 0}));
    const glm::dvec3 cube_at(0, 7.46, -18.56);
    const double half = 3.0;
    doc.add_model(make_model("cube", "cube", {1.0, 0.05, 0.05}),
                  make_state(cube_at, glm::dvec3(half)));
    const double a = glm::radians(55.0);
    const glm::dvec3 n(0, -std::sin(a), std::cos(a));
    const glm::dvec3 in = glm::normalize(n - glm::dvec3(0, 0, 6));
    const glm::dvec3 refracted = glm::refract(in, n, 1.0 / 1.5);
    REQUIRE(glm::length(refracted) > 0.5);
    // The refracted ray from the ball's centre meets the cube (half across about cube_at): where
    // it reaches the cube's depth it is within its height. And the cube's lowest front edge is
    // seen above the ball's top.
    const double reach = (cube_at.z - 0.0) / refracted.z;
    const glm::dvec3 hit = reach * refracted;
    REQUIRE(std::abs(hit.y - cube_at.y) < half);
    REQUIRE(std::abs(hit.x - cube_at.x) < half);
    REQUIRE(pixel_of(doc, cube_at + glm::dvec3(0, -half, half)).y < pixel_of(doc, {0, 1, 0}).y - 3);

    const Rendered on = render_document(doc, kWidth, kHeight);
    const Rendered off = render_document(doc, kWidth, kHeight, {}, with_reflections(0));
    const glm::dvec2 at = pixel_of(doc, n);
    const glm::ivec3 seen = pixel(on.image, int(at.x), int(at.y)),
                     skybox_only = pixel(off.image, int(at.x), int(at.y));
    CAPTURE(at.x, at.y, seen, skybox_only);
    CHECK(red(seen));
    CHECK_FALSE(red(skybox_only));
    // Upside down: the upper half's rays turn downward, away from the cube.
    const glm::dvec2 upper = pixel_of(doc, glm::dvec3(0, std::sin(a), std::cos(a)));
    CHECK_FALSE(red(pixel(on.image, int(upper.x), int(upper.y))));
    const std::string problem =
        check_golden("refraction_of_models", on.image, Tolerance{48.0, 0.005, 1.0});
    INFO(problem);
    CHECK(problem.empty());
}

TEST_CASE("a mirror alone reflects the sky through its cube map as it reflects the skybox") {
    // Nothing else around it: its cube map holds only the sky, copied from the skybox's level as
    // large as its faces (256 texels, 128 pixels: level 1) where it can be, drawn where not (96
    // pixels). Either way the mirror shows what it shows with the skybox itself, but for the
    // cube map's resolution. A face copied to the wrong place, or turned, would show another
    // part of the sky (the day sky's ground, the sun).
    Document doc = make_document(make_camera({0, 0, 4}, 0, 0), false, "day");
    Model mirror = make_model("mirror", "sphere", {0.5, 0.5, 0.5});
    mirror.reflectivity = 1.0;
    doc.add_model(mirror, make_state({0, 0, 0}));
    const Rendered sky = render_document(doc, kWidth, kHeight, {}, with_reflections(0));
    for (int size : {128, 96}) {
        const Rendered on = render_document(doc, kWidth, kHeight, {}, with_reflections(size));
        CHECK(on.stats.reflection_maps == 1);
        CHECK(on.stats.skies_copied == (size == 128 && ReflectionProbes::copies_sky() ? 1u : 0u));
        // Over the ball's disk (radius 1 seen from 4: within 0.9 of its centre on screen).
        const glm::dvec2 c = pixel_of(doc, {0, 0, 0}), edge = pixel_of(doc, {0.9, 0, 0});
        const double r = edge.x - c.x;
        double sum = 0.0;
        int worst = 0, looked = 0;
        for (int y = int(c.y - r); y <= int(c.y + r); ++y)
            for (int x = int(c.x - r); x <= int(c.x + r); ++x) {
                if ((x - c.x) * (x - c.x) + (y - c.y) * (y - c.y) > r * r) continue;
                const glm::ivec3 d = glm::abs(pixel(on.image, x, y) - pixel(sky.image, x, y));
                sum += d.r + d.g + d.b;
                worst = std::max({worst, d.r, d.g, d.b});
                ++looked;
            }
        CAPTURE(size, looked, sum / (3.0 * looked), worst);
        CHECK(looked > 1000);
        CHECK(sum / (3.0 * looked) < 3.0);
        CHECK(worst < 48);
        // Over a copied sky no face sees anything to draw; drawn, the sky is in every face.
        CHECK(on.stats.reflection_faces == (on.stats.skies_copied ? 0u : 6u));
    }
    // A red cube on +X, 3.5 away and 2 across (its bounding sphere, of radius 1.73, is within
    // 2.47 of the face's sides there): seen by the +X face only, which is drawn over the copied
    // sky (the others keep it); the mirror shows the cube where the law of reflection says (12
    // degrees from +X; the cube covers 22 from the centre), and the sky elsewhere.
    doc.add_model(make_model("cube", "cube", {1.0, 0.05, 0.05}),
                  make_state({3.5, 0, 0}, glm::dvec3(1.0)));
    const glm::dvec3 n = glm::normalize(glm::dvec3(0, 0, 1) + glm::dvec3(1, 0, 0));
    const glm::dvec2 at = pixel_of(doc, n);
    for (int size : {128, 96}) {
        const Rendered on = render_document(doc, kWidth, kHeight, {}, with_reflections(size));
        CAPTURE(size);
        CHECK(on.stats.reflection_faces == (on.stats.skies_copied ? 1u : 6u));
        CHECK(red(pixel(on.image, int(at.x), int(at.y))));
        const glm::dvec2 left = pixel_of(doc, glm::normalize(glm::dvec3(-1, 0, 1)));
        const glm::ivec3 d = glm::abs(pixel(on.image, int(left.x), int(left.y)) -
                                      pixel(sky.image, int(left.x), int(left.y)));
        CHECK(std::max({d.r, d.g, d.b}) < 24);
    }
}

TEST_CASE("the models around a reflective one are drawn as without reflections of other models") {
    // Drawing the cube maps (a skybox and plain models in each face) leaves nothing behind for
    // the frame: a plain sphere beside a glass cube and a mirror ball is the same pixel for pixel
    // with them on and off (it once took the skybox's program, bound last in a cube map).
    Document doc = make_document(make_camera({0, 0.5, 7}, 0, -4), false, "day");
    Model glass = make_model("glass", "cube", {0.5, 0.5, 0.5});
    glass.transparency = 0.7;
    glass.refractive_index = 1.5;
    Model mirror = make_model("mirror", "sphere", {0.5, 0.5, 0.5});
    mirror.reflectivity = 1.0;
    doc.add_model(make_model("plain", "sphere", {0.2, 0.7, 0.3}, {1, 1, 1}, 40),
                  make_state({-2.6, 0, 0}));
    doc.add_model(glass, make_state({0, 0, 0}));
    doc.add_model(mirror, make_state({2.6, 0, 0}));
    doc.add_model(make_model("inside", "sphere", {0.9, 0.1, 0.1}),
                  make_state({0, 0, 0}, glm::dvec3(0.5)));
    const Rendered on = render_document(doc, kWidth, kHeight);
    const Rendered off = render_document(doc, kWidth, kHeight, {}, with_reflections(0));
    CHECK(on.stats.reflection_maps == 2);
    // The plain sphere's square on screen, and the sky above everything.
    const glm::dvec2 c = pixel_of(doc, {-2.6, 0, 0});
    int differ = 0, looked = 0;
    for (int y = int(c.y) - 20; y <= int(c.y) + 20; ++y)
        for (int x = int(c.x) - 20; x <= int(c.x) + 20; ++x, ++looked)
            differ += pixel(on.image, x, y) != pixel(off.image, x, y);
    for (int y = 0; y < 20; ++y)
        for (int x = 0; x < kWidth; x += 4, ++looked)
            differ += pixel(on.image, x, y) != pixel(off.image, x, y);
    CAPTURE(looked);
    CHECK(differ == 0);
    // The red ball inside the glass shows through it either way; and the glass's cube map holds
    // what is around it, not what it holds: near its corners, where only the sky is behind, it
    // refracts the sky as without the cube maps (to their resolution), not the inside of the ball
    // that would fill its view from its centre.
    const glm::dvec2 inside = pixel_of(doc, {0, 0, 0.5});
    CHECK(red(pixel(on.image, int(inside.x), int(inside.y))));
    for (const glm::dvec3 corner : {glm::dvec3(0.85, 0.85, 1), glm::dvec3(-0.85, 0.85, 1),
                                    glm::dvec3(0.85, -0.85, 1), glm::dvec3(-0.85, -0.85, 1)}) {
        const glm::dvec2 at = pixel_of(doc, corner);
        const glm::ivec3 seen = pixel(on.image, int(at.x), int(at.y)),
                         sky = pixel(off.image, int(at.x), int(at.y));
        CAPTURE(corner.x, corner.y, seen, sky);
        CHECK(std::abs(seen.r - sky.r) + std::abs(seen.g - sky.g) + std::abs(seen.b - sky.b) < 45);
    }
}

TEST_CASE("golden: the orbs reflect and refract each other") {
    Document doc = make_document(make_camera({0, 0.3, 5}, 0, -3), false, "sunset");
    Model mirror = make_model("mirror", "sphere", {0.5, 0.5, 0.5});
    mirror.reflectivity = 1.0;
    Model glass = make_model("glass", "sphere", {0.2, 0.3, 0.8}, {1, 1, 1}, 60);
    glass.transparency = 0.8;
    glass.refractive_index = 1.5;
    doc.add_model(mirror, make_state({-1.05, 0, 0}));
    doc.add_model(glass, make_state({1.05, 0, 0}));
    doc.add_model(make_model("red", "cube", {0.9, 0.1, 0.1}),
                  make_state({0, 0, -2.5}, glm::dvec3(0.6)));
    const Rendered r = render_document(doc, 160, 120);
    CHECK(r.stats.reflection_maps == 2);
    const std::string problem =
        check_golden("reflections_of_models", r.image, Tolerance{48.0, 0.005, 1.0});
    INFO(problem);
    CHECK(problem.empty());
}

TEST_CASE("reflections of other models are kept to the nearest few, said once") {
    Document doc = make_document(make_camera({0, 0, 12}, 0, 0));
    for (int k = 0; k < 5; ++k) {
        Model m = make_model("m" + std::to_string(k), "sphere", {0.5, 0.5, 0.5});
        m.reflectivity = 1.0;
        doc.add_model(m, make_state({2.5 * k - 5.0, 0, -k}));
    }
    RenderOptions options;
    options.reflection_models = 3;
    const Rendered r = render_document(doc, 160, 120, {}, options);
    CHECK(r.stats.reflection_maps == 3);
    REQUIRE(r.log.size() == 1);
    CHECK(r.log[0].find("the 3 nearest the camera") != std::string::npos);
}

namespace {

// Level `level` of face `face` of cube map `texture`, RGBA8, rows from t = 0.
std::vector<unsigned char> cube_level(unsigned texture, int face, int level, int side) {
    std::vector<unsigned char> texels(static_cast<std::size_t>(side * side * 4));
    GLint held = 0;
    glGetIntegerv(GL_TEXTURE_BINDING_CUBE_MAP, &held);
    glBindTexture(GL_TEXTURE_CUBE_MAP, texture);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glGetTexImage(GL_TEXTURE_CUBE_MAP_POSITIVE_X + static_cast<GLenum>(face), level, GL_RGBA,
                  GL_UNSIGNED_BYTE, texels.data());
    glBindTexture(GL_TEXTURE_CUBE_MAP, static_cast<GLuint>(held));
    return texels;
}

// The greatest difference, over every texel and channel of every face and of levels 1 and 2,
// between what `probes` made of model `model`'s cube map (`side` texels at level 0) and the
// average of the 2x2 texels of the level above.
int worst_level_error(ReflectionProbes &probes, int side, int model = 0) {
    int worst = 0;
    for (int face = 0; face < 6; ++face)
        for (int level = 1; level <= 2; ++level) {
            const int above_side = side >> (level - 1), here_side = side >> level;
            const auto above = cube_level(probes.texture(model), face, level - 1, above_side);
            const auto here = cube_level(probes.texture(model), face, level, here_side);
            for (int y = 0; y < here_side; ++y)
                for (int x = 0; x < here_side; ++x)
                    for (int c = 0; c < 4; ++c) {
                        int sum = 0;
                        for (int dy = 0; dy < 2; ++dy)
                            for (int dx = 0; dx < 2; ++dx)
                                sum += above[static_cast<std::size_t>(
                                    ((2 * y + dy) * above_side + 2 * x + dx) * 4 + c)];
                        const int got = here[static_cast<std::size_t>((y * here_side + x) * 4 + c)];
                        worst = std::max(worst, std::abs(got - (sum + 2) / 4));
                    }
        }
    return worst;
}

// Draws model `model`'s cube map with faces of small squares of colours that differ face to face
// and model to model, so that each texel of level 1 and 2 averages four different ones. Its
// levels are made by the next probes.finish().
void draw_checkered(ReflectionProbes &probes, int side, int model = 0) {
    int face = 0;
    probes.draw(model, side, glm::dvec3(0.0), glm::vec3(0.0f), nullptr, 0,
                [&](const glm::dmat4 &, const glm::dmat4 &) {
                    glEnable(GL_SCISSOR_TEST);
                    for (int y = 0; y < side; ++y)
                        for (int x = 0; x < side; ++x) {
                            glScissor(x, y, 1, 1);
                            const int k = (x * 7 + y * 13 + face * 29 + model * 5) % 17;
                            glClearColor(static_cast<float>(k) / 16.0f,
                                         static_cast<float>((k * 5) % 17) / 16.0f,
                                         static_cast<float>(x % 3) / 2.0f, (y % 2) ? 1.0f : 0.5f);
                            glClear(GL_COLOR_BUFFER_BIT);
                        }
                    glDisable(GL_SCISSOR_TEST);
                    ++face;
                });
}

} // namespace

TEST_CASE("each mipmap level of a model's cube map averages the 2x2 texels of the level above, on "
          "every face, as glGenerateMipmap does") {
    gl_context();
    constexpr int kSide = 16;
    // Drawn layered (one draw a level) where the OpenGL can: llvmpipe can.
    ReflectionProbes probes;
    draw_checkered(probes, kSide);
    probes.finish();
    CHECK(probes.layered());
    CHECK(worst_level_error(probes, kSide) <= 1);
    // The same with glGenerateMipmap, which the layered draw replaces: the truth it must match.
    setenv("ANIMATOR_PROBE_MIPMAPS", "1", 1);
    ReflectionProbes generated;
    draw_checkered(generated, kSide);
    generated.finish();
    unsetenv("ANIMATOR_PROBE_MIPMAPS");
    CHECK_FALSE(generated.layered());
    CHECK(worst_level_error(generated, kSide) <= 1);
    // And the two agree texel for texel.
    for (int face = 0; face < 6; ++face)
        for (int level = 1; level <= 2; ++level) {
            CAPTURE(face, level);
            CHECK(cube_level(probes.texture(0), face, level, kSide >> level) ==
                  cube_level(generated.texture(0), face, level, kSide >> level));
        }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

TEST_CASE("the cube maps of a frame make their levels several at once and each its own") {
    gl_context();
    constexpr int kSide = 16;
    // More cube maps than one draw takes (at most 8 on any OpenGL): two draws a level at least.
    ReflectionProbes probes;
    REQUIRE(probes.layered());
    CHECK(probes.at_once() > 1);
    const int models = static_cast<int>(probes.at_once()) + 3;
    for (int m = 0; m < models; ++m) draw_checkered(probes, kSide, m);
    probes.finish();
    setenv("ANIMATOR_PROBE_MIPMAPS", "1", 1);
    ReflectionProbes generated;
    for (int m = 0; m < models; ++m) draw_checkered(generated, kSide, m);
    generated.finish();
    unsetenv("ANIMATOR_PROBE_MIPMAPS");
    for (int m = 0; m < models; ++m) {
        CAPTURE(m);
        CHECK(worst_level_error(probes, kSide, m) <= 1);
        // Each from its own level 0: as glGenerateMipmap makes it, texel for texel (a cube map
        // sampled from another's would differ, the squares shifted model to model).
        for (int face = 0; face < 6; ++face)
            for (int level = 1; level <= 2; ++level) {
                CAPTURE(face, level);
                CHECK(cube_level(probes.texture(m), face, level, kSide >> level) ==
                      cube_level(generated.texture(m), face, level, kSide >> level));
            }
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

TEST_CASE("a cube map sees a far model at a coarser level than the view and without speckles") {
    // A flat mirror 8 m wide on the ground, the camera 6 m above it looking down, and a lit
    // white ball 3 m above the camera: whole in the view's levels (2 m from the camera), but 8 m
    // from the mirror's centre, where a face of its cube map (128 pixels) sees it at a coarser
    // level. The mirror shows it in the middle of the view, seen from below. Its shadow map holds
    // it at the view's level, whose surface lies outside the coarser one's: the shading's normal
    // offset must cover the difference, or its lit side reads its own shadow in the reflection.
    // A far light (small shadow texels, a small offset) lights the side the mirror sees.
    Document doc = make_document(make_camera({0, 6, 0}, 0, -90));
    Settings s = doc.settings();
    s.lights = {Light{"lamp", {-14.0, 4.0, 6.0}, {1.0, 1.0, 1.0}, {1.0, 0.0, 0.0}}};
    doc.set_settings(s);
    Model mirror = make_model("mirror", "plane", {0.5, 0.5, 0.5});
    mirror.reflectivity = 1.0;
    doc.add_model(mirror, make_state({0, 0, 0}, {4, 1, 4}));
    doc.add_model(make_model("ball", "sphere", {0.9, 0.9, 0.9}), make_state({0, 9, 0}));
    const Rendered levels = render_document(doc, kWidth, kHeight);
    RenderOptions whole_meshes;
    whole_meshes.detail_pixels = 0.0;
    const Rendered whole = render_document(doc, kWidth, kHeight, {}, whole_meshes);
    REQUIRE(levels.stats.reflection_maps == 1);
    REQUIRE(levels.stats.shadow_maps == 1);
    // Fewer triangles, all of them in the cube map (the ball is behind the camera in the view).
    CHECK(levels.stats.triangles < whole.stats.triangles);
    // Inside the ball's lit side (whole meshes: lit 4 pixels around; the coarser level's outline
    // moves by up to its error, a face pixel, some 3 pixels of the view here), the coarser level
    // is as lit: its own shadow would darken it (the ambient light's and the lamp's share of it).
    constexpr int kBorder = 4;
    const auto bright = [&](int x, int y) { return pixel(whole.image, x, y).r > 150; };
    int inside = 0;
    double worst = 0.0;
    for (int y = kHeight / 2 - 40; y <= kHeight / 2 + 40; ++y)
        for (int x = kWidth / 2 - 40; x <= kWidth / 2 + 40; ++x) {
            bool all = true;
            for (int dy = -kBorder; dy <= kBorder; ++dy)
                for (int dx = -kBorder; dx <= kBorder; ++dx) all = all && bright(x + dx, y + dy);
            if (!all) continue;
            ++inside;
            worst =
                std::max(worst, double(pixel(whole.image, x, y).r - pixel(levels.image, x, y).r));
        }
    CAPTURE(inside, worst);
    CHECK(inside > 200); // (the lit side fills much of it: it is what is compared)
    // (Without the offset's widening, 19 darker at worst; with it 6.)
    CHECK(worst <= 10);
}
