// Distances between meshes (mesh_distance.hpp), for conservative advancement of keyed models:
// segment-segment against dense sampling, and cube-cube against hand-computed gaps.
#include "mesh_distance.hpp"

#include <catch2/catch.hpp>
#include <glm/geometric.hpp>

#include <cmath>
#include <random>

using namespace physics_custom;

namespace {

// The cube of side 2 centered at c (8 vertices, 12 triangles counter-clockwise outward).
struct Cube {
    std::vector<glm::dvec3> vertices;
    std::vector<uint32_t> triangles;
    std::vector<std::array<uint32_t, 2>> edges;
};

Cube cube(const glm::dvec3 &c, double half = 1.0) {
    Cube out;
    for (int k = 0; k < 8; ++k)
        out.vertices.push_back(c +
                               half * glm::dvec3(k & 1 ? 1 : -1, k & 2 ? 1 : -1, k & 4 ? 1 : -1));
    out.triangles = {0, 2, 1, 1, 2, 3, 4, 5, 6, 5, 7, 6, 0, 1, 4, 1, 5, 4,
                     2, 6, 3, 3, 6, 7, 0, 4, 2, 2, 4, 6, 1, 3, 5, 3, 7, 5};
    out.edges = edges_of(out.triangles.data(), 12);
    return out;
}

PlacedMesh placed(const Cube &c, const glm::dvec3 &center) {
    return {center, c.vertices, c.triangles.data(), 12, c.edges.data(), c.edges.size()};
}

} // namespace

TEST_CASE("closest points of two segments agree with dense sampling") {
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> u(-2.0, 2.0);
    for (int k = 0; k < 300; ++k) {
        const glm::dvec3 p1(u(rng), u(rng), u(rng)), q1(u(rng), u(rng), u(rng)),
            p2(u(rng), u(rng), u(rng)), q2(u(rng), u(rng), u(rng));
        glm::dvec3 c1, c2;
        closest_on_segments(p1, q1, p2, q2, c1, c2);
        const double d = glm::length(c1 - c2);
        double sampled = 1e300;
        for (int i = 0; i <= 100; ++i)
            for (int j = 0; j <= 100; ++j)
                sampled = std::min(sampled, glm::length((p1 + (q1 - p1) * (i / 100.0)) -
                                                        (p2 + (q2 - p2) * (j / 100.0))));
        CHECK(d <= sampled + 1e-12); // never worse than any sample
        CHECK(d >= sampled - 0.05 * glm::length(q1 - p1) -
                       0.05 * glm::length(q2 - p2)); // and near the best
    }
    // Parallel and degenerate segments.
    glm::dvec3 c1, c2;
    closest_on_segments({0, 0, 0}, {1, 0, 0}, {0.5, 1, 0}, {2, 1, 0}, c1, c2);
    CHECK(glm::length(c1 - c2) == Approx(1.0));
    closest_on_segments({0, 0, 0}, {0, 0, 0}, {3, 4, 0}, {3, 4, 0}, c1, c2);
    CHECK(glm::length(c1 - c2) == Approx(5.0));
}

TEST_CASE("the distance between two cubes, face to face, edge to edge, and touching") {
    const Cube a = cube({0, 0, 0}), b = cube({3.5, 0.2, -0.1});
    glm::dvec3 on_a, on_b, n;
    // Face to face along x: gap 3.5 - 2 = 1.5, normal from b towards a: -x.
    CHECK(mesh_distance(placed(a, {0, 0, 0}), placed(b, {3.5, 0.2, -0.1}), on_a, on_b, n) ==
          Approx(1.5));
    CHECK(n.x == Approx(-1.0));
    // Diagonally apart: nearest corner to corner, (3,3,3) - (1,1,1) apart by 1 on each axis.
    const Cube c = cube({3, 3, 3});
    CHECK(mesh_distance(placed(a, {0, 0, 0}), placed(c, {3, 3, 3}), on_a, on_b, n) ==
          Approx(std::sqrt(3.0)));
    CHECK(glm::length(n - glm::normalize(glm::dvec3(-1, -1, -1))) < 1e-9);
    // Touching face to face: the distance is 0 and the normal is still the face's.
    const Cube d = cube({2, 0.5, 0.5});
    CHECK(mesh_distance(placed(a, {0, 0, 0}), placed(d, {2, 0.5, 0.5}), on_a, on_b, n) ==
          Approx(0.0).margin(1e-15));
    CHECK(std::abs(n.x) == Approx(1.0));
    CHECK(n.x < 0.0); // from d (at +x) towards a
}

TEST_CASE("surfaces cross where a cube is sunk into another, not where they touch") {
    // Two cubes of side 2: one at the origin, the other above it at height h. They touch for
    // h = 2 (face on face) and overlap by 2 - h below; beside the first, over its edge (offset by
    // 1.5 along x, so its face hangs over the edge) they touch at h = 2 too.
    const Cube base = cube(glm::dvec3(0.0)), top = cube(glm::dvec3(0.0));
    const double tol = 1e-6;
    auto cross = [&](const glm::dvec3 &at) {
        Cube moved = top;
        for (glm::dvec3 &v : moved.vertices) v += at;
        return surfaces_cross(placed(moved, at), placed(base, glm::dvec3(0.0)), tol);
    };
    // Sunk by 1, not exactly aligned (aligned, its faces would lie in the other's planes, which
    // no edge crosses).
    CHECK(cross({0.3, 1.0, 0.2}));
    CHECK(cross({0.3, 1.999, 0.2}));            // sunk by 1e-3, off centre
    CHECK_FALSE(cross({0.0, 2.0, 0.0}));        // face on face
    CHECK_FALSE(cross({1.5, 2.0, 0.0}));        // over the edge, touching
    CHECK_FALSE(cross({1.5, 2.0 + 1e-7, 0.0})); // within single precision of touching
    CHECK(cross({1.5, 1.9, 0.0}));              // over the edge, sunk
    CHECK_FALSE(cross({2.5, 0.0, 0.0}));        // apart
    CHECK_FALSE(cross({2.0, 2.0, 0.0}));        // edge on edge
}
