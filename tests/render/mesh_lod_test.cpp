// Levels of detail (render/mesh_lod.hpp): each level's surface is within its stated error of the
// shape the mesh stands for, the renderer draws a far model with fewer triangles and a near one
// whole, and what it draws looks the same (the golden images' tolerance) as the whole meshes.
#include "image_compare.hpp"
#include "render_support.hpp"
#include "support.hpp"

#include "render/mesh_lod.hpp"

#include <catch2/catch.hpp>
#include <glm/geometric.hpp>

#include <cmath>
#include <map>
#include <set>
#include <tuple>

using namespace animator;
using namespace animator::test;

namespace {

const Mesh &generated(const std::string &name) {
    static std::map<std::string, Mesh> loaded;
    auto found = loaded.find(name);
    if (found == loaded.end())
        found = loaded.emplace(name, load_mesh(bin_dir().parent_path() / "assets/meshes" / name).mesh).first;
    return found->second;
}

// Vertex i of a chain's levels: the mesh's, or one a level added after them.
glm::dvec3 vertex(const Mesh &mesh, const LodChain &chain, std::uint32_t i) {
    return i < mesh.positions.size() ? mesh.positions[i]
                                     : chain.added_positions.at(i - mesh.positions.size());
}

// The largest distance from the unit sphere of points spread over a level's triangles (each
// triangle's corners and a grid of 45 points inside it).
double sphere_deviation(const Mesh &mesh, const LodChain &chain, const LodLevel &level) {
    double worst = 0.0;
    for (std::uint32_t t = level.first; t < level.first + level.count; t += 3) {
        const glm::dvec3 a = vertex(mesh, chain, chain.indices[t]),
                         b = vertex(mesh, chain, chain.indices[t + 1]),
                         c = vertex(mesh, chain, chain.indices[t + 2]);
        const int n = 8;
        for (int i = 0; i <= n; ++i)
            for (int j = 0; i + j <= n; ++j) {
                const glm::dvec3 p = a + (b - a) * (double(i) / n) + (c - a) * (double(j) / n);
                worst = std::max(worst, std::abs(1.0 - glm::length(p)));
            }
    }
    return worst;
}

std::set<std::uint32_t> used_vertices(const LodChain &chain, const LodLevel &level) {
    return {chain.indices.begin() + level.first, chain.indices.begin() + level.first + level.count};
}

} // namespace

TEST_CASE("a sphere's levels of detail halve its triangles and stay within their stated error of the sphere") {
    const Mesh &sphere = generated("sphere.obj"); // a UV sphere of radius 1, 32 x 32
    const LodChain chain = build_lod_chain(sphere);
    REQUIRE(chain.levels.size() >= 4);
    CHECK(chain.levels[0].count == sphere.triangles.size());
    CHECK(chain.levels[0].error == 0.0);
    const double own = sphere_deviation(sphere, chain, chain.levels[0]); // the mesh's own chords
    CHECK(own < 0.01);
    for (std::size_t i = 1; i < chain.levels.size(); ++i) {
        const LodLevel &level = chain.levels[i], &before = chain.levels[i - 1];
        INFO("level " << i << ": " << level.count / 3 << " triangles, error " << level.error);
        CHECK(level.count % 3 == 0);
        // The simplified levels first, each coarser than the one before; then the even ones
        // (sphere_lod.hpp), likewise among themselves.
        if (level.keeps_texture == before.keeps_texture) {
            CHECK(level.count * 4 <= before.count * 3);
            CHECK(level.error >= before.error);
        } else {
            CHECK(before.keeps_texture);
        }
        CHECK(level.count / 3 >= 24);
        // The truth is the sphere: no point of the level lies farther from it than the level's
        // stated error beyond what the whole mesh's own chords stray.
        CHECK(sphere_deviation(sphere, chain, level) <= level.error + own + 1e-6);
        // The simplified levels over the mesh's own vertices (normals and UVs stay those of the
        // mesh); the even ones over their own, pushed out of the sphere by less than their error
        // (sphere_lod.hpp), normals along the radius.
        CHECK(chain.added_positions.size() == chain.added_normals.size());
        for (std::uint32_t v : used_vertices(chain, level)) {
            if (level.keeps_texture) {
                REQUIRE(v < sphere.positions.size());
            } else {
                REQUIRE(v >= sphere.positions.size());
                const std::size_t k = v - sphere.positions.size();
                REQUIRE(k < chain.added_positions.size());
                const glm::dvec3 p = chain.added_positions[k];
                CHECK(glm::length(p) >= 1.0 - 1e-6);
                CHECK(glm::length(p) <= 1.0 + level.error);
                CHECK(glm::length(chain.added_normals[k] - glm::normalize(p)) < 1e-6);
            }
        }
    }
}

TEST_CASE("a sphere's even levels stray less than its simplified ones of as many triangles and "
          "keep no texture seam") {
    const Mesh &sphere = generated("sphere.obj");
    const LodChain chain = build_lod_chain(sphere);
    const double own = sphere_deviation(sphere, chain, chain.levels[0]);
    std::size_t even = 0;
    for (const LodLevel &level : chain.levels) {
        if (level.keeps_texture) continue;
        ++even;
        INFO(level.count / 3 << " triangles, error " << level.error);
        // Within its stated error of the sphere, the truth.
        CHECK(sphere_deviation(sphere, chain, level) <= level.error + own + 1e-6);
        // Closed: every edge is shared by two of its triangles, once each way (a hull's faces
        // wound alike), and Euler's V - E + F = 2.
        std::map<std::pair<glm::dvec3, glm::dvec3>, int,
                 bool (*)(const std::pair<glm::dvec3, glm::dvec3> &,
                          const std::pair<glm::dvec3, glm::dvec3> &)>
            edges([](const auto &a, const auto &b) {
                const auto key = [](const auto &e) {
                    return std::make_tuple(e.first.x, e.first.y, e.first.z, e.second.x, e.second.y,
                                           e.second.z);
                };
                return key(a) < key(b);
            });
        std::set<std::tuple<double, double, double>> corners;
        for (std::uint32_t t = level.first; t < level.first + level.count; t += 3)
            for (int k = 0; k < 3; ++k) {
                const glm::dvec3 a = vertex(sphere, chain, chain.indices[t + k]),
                                 b = vertex(sphere, chain, chain.indices[t + (k + 1) % 3]);
                ++edges[{a, b}];
                corners.insert({a.x, a.y, a.z});
            }
        bool paired = true;
        for (const auto &[edge, n] : edges) {
            const auto back = edges.find({edge.second, edge.first});
            paired = paired && n == 1 && back != edges.end() && back->second == 1;
        }
        CHECK(paired);
        CHECK(static_cast<long>(corners.size()) - static_cast<long>(edges.size() / 2) +
                  static_cast<long>(level.count / 3) ==
              2);
        // Wound as the sphere's own triangles: out of the sphere.
        for (std::uint32_t t = level.first; t < level.first + level.count; t += 3) {
            const glm::dvec3 a = vertex(sphere, chain, chain.indices[t]),
                             b = vertex(sphere, chain, chain.indices[t + 1]),
                             c = vertex(sphere, chain, chain.indices[t + 2]);
            REQUIRE(glm::dot(glm::cross(b - a, c - a), a + b + c) > 0.0);
        }
    }
    CHECK(even >= 4);
    // At each simplified level's error, the level chosen for an untextured model has at most
    // 3/4 of its triangles from 496 down (sphere.obj's 496: 0.030 of the radius; an even level of
    // 252 triangles strays as far), and for a textured one it is that level.
    for (std::size_t i = 2; i < chain.levels.size() && chain.levels[i].keeps_texture; ++i) {
        const LodLevel &simplified = chain.levels[i];
        INFO(simplified.count / 3 << " triangles, error " << simplified.error);
        CHECK(choose_level(chain.levels, simplified.error, true) == i);
        CHECK(chain.levels[choose_level(chain.levels, simplified.error, false)].count * 4 <=
              simplified.count * 3);
    }
}

TEST_CASE("a flat grid's coarser levels lose nothing of its shape, and a small mesh keeps one level") {
    const Mesh &floor = generated("floor_fine.obj"); // a flat 64 x 64 grid
    const LodChain chain = build_lod_chain(floor);
    REQUIRE(chain.levels.size() >= 2);
    for (std::size_t i = 1; i < chain.levels.size(); ++i) {
        INFO("level " << i << ": " << chain.levels[i].count / 3 << " triangles");
        CHECK(chain.levels[i].error < 1e-6);
        // Still the whole square: its triangles' areas add up to the grid's.
        double area = 0.0, whole = 0.0;
        auto add = [&](const LodLevel &l, double &sum) {
            for (std::uint32_t t = l.first; t < l.first + l.count; t += 3)
                sum += 0.5 * glm::length(glm::cross(floor.positions[chain.indices[t + 1]] - floor.positions[chain.indices[t]],
                                                    floor.positions[chain.indices[t + 2]] - floor.positions[chain.indices[t]]));
        };
        add(chain.levels[0], whole);
        add(chain.levels[i], area);
        CHECK(area == Approx(whole).epsilon(1e-6));
    }
    CHECK(build_lod_chain(generated("cube.obj")).levels.size() == 1);
}

TEST_CASE("the coarsest level within the allowed error is chosen") {
    const std::vector<LodLevel> levels = {{0, 300, 0.0}, {300, 150, 0.01}, {450, 75, 0.04}};
    CHECK(choose_level(levels, 0.0) == 0);
    CHECK(choose_level(levels, 0.005) == 0);
    CHECK(choose_level(levels, 0.01) == 1);
    CHECK(choose_level(levels, 0.039) == 1);
    CHECK(choose_level(levels, 1.0) == 2);
    // A level that does not keep the texture's seam: the fewest triangles within the error, but
    // not for a textured model.
    std::vector<LodLevel> with_even = levels;
    with_even.push_back({525, 90, 0.02, false});
    CHECK(choose_level(with_even, 0.02) == 3);
    CHECK(choose_level(with_even, 0.02, true) == 1);
    CHECK(choose_level(with_even, 0.04) == 2);
}

namespace {

// A floor and a 6 x 5 grid of balls from 10 to 40 m away.
Document far_balls() {
    Document doc = make_document(make_camera({0, 3, 12}, 0, -4), false, "day");
    doc.add_model(make_model("floor", "plane", {0.5, 0.5, 0.5}), make_state({0, 0, -15}, {20, 1, 30}));
    for (int i = 0; i < 30; ++i) {
        Model m = make_model("ball" + std::to_string(i), "sphere", {0.3 + 0.02 * i, 0.5, 0.9 - 0.02 * i},
                             {0.6, 0.6, 0.6}, 30);
        if (i % 4 == 0) m.texture = "wood";
        doc.add_model(m, make_state({(i % 6) * 3.0 - 7.5, 1.0, -(i / 6) * 7.0}));
    }
    return doc;
}

} // namespace

TEST_CASE("far models are drawn with fewer triangles and look as their whole meshes do") {
    const Document doc = far_balls();
    RenderOptions whole;
    whole.detail_pixels = 0.0;
    whole.shadows = false;
    RenderOptions detail = whole;
    detail.detail_pixels = 0.5;
    const Rendered full = render_document(doc, 640, 360, {}, whole);
    const Rendered lod = render_document(doc, 640, 360, {}, detail);
    const std::size_t sphere = generated("sphere.obj").triangle_count();
    // Work counts: whole meshes draw every triangle; levels of detail leave out more than half.
    CHECK(full.stats.triangles == 30 * sphere + 2);
    CHECK(full.stats.triangles_saved == 0);
    CHECK(lod.stats.triangles + lod.stats.triangles_saved == full.stats.triangles);
    CHECK(lod.stats.triangles * 2 < full.stats.triangles);
    // The same picture, as the golden images judge (tests/render/golden_test.cpp's tolerance).
    const ImageDifference d = compare_images(lod.image, full.image, 48.0);
    INFO("mean " << d.mean << ", max " << d.max << ", over 48: " << d.over);
    CHECK(d.mean < 0.5);
    CHECK(d.over < 0.001);
}

TEST_CASE("a model near the camera is drawn whole, and a far one as coarse in its shadow map as in the view") {
    Document doc = make_document(make_camera({0, 0, 3}), false);
    doc.add_model(make_model("ball", "sphere", {0.8, 0.2, 0.2}), make_state({0, 0, 0}));
    RenderOptions options;
    options.shadows = false;
    const Rendered near = render_document(doc, 320, 240, {}, options);
    CHECK(near.stats.triangles == generated("sphere.obj").triangle_count());
    CHECK(near.stats.triangles_saved == 0);
    // A ball far from the camera: a coarser level in the view; with shadows on, the same level in
    // the shadow map (another surface there would shadow the one in view).
    doc = make_document(make_camera({0, 2, 80}), false);
    doc.add_model(make_model("floor", "plane", {0.5, 0.5, 0.5}), make_state({0, -1, 0}, {100, 1, 100}));
    doc.add_model(make_model("ball", "sphere", {0.8, 0.2, 0.2}), make_state({0, 0, 0}));
    const Rendered far = render_document(doc, 320, 240, {}, options);
    CHECK(far.stats.triangles < near.stats.triangles);
    CHECK(far.stats.triangles_saved > 0);
    options.shadows = true;
    const Rendered shadowed = render_document(doc, 320, 240, {}, options);
    CHECK(shadowed.stats.shadow_casters == 2);
    CHECK(shadowed.stats.triangles_saved == 2 * far.stats.triangles_saved);
    // A mirror keeps its whole mesh however far: its reflection turns with the normals.
    Model mirror = doc.models()[1];
    mirror.reflectivity = 0.8;
    doc.set_model(1, mirror);
    options.shadows = false;
    CHECK(render_document(doc, 320, 240, {}, options).stats.triangles_saved == 0);
    // Unless asked (the editor's frame budget while playing): then at the plain ball's level.
    options.mirror_levels = true;
    CHECK(render_document(doc, 320, 240, {}, options).stats.triangles_saved ==
          far.stats.triangles_saved);
}

TEST_CASE("coarser levels of detail (the frame budget's 2 pixels) draw fewer triangles and look "
          "alike") {
    const Document doc = far_balls();
    RenderOptions fine;
    fine.shadows = false;
    RenderOptions coarse = fine;
    coarse.detail_pixels = 2.0;
    const Rendered a = render_document(doc, 640, 360, {}, fine);
    const Rendered b = render_document(doc, 640, 360, {}, coarse);
    // Work counts: each ball's level is the coarsest within 2 pixels (mesh_lod.hpp), so fewer
    // triangles in all, and every level coarser or the same.
    CHECK(b.stats.triangles < a.stats.triangles);
    CHECK(b.stats.triangles + b.stats.triangles_saved == a.stats.triangles + a.stats.triangles_saved);
    // Outlines move by up to 2 pixels: the pictures differ at some edge pixels, and little in
    // the mean (a frame drawn while playing, never a still frame or `animator render`'s).
    const ImageDifference d = compare_images(b.image, a.image, 48.0);
    INFO("mean " << d.mean << ", max " << d.max << ", over 48: " << d.over);
    CHECK(d.mean < 1.0);
    CHECK(d.over < 0.005);
}
