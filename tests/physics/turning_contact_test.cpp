// Time of impact for turning meshes (turning_contact.hpp) against independent truths: closed
// forms for a falling cube and two crossing edges, a brute-force root search coded here (dense
// sampling of the lowest vertex plus bisection, rotating by Rodrigues' formula rather than by
// quaternions) for turning cubes and a fast plank, and the sphere's closed form bracketed by the
// tessellation's inner and outer radii.
#include "mesh_distance.hpp"
#include "test_meshes.hpp"
#include "turning_contact.hpp"

#include <catch2/catch.hpp>
#include <glm/geometric.hpp>

#include <cmath>
#include <functional>
#include <limits>
#include <random>
#include <vector>

using namespace physics_custom;

namespace {

constexpr double kG = 9.81;

// Never past the truth, up to the rounding of the truth itself (a few units in the last place
// of t: the brute force evaluates the same heights in a different order).
bool not_past(double t, double truth) {
    return t <= truth + 8.0 * 2.2e-16 * truth;
}

// A box with half-extents e about its centre (8 vertices, 12 triangles outward).
struct TestMesh {
    std::vector<glm::dvec3> vertices;
    std::vector<uint32_t> triangles;
    std::vector<std::array<uint32_t, 2>> edges;
    TurningMesh mesh() const {
        return {vertices.data(),      vertices.size(), triangles.data(),
                triangles.size() / 3, edges.data(),    edges.size()};
    }
};

TestMesh box(const glm::dvec3 &e) {
    TestMesh out;
    for (int k = 0; k < 8; ++k)
        out.vertices.push_back(e * glm::dvec3(k & 1 ? 1 : -1, k & 2 ? 1 : -1, k & 4 ? 1 : -1));
    out.triangles = {0, 2, 1, 1, 2, 3, 4, 5, 6, 5, 7, 6, 0, 1, 4, 1, 5, 4,
                     2, 6, 3, 3, 6, 7, 0, 4, 2, 2, 4, 6, 1, 3, 5, 3, 7, 5};
    out.edges = edges_of(out.triangles.data(), 12);
    return out;
}

// A square of two triangles in the plane x[axis] = at, spanning [-half, half] in the others:
// a world-space soup (a ground or a thin wall).
TestMesh square(int axis, double at, double half) {
    TestMesh out;
    const int u = (axis + 1) % 3, v = (axis + 2) % 3;
    for (int k = 0; k < 4; ++k) {
        glm::dvec3 p(0.0);
        p[axis] = at;
        p[u] = (k & 1 ? 1 : -1) * half;
        p[v] = (k & 2 ? 1 : -1) * half;
        out.vertices.push_back(p);
    }
    out.triangles = {0, 1, 3, 0, 3, 2};
    out.edges = edges_of(out.triangles.data(), 2);
    return out;
}

// Rodrigues' rotation of p by angle about the unit axis k.
glm::dvec3 rodrigues(const glm::dvec3 &p, const glm::dvec3 &k, double angle) {
    return p * std::cos(angle) + glm::cross(k, p) * std::sin(angle) +
           k * glm::dot(k, p) * (1.0 - std::cos(angle));
}

// The first root of H(t) = min_i height_i(t) in [0, t_end] by sampling every `dt` and bisecting
// the first sign change to rounding; -1 when none.
double brute_first_root(const std::function<double(double)> &H, double t_end, double dt) {
    double prev = 0.0;
    if (!(H(prev) > 0.0)) return 0.0;
    for (double t = dt; t <= t_end; t += dt) {
        if (H(t) <= 0.0) {
            double lo = prev, hi = t;
            for (int k = 0; k < 200 && std::nextafter(lo, 1e300) < hi; ++k) {
                const double mid = 0.5 * (lo + hi);
                (H(mid) > 0.0 ? lo : hi) = mid;
            }
            return lo;
        }
        prev = t;
    }
    return -1.0;
}

// The lowest height above the plane n . x = d of vertices turned about axis k (unit) at rate
// omega from angle0 and carried by c(t) = c0 + v t + a t^2 / 2.
std::function<double(double)> lowest_height(const std::vector<glm::dvec3> &vertices, glm::dvec3 k,
                                            double angle0, double omega, glm::dvec3 c0,
                                            glm::dvec3 v, glm::dvec3 a, glm::dvec3 n, double d) {
    return [=](double t) {
        double lowest = 1e300;
        const glm::dvec3 c = c0 + v * t + a * (0.5 * t * t);
        for (const glm::dvec3 &p : vertices)
            lowest = std::min(lowest, glm::dot(n, c + rodrigues(p, k, angle0 + omega * t)) - d);
        return lowest;
    };
}

// turning_mesh_contact's work against the plain advancement, which measures every pair of
// triangles at each step: the same contact (within 1e-12 s), in at most 200 plain steps; the
// pairs each measured, added to `lazy` and `plain` for the caller to compare.
void against_plain(const TurningContact &hit, const TurningMesh &a, const TurningPath &pa,
                   const TurningMesh &b, const TurningPath &pb, double t0, double t1,
                   std::size_t &lazy, std::size_t &plain) {
    TurningContactSettings settings;
    settings.measure_every_pair = true;
    const TurningContact every = turning_mesh_contact(a, pa, b, pb, t0, t1, settings);
    CHECK(every.kind == hit.kind);
    CHECK(std::abs(every.t - hit.t) <= 1e-12);
    CHECK(every.steps < 200);
    lazy += hit.pair_tests;
    plain += every.pair_tests;
}

} // namespace

TEST_CASE("turning contact: a cube dropped on its corner lands at the closed-form time",
          "[physics][turning]") {
    // Body diagonal (1,1,1)/sqrt3 turned onto -y: the lowest corner is sqrt(3)/2 below the
    // centre, which falls from rest at h = 3 under g, so it lands at sqrt(2 (h - sqrt3/2) / g).
    const TestMesh cube = box(glm::dvec3(0.5));
    const glm::dvec3 from = glm::normalize(glm::dvec3(1.0)), to(0.0, -1.0, 0.0);
    TurningPath path;
    path.q0 = glm::angleAxis(std::acos(glm::dot(from, to)), glm::normalize(glm::cross(from, to)));
    path.c0 = {0.0, 3.0, 0.0};
    path.a = {0.0, -kG, 0.0};
    const double truth = std::sqrt(2.0 * (3.0 - std::sqrt(3.0) / 2.0) / kG);
    const StaticPlane ground{{0.0, 1.0, 0.0}, 0.0};

    const TurningContact hit = turning_plane_contact(cube.mesh(), path, ground, 0.0, 5.0);
    REQUIRE(hit.kind == TurningContact::kVertexFace);
    CHECK(not_past(hit.t, truth)); // never past the truth
    CHECK(truth - hit.t <= 1e-12);
    CHECK(hit.points.size() == 1);
    CHECK(std::abs(hit.point.y) < 1e-11);
    CHECK(glm::length(glm::dvec3(hit.point.x, 0.0, hit.point.z)) < 1e-12);
    CHECK(hit.normal == glm::dvec3(0.0, 1.0, 0.0));
    CHECK(hit.steps < 200);

    const double root = turning_plane_root(cube.mesh(), path, ground, hit.t, 5.0);
    CHECK(std::abs(root - truth) <= 1e-14);

    // The same ground as a two-triangle soup.
    const TestMesh soup = square(1, 0.0, 10.0);
    const TurningContact on_soup =
        turning_mesh_contact(cube.mesh(), path, soup.mesh(), TurningPath{}, 0.0, 5.0);
    REQUIRE(on_soup.kind == TurningContact::kVertexFace);
    CHECK(not_past(on_soup.t, truth));
    CHECK(truth - on_soup.t <= 1e-12);
    CHECK(glm::length(on_soup.normal - glm::dvec3(0.0, 1.0, 0.0)) < 1e-12);
    std::size_t lazy = 0, plain = 0;
    against_plain(on_soup, cube.mesh(), path, soup.mesh(), TurningPath{}, 0.0, 5.0, lazy, plain);
    CHECK(lazy <= plain);
}

TEST_CASE("turning contact: a cube turning towards a wall meets it at the brute-force time",
          "[physics][turning]") {
    // No gravity, moving +x at 2 m/s towards the wall x = 5 (normal -x), turning at 3 rad/s about
    // a horizontal axis. The truth turns the vertices by Rodrigues' formula and samples.
    const TestMesh cube = box(glm::dvec3(0.5));
    const StaticPlane wall{{-1.0, 0.0, 0.0}, -5.0};
    struct Case {
        glm::dvec3 axis;
        double angle0;
    };
    for (const Case &c :
         {Case{{0.0, 0.0, 1.0}, 0.3}, Case{{0.6, 0.0, 0.8}, 0.0}, Case{{0.0, 0.0, 1.0}, 1.1}}) {
        TurningPath path;
        path.c0 = {0.0, 1.0, 0.0};
        path.v = {2.0, 0.0, 0.0};
        path.q0 = glm::angleAxis(c.angle0, c.axis);
        path.w = 3.0 * c.axis;
        const double truth =
            brute_first_root(lowest_height(cube.vertices, c.axis, c.angle0, 3.0, path.c0, path.v,
                                           glm::dvec3(0.0), wall.n, wall.d),
                             5.0, 1e-4);
        REQUIRE(truth > 0.0);

        const TurningContact hit = turning_plane_contact(cube.mesh(), path, wall, 0.0, 5.0);
        REQUIRE(hit.kind == TurningContact::kVertexFace);
        CHECK(not_past(hit.t, truth));
        CHECK(truth - hit.t <= 1e-12);
        CHECK(hit.steps < 200);
        CHECK(std::abs(hit.point.x - 5.0) < 1e-11);

        const double root = turning_plane_root(cube.mesh(), path, wall, hit.t, 5.0);
        CHECK(std::abs(root - truth) <= 1e-14);

        const TestMesh soup = square(0, 5.0, 10.0);
        const TurningContact on_soup =
            turning_mesh_contact(cube.mesh(), path, soup.mesh(), TurningPath{}, 0.0, 5.0);
        REQUIRE(on_soup.found());
        INFO("axis " << c.axis.x << " " << c.axis.z << " angle0 " << c.angle0 << " t-truth "
                     << on_soup.t - truth << " normal " << on_soup.normal.x << " "
                     << on_soup.normal.y << " " << on_soup.normal.z << " gap " << on_soup.gap
                     << " steps " << on_soup.steps);
        CHECK(not_past(on_soup.t, truth));
        CHECK(truth - on_soup.t <= 1e-12);
        CHECK(glm::length(on_soup.normal - wall.n) < 1e-9);
        std::size_t lazy = 0, plain = 0;
        against_plain(on_soup, cube.mesh(), path, soup.mesh(), TurningPath{}, 0.0, 5.0, lazy,
                      plain);
        CHECK(lazy <= plain);
    }
}

TEST_CASE("turning contact: random turning cubes against a wall agree with brute force",
          "[physics][turning]") {
    // 40 cubes with random axes (any direction), rates up to 20 rad/s and speeds 0.5-5 m/s
    // towards the wall x = 5, with random accelerations (never away from the wall).
    const TestMesh cube = box(glm::dvec3(0.5));
    const TestMesh soup = square(0, 5.0, 20.0);
    const StaticPlane wall{{-1.0, 0.0, 0.0}, -5.0};
    std::mt19937 random(18);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    int most_steps = 0;
    std::size_t lazy = 0, plain = 0;
    for (int k = 0; k < 40; ++k) {
        glm::dvec3 axis;
        do axis = {unit(random), unit(random), unit(random)};
        while (glm::length(axis) > 1.0 || glm::length(axis) < 0.1);
        axis = glm::normalize(axis);
        const double omega = 10.0 * (unit(random) + 1.0), angle0 = 3.0 * unit(random);
        TurningPath path;
        path.c0 = {0.0, unit(random), unit(random)};
        path.v = {2.75 + 2.25 * unit(random), unit(random), unit(random)};
        path.a = {0.5 * (unit(random) + 1.0), unit(random), 0.0};
        path.q0 = glm::angleAxis(angle0, axis);
        path.w = omega * axis;
        const double truth =
            brute_first_root(lowest_height(cube.vertices, axis, angle0, omega, path.c0, path.v,
                                           path.a, wall.n, wall.d),
                             10.0, 1e-4);
        REQUIRE(truth > 0.0);
        const TurningContact hit = turning_plane_contact(cube.mesh(), path, wall, 0.0, 10.0);
        const TurningContact on_soup =
            turning_mesh_contact(cube.mesh(), path, soup.mesh(), TurningPath{}, 0.0, 10.0);
        INFO("case " << k << " truth " << truth);
        REQUIRE(hit.found());
        REQUIRE(on_soup.found());
        CHECK(not_past(hit.t, truth));
        CHECK(truth - hit.t <= 1e-12);
        CHECK(not_past(on_soup.t, truth));
        CHECK(truth - on_soup.t <= 1e-12);
        CHECK(std::abs(turning_plane_root(cube.mesh(), path, wall, hit.t, 10.0) - truth) <= 1e-14);
        most_steps = std::max(most_steps, hit.steps);
        against_plain(on_soup, cube.mesh(), path, soup.mesh(), TurningPath{}, 0.0, 10.0, lazy,
                      plain);
    }
    CHECK(most_steps < 200);
    CHECK(lazy <= plain);
}

TEST_CASE("turning contact: a cube spinning up towards a wall, known only by bounds on w",
          "[physics][turning]") {
    // The turn angle about a fixed axis k is theta(t) = 0.4 + t + 3 t^2 (w = 1 + 6 t rad/s, not
    // constant): over [0, 3] |w| <= 19 and |w'| = 6. The steps see only those bounds; the truth
    // turns the vertices by Rodrigues' formula at theta(t) and samples.
    const TestMesh cube = box(glm::dvec3(0.5));
    const StaticPlane wall{{-1.0, 0.0, 0.0}, -5.0};
    const TestMesh soup = square(0, 5.0, 20.0);
    for (const glm::dvec3 &k :
         {glm::dvec3(0.0, 0.0, 1.0), glm::normalize(glm::dvec3(1.0, 2.0, 2.0))}) {
        auto theta = [](double t) { return 0.4 + t + 3.0 * t * t; };
        TurningPath path;
        path.c0 = {0.0, 0.3, 0.0};
        path.v = {1.5, 0.0, 0.0};
        path.turn = [=](double t) { return glm::angleAxis(theta(t), k); };
        path.turn_rate = [=](double t) { return (1.0 + 6.0 * t) * k; };
        path.w_bound = 19.0;
        path.w_rate_bound = 6.0;
        const double truth = brute_first_root(
            [&](double t) {
                double lowest = 1e300;
                for (const glm::dvec3 &p : cube.vertices)
                    lowest = std::min(
                        lowest, glm::dot(wall.n, path.c0 + path.v * t + rodrigues(p, k, theta(t))) -
                                    wall.d);
                return lowest;
            },
            3.0, 1e-5);
        REQUIRE(truth > 0.0);
        const TurningContact hit = turning_plane_contact(cube.mesh(), path, wall, 0.0, 3.0);
        REQUIRE(hit.found());
        CHECK(not_past(hit.t, truth));
        CHECK(truth - hit.t <= 1e-12);
        CHECK(hit.steps < 200);
        CHECK(std::abs(turning_plane_root(cube.mesh(), path, wall, hit.t, 3.0) - truth) <= 1e-14);
        const TurningContact on_soup =
            turning_mesh_contact(cube.mesh(), path, soup.mesh(), TurningPath{}, 0.0, 3.0);
        REQUIRE(on_soup.found());
        CHECK(not_past(on_soup.t, truth));
        CHECK(truth - on_soup.t <= 1e-12);
        std::size_t lazy = 0, plain = 0;
        against_plain(on_soup, cube.mesh(), path, soup.mesh(), TurningPath{}, 0.0, 3.0, lazy,
                      plain);
        CHECK(lazy <= plain);
    }
}

TEST_CASE("turning contact: a thin fast-turning plank never passes a thin wall",
          "[physics][turning]") {
    // A 2 m x 2 cm x 0.5 m plank spinning at 40 rad/s about z, flying at 30 m/s at a wall of
    // zero thickness (two triangles, x = 3): a check at fixed steps of 1/60 s (0.5 m of flight
    // and 38 degrees of turn) could step over it; advancement must stop before the truth.
    const TestMesh plank = box({1.0, 0.01, 0.25});
    const TestMesh wall = square(0, 3.0, 10.0);
    const StaticPlane plane{{-1.0, 0.0, 0.0}, -3.0};
    for (double angle0 : {0.0, 0.7, 2.0}) {
        TurningPath path;
        path.v = {30.0, 0.0, 0.0};
        path.q0 = glm::angleAxis(angle0, glm::dvec3(0.0, 0.0, 1.0));
        path.w = {0.0, 0.0, 40.0};
        const double truth =
            brute_first_root(lowest_height(plank.vertices, {0.0, 0.0, 1.0}, angle0, 40.0, path.c0,
                                           path.v, glm::dvec3(0.0), plane.n, plane.d),
                             1.0, 1e-6);
        REQUIRE(truth > 0.0);
        const TurningContact hit =
            turning_mesh_contact(plank.mesh(), path, wall.mesh(), TurningPath{}, 0.0, 1.0);
        REQUIRE(hit.found());
        CHECK(not_past(hit.t, truth));
        CHECK(truth - hit.t <= 1e-12);
        CHECK(glm::length(hit.normal - plane.n) < 1e-9);
        CHECK(hit.steps < 200);

        const TurningContact on_plane = turning_plane_contact(plank.mesh(), path, plane, 0.0, 1.0);
        REQUIRE(on_plane.found());
        CHECK(not_past(on_plane.t, truth));
        CHECK(truth - on_plane.t <= 1e-12);
        CHECK(on_plane.steps < 200);
    }
}

TEST_CASE("turning contact: a tessellated sphere lands between its outer and inner spheres' "
          "closed-form times",
          "[physics][turning]") {
    // Every vertex lies on the sphere of radius r and every face at least r_in from the centre,
    // so the mesh lies between those spheres and lands between their closed-form times
    // sqrt(2 (h - r) / g) and sqrt(2 (h - r_in) / g), whatever its turn.
    auto [unit, tris] = test_meshes::subdivided_icosahedron(2);
    tris = test_meshes::facing_out(unit, tris);
    const double r = 0.5;
    std::vector<glm::dvec3> vertices;
    for (const glm::dvec3 &p : unit) vertices.push_back(r * p);
    std::vector<uint32_t> flat;
    double r_in = r;
    for (const auto &t : tris) {
        for (uint32_t i : t) flat.push_back(i);
        const glm::dvec3 n = glm::normalize(
            glm::cross(vertices[t[1]] - vertices[t[0]], vertices[t[2]] - vertices[t[0]]));
        r_in = std::min(r_in, glm::dot(n, vertices[t[0]]));
    }
    const auto edges = edges_of(flat.data(), tris.size());
    const TurningMesh mesh{vertices.data(), vertices.size(), flat.data(),
                           tris.size(),     edges.data(),    edges.size()};
    TurningPath path;
    path.c0 = {0.0, 2.0, 0.0};
    path.v = {1.0, 0.0, 0.0};
    path.a = {0.0, -kG, 0.0};
    path.w = {2.0, 1.0, 0.5};
    const double outer = std::sqrt(2.0 * (2.0 - r) / kG),
                 inner = std::sqrt(2.0 * (2.0 - r_in) / kG);
    REQUIRE(inner - outer < 1e-2); // the tessellation error the bracket allows

    const TurningContact hit = turning_plane_contact(mesh, path, {{0.0, 1.0, 0.0}, 0.0}, 0.0, 5.0);
    REQUIRE(hit.found());
    CHECK(hit.t >= outer - 1e-15);
    CHECK(hit.t <= inner);
    CHECK(hit.steps < 200);
    const double root = turning_plane_root(mesh, path, {{0.0, 1.0, 0.0}, 0.0}, hit.t, 5.0);
    CHECK(root >= hit.t);
    CHECK(root - hit.t <= 1e-12);

    const TestMesh ground = square(1, 0.0, 10.0);
    const TurningContact on_soup =
        turning_mesh_contact(mesh, path, ground.mesh(), TurningPath{}, 0.0, 5.0);
    REQUIRE(on_soup.found());
    CHECK(not_past(on_soup.t, root));
    CHECK(root - on_soup.t <= 1e-12);
    std::size_t lazy = 0, plain = 0;
    against_plain(on_soup, mesh, path, ground.mesh(), TurningPath{}, 0.0, 5.0, lazy, plain);
    CHECK(lazy <= plain);
}

TEST_CASE("turning contact: two crossed edges meet at the closed-form time, edge to edge",
          "[physics][turning]") {
    // Cube a turned 45 degrees about x hangs an edge along x, sqrt(2)/2 below its centre; cube b
    // turned 45 degrees about z raises an edge along z, sqrt(2)/2 above its centre. a falls from
    // rest (centres 3 apart, vertically) while spinning about the vertical at 1 rad/s, which
    // keeps its lowest edge level and under its centre, so the edges cross and meet at
    // sqrt(2 (3 - sqrt2) / g), the normal +y (from b towards a).
    const TestMesh cube = box(glm::dvec3(0.5));
    const double pi = std::acos(-1.0);
    TurningPath a, b;
    a.c0 = {0.0, 3.0, 0.0};
    a.a = {0.0, -kG, 0.0};
    a.q0 = glm::angleAxis(pi / 4.0, glm::dvec3(1.0, 0.0, 0.0));
    a.w = {0.0, 1.0, 0.0};
    b.q0 = glm::angleAxis(pi / 4.0, glm::dvec3(0.0, 0.0, 1.0));
    const double truth = std::sqrt(2.0 * (3.0 - std::sqrt(2.0)) / kG);
    const TurningContact hit = turning_mesh_contact(cube.mesh(), a, cube.mesh(), b, 0.0, 5.0);
    REQUIRE(hit.kind == TurningContact::kEdgeEdge);
    CHECK(not_past(hit.t, truth));
    CHECK(truth - hit.t <= 1e-12);
    CHECK(glm::length(hit.normal - glm::dvec3(0.0, 1.0, 0.0)) < 1e-9);
    CHECK(glm::length(hit.point - glm::dvec3(0.0, std::sqrt(0.5), 0.0)) < 1e-9);
    CHECK(hit.steps < 200);
}

TEST_CASE("turning contact: no contact within the window, and a miss", "[physics][turning]") {
    const TestMesh cube = box(glm::dvec3(0.5));
    TurningPath path;
    path.c0 = {0.0, 3.0, 0.0};
    path.a = {0.0, -kG, 0.0};
    path.w = {0.0, 0.0, 5.0};
    const StaticPlane ground{{0.0, 1.0, 0.0}, 0.0};
    // The centre reaches 0.5 + sqrt(3)/2 (the highest the lowest corner can be) only at
    // sqrt(2 (3 - 0.5 - sqrt3/2) / g) ~ 0.577 s: nothing before 0.5 s.
    const TurningContact early = turning_plane_contact(cube.mesh(), path, ground, 0.0, 0.5);
    CHECK(early.kind == TurningContact::kNone);
    CHECK(turning_plane_root(cube.mesh(), path, ground, 0.0, 0.5) > 0.5);
    // Moving up and away from a wall beside it: never.
    path.a = glm::dvec3(0.0);
    path.v = {-1.0, 0.0, 0.0};
    const TurningContact away =
        turning_plane_contact(cube.mesh(), path, {{-1.0, 0.0, 0.0}, -5.0}, 0.0, 100.0);
    CHECK(away.kind == TurningContact::kNone);
}

TEST_CASE("turning contact: inputs that are not finite are refused", "[physics][turning]") {
    const TestMesh cube = box(glm::dvec3(0.5));
    const StaticPlane ground{{0.0, 1.0, 0.0}, 0.0};
    TurningPath path;
    path.c0 = {0.0, 3.0, 0.0};
    path.w = {0.0, std::nan(""), 0.0};
    CHECK(turning_plane_contact(cube.mesh(), path, ground, 0.0, 1.0).kind ==
          TurningContact::kInvalid);
    CHECK(std::isnan(turning_plane_root(cube.mesh(), path, ground, 0.0, 1.0)));
    path.w = glm::dvec3(0.0);
    CHECK(turning_mesh_contact(cube.mesh(), path, cube.mesh(), TurningPath{}, 0.0,
                               std::numeric_limits<double>::infinity())
              .kind == TurningContact::kInvalid);
    CHECK(turning_plane_contact(cube.mesh(), path, ground, 0.0, 1.0).kind ==
          TurningContact::kNone); // falls no further than it is now: no gravity, at rest
}

TEST_CASE("turning contact: a cube landing flat touches with its four bottom corners",
          "[physics][turning]") {
    // Axis-aligned, falling from rest with its centre at 2 m: its bottom face (0.5 below the
    // centre) lands at sqrt(2 (2 - 0.5) / g), all four corners at once. The plane is given with
    // a normal of length 2 (2 y = 0): the same plane.
    const TestMesh cube = box(glm::dvec3(0.5));
    TurningPath path;
    path.c0 = {0.0, 2.0, 0.0};
    path.a = {0.0, -kG, 0.0};
    const double truth = std::sqrt(2.0 * 1.5 / kG);
    const TurningContact hit =
        turning_plane_contact(cube.mesh(), path, {{0.0, 2.0, 0.0}, 0.0}, 0.0, 5.0);
    REQUIRE(hit.found());
    CHECK(not_past(hit.t, truth));
    CHECK(truth - hit.t <= 1e-12);
    CHECK(hit.normal == glm::dvec3(0.0, 1.0, 0.0));
    REQUIRE(hit.points.size() == 4);
    for (const glm::dvec3 &p : hit.points) {
        CHECK(std::abs(p.y) < 1e-12);
        CHECK(std::abs(std::abs(p.x) - 0.5) < 1e-12);
        CHECK(std::abs(std::abs(p.z) - 0.5) < 1e-12);
    }
}

TEST_CASE("turning contact: a non-convex U comes down over a post, spinning, and meets it with "
          "its crossbar",
          "[physics][turning]") {
    // The U is three boxes' surfaces: prongs at x = +-0.5 (half-extents 0.1, 0.5, 0.2) and a
    // crossbar above them at y = 0.6 (0.6, 0.1, 0.2), its underside 0.5 above the centre. It falls
    // from rest at 3 m, spinning about the vertical at 2 rad/s, over a post of half-width 0.05
    // whose top is at 1 m: the prongs (at least 0.4 from the axis) circle clear of the post
    // (within 0.071 of it), so the crossbar's underside meets the post's top when the centre is
    // at 0.5: at sqrt(2 (3 - 0.5) / g). The U's convex hull would meet it 1 m of fall earlier.
    TestMesh u;
    for (const auto &[centre, half] :
         {std::pair{glm::dvec3(-0.5, 0.0, 0.0), glm::dvec3(0.1, 0.5, 0.2)},
          std::pair{glm::dvec3(0.5, 0.0, 0.0), glm::dvec3(0.1, 0.5, 0.2)},
          std::pair{glm::dvec3(0.0, 0.6, 0.0), glm::dvec3(0.6, 0.1, 0.2)}}) {
        const TestMesh part = box(half);
        const auto base = static_cast<uint32_t>(u.vertices.size());
        for (const glm::dvec3 &v : part.vertices) u.vertices.push_back(centre + v);
        for (uint32_t i : part.triangles) u.triangles.push_back(base + i);
    }
    u.edges = edges_of(u.triangles.data(), u.triangles.size() / 3);
    TestMesh post = box({0.05, 1.0, 0.05});
    TurningPath path;
    path.c0 = {0.0, 3.0, 0.0};
    path.a = {0.0, -kG, 0.0};
    path.w = {0.0, 2.0, 0.0};
    const double truth = std::sqrt(2.0 * 2.5 / kG);
    const TurningContact hit =
        turning_mesh_contact(u.mesh(), path, post.mesh(), TurningPath{}, 0.0, 5.0);
    REQUIRE(hit.kind == TurningContact::kVertexFace);
    CHECK(not_past(hit.t, truth));
    CHECK(truth - hit.t <= 1e-12);
    CHECK(glm::length(hit.normal - glm::dvec3(0.0, 1.0, 0.0)) < 1e-9);
    CHECK(std::abs(hit.point.y - 1.0) < 1e-9);
    // The post's four top corners, and where its top edges cross the crossbar's triangles'
    // edges: all on the post's top.
    CHECK(hit.points.size() >= 4);
    for (const glm::dvec3 &p : hit.points) {
        CHECK(std::abs(p.y - 1.0) < 1e-9);
        CHECK(std::max(std::abs(p.x), std::abs(p.z)) <= 0.05 + 1e-9);
    }
    std::size_t lazy = 0, plain = 0;
    against_plain(hit, u.mesh(), path, post.mesh(), TurningPath{}, 0.0, 5.0, lazy, plain);
    CHECK(lazy <= plain);
}

TEST_CASE("turning contact: random pairs of turning cubes agree with a second engine",
          "[physics][turning]") {
    // The truth is mesh_distance.cpp's surfaces_cross (an edge through a face), run on poses
    // placed here by Rodrigues' formula: sampled every 1e-4 s for the first crossing, then
    // bisected to rounding between the last sample apart and the first crossing.
    const TestMesh cube = box(glm::dvec3(0.5));
    std::mt19937 random(1818);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    auto random_axis = [&] {
        glm::dvec3 k;
        do k = {unit(random), unit(random), unit(random)};
        while (glm::length(k) > 1.0 || glm::length(k) < 0.1);
        return glm::normalize(k);
    };
    std::size_t lazy = 0, plain = 0;
    for (int k = 0; k < 12; ++k) {
        struct Body {
            glm::dvec3 c0, v, axis;
            double angle0, omega;
        };
        Body bodies[2];
        for (int i = 0; i < 2; ++i) {
            const double side = i == 0 ? -1.0 : 1.0;
            bodies[i] = {{2.0 * side, 0.3 * unit(random), 0.3 * unit(random)},
                         {-side * (1.0 + unit(random) * 0.5), 0.2 * unit(random), 0.0},
                         random_axis(),
                         3.0 * unit(random),
                         5.0 * (unit(random) + 1.0)};
        }
        auto posed = [&](const Body &b, double t) {
            std::vector<glm::dvec3> out;
            for (const glm::dvec3 &p : cube.vertices)
                out.push_back(b.c0 + b.v * t + rodrigues(p, b.axis, b.angle0 + b.omega * t));
            return out;
        };
        auto crossing = [&](double t) {
            PlacedMesh pa, pb;
            pa.vertices = posed(bodies[0], t);
            pb.vertices = posed(bodies[1], t);
            for (PlacedMesh *m : {&pa, &pb}) {
                m->triangles = cube.triangles.data();
                m->triangle_count = 12;
                m->edges = cube.edges.data();
                m->edge_count = cube.edges.size();
            }
            return surfaces_cross(pa, pb, 0.0);
        };
        double lo = 0.0, hi = -1.0;
        for (double t = 1e-4; t <= 3.0; t += 1e-4) {
            if (crossing(t)) {
                hi = t;
                break;
            }
            lo = t;
        }
        REQUIRE(hi > 0.0);
        for (int n = 0; n < 200 && std::nextafter(lo, 1e300) < hi; ++n) {
            const double mid = 0.5 * (lo + hi);
            (crossing(mid) ? hi : lo) = mid;
        }
        const double truth = lo;
        TurningPath path[2];
        for (int i = 0; i < 2; ++i) {
            path[i].c0 = bodies[i].c0;
            path[i].v = bodies[i].v;
            path[i].q0 = glm::angleAxis(bodies[i].angle0, bodies[i].axis);
            path[i].w = bodies[i].omega * bodies[i].axis;
        }
        const TurningContact hit =
            turning_mesh_contact(cube.mesh(), path[0], cube.mesh(), path[1], 0.0, 3.0);
        INFO("case " << k << " truth " << truth << " t " << hit.t);
        REQUIRE(hit.found());
        CHECK(not_past(hit.t, truth));
        CHECK(truth - hit.t <= 1e-12);
        // From b towards a: a approaches from the -x side.
        CHECK(hit.normal.x < 0.0);
        against_plain(hit, cube.mesh(), path[0], cube.mesh(), path[1], 0.0, 3.0, lazy, plain);
    }
    CHECK(lazy <= plain);
}
