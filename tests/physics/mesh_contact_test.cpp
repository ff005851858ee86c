// Mesh-mesh time of impact (seed, "Collision Detection": vertex-face, face-vertex and the edge
// tests between two models) against closed forms, and the hierarchy against the brute-force
// oracle on random queries.
#include "mesh_contact.hpp"
#include "response.hpp"
#include "test_meshes.hpp"

#include <catch2/catch.hpp>
#include <glm/geometric.hpp>

#include <cmath>
#include <map>
#include <random>
#include <sstream>

using namespace physics_custom;

namespace {

const double G = 9.81;
const glm::dvec3 gravity(0.0, -G, 0.0);
const double pi = 3.14159265358979323846;

using namespace test_meshes;

glm::dvec3 rotate_x(const glm::dvec3 &v, double angle) {
    const double c = std::cos(angle), s = std::sin(angle);
    return {v.x, c * v.y - s * v.z, s * v.y + c * v.z};
}
glm::dvec3 rotate_z(const glm::dvec3 &v, double angle) {
    const double c = std::cos(angle), s = std::sin(angle);
    return {c * v.x - s * v.y, s * v.x + c * v.y, v.z};
}

// A cube of side 2 h around the origin; vertex i has x > 0 when bit 0 is set, y bit 1, z bit 2.
// Each face is split along the diagonal from its first listed corner.
MeshShape cube(double h = 1.0, double angle_x = 0.0, double angle_z = 0.0) {
    Vertices v;
    for (int i = 0; i < 8; ++i) {
        const glm::dvec3 p((i & 1) ? h : -h, (i & 2) ? h : -h, (i & 4) ? h : -h);
        v.push_back(rotate_x(rotate_z(p, angle_z), angle_x));
    }
    const uint32_t quads[6][4] = {{0, 2, 6, 4}, {1, 5, 7, 3}, {0, 4, 5, 1},
                                  {2, 3, 7, 6}, {0, 1, 3, 2}, {4, 6, 7, 5}};
    Triangles t;
    for (const auto &q : quads) {
        t.push_back({q[0], q[1], q[2]});
        t.push_back({q[0], q[2], q[3]});
    }
    return MeshShape::build(v, facing_out(v, t));
}

// A box of half sizes h around the origin, axis-aligned.
MeshShape box_of(const glm::dvec3 &h) {
    const MeshShape unit = cube();
    Vertices v = unit.vertices;
    for (auto &p : v) p *= h;
    return MeshShape::build(v, unit.triangles);
}

// A UV sphere: poles on Y, `stacks` bands of `slices` quads (triangles at the poles).
Vertices uv_sphere_vertices(int stacks, int slices, double r) {
    Vertices v = {{0, r, 0}};
    for (int i = 1; i < stacks; ++i)
        for (int j = 0; j < slices; ++j) {
            const double theta = pi * i / stacks, phi = 2.0 * pi * j / slices;
            v.emplace_back(r * std::sin(theta) * std::cos(phi), r * std::cos(theta),
                           r * std::sin(theta) * std::sin(phi));
        }
    v.emplace_back(0, -r, 0);
    return v;
}
Triangles uv_sphere_triangles(int stacks, int slices) {
    Triangles t;
    const auto ring = [&](int i, int j) {
        return static_cast<uint32_t>(1 + (i - 1) * slices + (j % slices));
    };
    const auto bottom = static_cast<uint32_t>(1 + (stacks - 1) * slices);
    for (int j = 0; j < slices; ++j) {
        t.push_back({0, ring(1, j), ring(1, j + 1)});
        for (int i = 1; i + 1 < stacks; ++i) {
            t.push_back({ring(i, j), ring(i + 1, j), ring(i + 1, j + 1)});
            t.push_back({ring(i, j), ring(i + 1, j + 1), ring(i, j + 1)});
        }
        t.push_back({bottom, ring(stacks - 1, j + 1), ring(stacks - 1, j)});
    }
    return t;
}

// An icosahedron's faces subdivided `level` times, on the sphere of radius r.
MeshShape icosphere(int level, double r) {
    auto [v, t] = subdivided_icosahedron(level);
    for (auto &x : v) x *= r;
    return MeshShape::build(v, facing_out(v, t));
}

// A square pyramid pointing up: base of side 1 in the plane y = 0, apex at `apex`.
MeshShape pyramid(const glm::dvec3 &apex) {
    const Vertices v = {{-0.5, 0, -0.5}, {0.5, 0, -0.5}, {0.5, 0, 0.5}, {-0.5, 0, 0.5}, apex};
    const Triangles t = {{0, 1, 2}, {0, 2, 3}, {0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}};
    return MeshShape::build(v, facing_out(v, t, glm::dvec3(0.0, apex.y / 4.0, 0.0)));
}

Path at_rest(const glm::dvec3 &p) {
    return Path{p, glm::dvec3(0.0), glm::dvec3(0.0)};
}
Path falling_from(const glm::dvec3 &p) {
    return Path{p, glm::dvec3(0.0), gravity};
}

// Both versions, which must agree to the bit; returns the hierarchy's answer.
std::optional<Contact> contact(const MeshShape &a, const Path &pa, const MeshShape &b,
                               const Path &pb, double t_max) {
    const auto fast = mesh_mesh(a, pa, b, pb, t_max);
    const auto brute = mesh_mesh_brute(a, pa, b, pb, t_max);
    REQUIRE(fast.has_value() == brute.has_value());
    if (fast) {
        CHECK(fast->t == brute->t);
        CHECK(fast->normal == brute->normal);
        CHECK(fast->point == brute->point);
    }
    return fast;
}

// "none", or the contact's time, normal and point: what a failed expectation of none shows.
std::string describe(const std::optional<Contact> &c) {
    if (!c) return "none";
    std::ostringstream out;
    out.precision(17);
    out << "t " << c->t << " normal " << c->normal.x << " " << c->normal.y << " " << c->normal.z
        << " point " << c->point.x << " " << c->point.y << " " << c->point.z;
    return out.str();
}

void check_normal(const glm::dvec3 &n, const glm::dvec3 &expected) {
    CAPTURE(n.x, n.y, n.z);
    CHECK(glm::length(n - expected) < 1e-12);
}

// The distance from p to the nearest triangle of `mesh` placed at `offset`.
double distance_to(const MeshShape &mesh, const glm::dvec3 &offset, const glm::dvec3 &p) {
    double best = std::numeric_limits<double>::infinity();
    for (const auto &t : mesh.triangles) {
        const glm::dvec3 q =
            closest_point_on_triangle(p, offset + mesh.vertices[t[0]], offset + mesh.vertices[t[1]],
                                      offset + mesh.vertices[t[2]]);
        best = std::min(best, glm::length(p - q));
    }
    return best;
}

// Whether the meshes at `oa` and `ob` cross: an edge of one through a triangle of the other (the
// seed's ray-triangle test), looking only where their boxes overlap.
bool overlapping(const MeshShape &a, const glm::dvec3 &oa, const MeshShape &b,
                 const glm::dvec3 &ob) {
    const Box ba{a.bounds().lo + oa, a.bounds().hi + oa},
        bb{b.bounds().lo + ob, b.bounds().hi + ob};
    if (!ba.overlaps(bb)) return false;
    const Box common{glm::max(ba.lo, bb.lo), glm::min(ba.hi, bb.hi)};
    auto edges_through = [&](const MeshShape &m, const glm::dvec3 &om, const MeshShape &n,
                             const glm::dvec3 &on) {
        std::vector<uint32_t> near;
        for (uint32_t t = 0; t < n.triangles.size(); ++t)
            if (Box{n.triangle_boxes[t].lo + on, n.triangle_boxes[t].hi + on}.overlaps(common))
                near.push_back(t);
        for (uint32_t e = 0; e < m.edges.size(); ++e) {
            const Box box{m.edge_boxes[e].lo + om, m.edge_boxes[e].hi + om};
            if (!box.overlaps(common)) continue;
            const glm::dvec3 p = om + m.vertices[m.edges[e][0]], q = om + m.vertices[m.edges[e][1]];
            for (uint32_t t : near) {
                const auto &tri = n.triangles[t];
                if (box.overlaps(Box{n.triangle_boxes[t].lo + on, n.triangle_boxes[t].hi + on}) &&
                    ray_triangle(p, q - p, on + n.vertices[tri[0]], on + n.vertices[tri[1]],
                                 on + n.vertices[tri[2]]))
                    return true;
            }
        }
        return false;
    };
    return edges_through(a, oa, b, ob) || edges_through(b, ob, a, oa);
}

} // namespace

TEST_CASE("a mesh shape derives its edges, sidedness and a hierarchy holding each feature once") {
    for (const MeshShape &m :
         {cube(), floor_square(3.0, 7), icosphere(3, 1.0), pyramid({0.1, 0.7, 0.2})}) {
        // Euler: a closed mesh of genus 0 has V - E + F = 2.
        if (m.closed)
            CHECK(long(m.vertices.size()) - long(m.edges.size()) + long(m.triangles.size()) == 2);
        std::vector<int> triangles(m.triangles.size()), vertices(m.vertices.size()),
            edges(m.edges.size());
        for (uint32_t t : m.order) ++triangles[t];
        for (uint32_t v : m.owned_vertices) ++vertices[v];
        for (uint32_t e : m.owned_edges) ++edges[e];
        CHECK(std::count(triangles.begin(), triangles.end(), 1) ==
              static_cast<long>(triangles.size()));
        CHECK(std::count(vertices.begin(), vertices.end(), 1) ==
              static_cast<long>(vertices.size()));
        CHECK(std::count(edges.begin(), edges.end(), 1) == static_cast<long>(edges.size()));
        for (const auto &node : m.nodes)
            if (node.leaf()) CHECK(node.count <= 4);
    }
    CHECK(cube().closed);
    CHECK(cube().edges.size() == 18);
    CHECK_FALSE(floor_square(10.0).closed);
    CHECK(floor_square(10.0).edges.size() == 5);
    CHECK(icosphere(4, 1.0).triangles.size() == 5120);
    CHECK_THROWS_AS(MeshShape::build({{0, 0, 0}}, {{0, 1, 2}}), std::invalid_argument);
}

TEST_CASE("a cube falling face-down on a floor lands at t = sqrt(2 (h - 1) / G)") {
    for (const MeshShape &floor : {floor_square(10.0), floor_square(10.0, 15)}) {
        for (double h : {1.5, 3.0, 10.0, 1000.0}) {
            CAPTURE(h, floor.triangles.size());
            const auto c =
                contact(cube(), falling_from({0.3, h, -0.7}), floor, at_rest({0, 0, 0}), 100.0);
            REQUIRE(c);
            CHECK(c->t == Approx(std::sqrt(2.0 * (h - 1.0) / G)).epsilon(1e-12));
            check_normal(c->normal, {0, 1, 0});
            CHECK(c->point.y == Approx(0.0).margin(1e-12));
        }
    }
    // Both falling: gravity cancels, and the floor's own motion is what is relative.
    const auto both = contact(cube(), {{0, 5, 0}, {0, -2, 0}, gravity}, floor_square(10.0),
                              {{0, 0, 0}, {0, 0, 0}, gravity}, 100.0);
    REQUIRE(both);
    CHECK(both->t == Approx(2.0).epsilon(1e-14));
    CHECK(both->point.y == Approx(-0.5 * G * 4.0).epsilon(1e-12)); // where the floor is by then
}

TEST_CASE("a cube falling corner-down touches the floor with that corner") {
    // 45 degrees about Z, then atan(1 / sqrt 2) about X: the corner (-1, -1, 1) points straight
    // down, sqrt(3) below the center.
    const MeshShape corner_down = cube(1.0, std::atan(1.0 / std::sqrt(2.0)), pi / 4.0);
    const glm::dvec3 lowest = corner_down.vertices[4];
    CHECK(lowest.x == Approx(0.0).margin(1e-15));
    CHECK(lowest.y == Approx(-std::sqrt(3.0)).epsilon(1e-15));
    CHECK(lowest.z == Approx(0.0).margin(1e-15));
    for (double h : {2.0, 5.0, 100.0}) {
        CAPTURE(h);
        const auto c = contact(corner_down, falling_from({3, h, -2}), floor_square(10.0),
                               at_rest({0, 0, 0}), 100.0);
        REQUIRE(c);
        CHECK(c->t == Approx(std::sqrt(2.0 * (h - std::sqrt(3.0)) / G)).epsilon(1e-12));
        check_normal(c->normal, {0, 1, 0});
        CHECK(glm::length(c->point - glm::dvec3(3, 0, -2)) < 1e-12);
    }
}

TEST_CASE("a pyramid's apex hits a cube's bottom face: face-vertex, normal from B towards A") {
    const glm::dvec3 apex(0.3, 0.5, 0.1); // not on the bottom face's diagonal (x = z)
    const MeshShape spike = pyramid(apex);
    const double h = 4.0, t = std::sqrt(2.0 * (h - 1.5) / G);
    const auto c = contact(cube(), falling_from({0, h, 0}), spike, at_rest({0, 0, 0}), 10.0);
    REQUIRE(c);
    CHECK(c->t == Approx(t).epsilon(1e-12));
    check_normal(c->normal, {0, 1, 0});
    CHECK(glm::length(c->point - apex) < 1e-12);
    // The same with the roles swapped: now a vertex of A on a face of B, the normal reversed.
    const auto swapped = contact(spike, at_rest({0, 0, 0}), cube(), falling_from({0, h, 0}), 10.0);
    REQUIRE(swapped);
    CHECK(swapped->t == c->t);
    check_normal(swapped->normal, {0, -1, 0});
}

TEST_CASE("two cubes on crossed edges meet when the gap between the edges closes") {
    // A turned 45 degrees about X: its lowest edge runs along X, sqrt(2) below its center. B
    // turned about Z: its highest edge runs along Z, sqrt(2) above its center.
    const MeshShape a = cube(1.0, pi / 4.0, 0.0), b = cube(1.0, 0.0, pi / 4.0);
    const double s2 = std::sqrt(2.0);
    const auto c = contact(a, {{0.3, 5, -0.4}, {0, -2, 0}, {0, 0, 0}}, b, at_rest({0, 0, 0}), 10.0);
    REQUIRE(c);
    CHECK(c->t == Approx((5.0 - 2.0 * s2) / 2.0).epsilon(1e-14));
    check_normal(c->normal, {0, 1, 0});
    CHECK(glm::length(c->point - glm::dvec3(0, s2, -0.4)) < 1e-12);
    // Both moving, A under gravity: 5 - 2 t - G t^2 / 2 = 2 sqrt 2 + t (B rises at 1).
    const auto moving = contact(a, {{0.3, 5, -0.4}, {0, -2, 0}, gravity}, b,
                                {{0, 0, 0}, {0, 1, 0}, {0, 0, 0}}, 10.0);
    REQUIRE(moving);
    const double gap = 5.0 - 2.0 * s2, t = (-3.0 + std::sqrt(9.0 + 2.0 * G * gap)) / G;
    CHECK(moving->t == Approx(t).epsilon(1e-13));
    check_normal(moving->normal, {0, 1, 0});
    // B above A: the normal (from B towards A) points down.
    const auto below =
        contact(b, at_rest({0, 0, 0}), a, {{0.3, 5, -0.4}, {0, -2, 0}, {0, 0, 0}}, 10.0);
    REQUIRE(below);
    CHECK(below->t == c->t);
    check_normal(below->normal, {0, -1, 0});
}

TEST_CASE("touching and separating, passing by and sliding are no contact") {
    const MeshShape box = cube(), floor = floor_square(10.0), tiled = floor_square(10.0, 15);
    // Resting on the floor and leaving it: nothing at 0; thrown up, it comes back at 2 v / G.
    CHECK(describe(contact(box, {{2, 1, -3}, {0, 1, 0}, {0, 0, 0}}, floor, at_rest({0, 0, 0}),
                           10.0)) == "none");
    const auto back =
        contact(box, {{2, 1, -3}, {0, 1, 0}, gravity}, floor, at_rest({0, 0, 0}), 10.0);
    REQUIRE(back);
    CHECK(back->t == Approx(2.0 / G).epsilon(1e-12));
    check_normal(back->normal, {0, 1, 0});
    // Touching and approaching: a contact at 0. Resting and pressed by gravity counts as well.
    const auto pushed =
        contact(box, {{2, 1, -3}, {0, -1, 0}, {0, 0, 0}}, floor, at_rest({0, 0, 0}), 10.0);
    REQUIRE(pushed);
    CHECK(pushed->t == 0.0);
    const auto resting = contact(box, falling_from({2, 1, -3}), tiled, at_rest({0, 0, 0}), 10.0);
    REQUIRE(resting);
    CHECK(resting->t == 0.0);
    check_normal(resting->normal, {0, 1, 0});

    // Sliding across the floors, over their internal edges (the diagonal x = z of the square,
    // the grid of the tiled one) and off the square's rim, with and without acceleration along
    // the floor: the edges crossed are not hit.
    for (const MeshShape *f : {&floor, &tiled}) {
        CHECK(describe(contact(box, {{-5, 1, 3}, {4, 0, -2}, {0, 0, 0}}, *f, at_rest({0, 0, 0}),
                               5.0)) == "none");
        CHECK(describe(contact(box, {{-5, 1, 3}, {1, 0, -1}, {2, 0, 0.5}}, *f, at_rest({0, 0, 0}),
                               5.0)) == "none");
        CHECK(describe(contact(box, {{8, 1, 8}, {3, 0, 1}, {0, 0, 0}}, *f, at_rest({0, 0, 0}),
                               5.0)) == "none");
        // The floor sliding under a cube at rest on it.
        CHECK(describe(contact(box, at_rest({0, 1, 0}), *f, {{0, 0, 0}, {-1, 0, 2}, {0, 0, 0}},
                               5.0)) == "none");
    }
    // A cube sliding on another cube's top face and off its edge.
    CHECK(describe(contact(box, {{0.5, 2, 0.2}, {3, 0, 1}, {0, 0, 0}}, box, at_rest({0, 0, 0}),
                           5.0)) == "none");
    CHECK(describe(contact(box, {{0.5, 2, 0.2}, {-3, 0, 0}, {0, 0, 0}}, box, at_rest({0, 0, 0}),
                           5.0)) == "none");
    // Sliding onto a box (or a floor tile) of the same height, square to it or not: its top edge
    // is met head on, but the two tops share a plane and the box slides on over it. A little
    // lower, it hits the side.
    const MeshShape turned = MeshShape::build(
        [] {
            Vertices v = cube().vertices;
            for (auto &p : v)
                p = glm::dvec3(std::cos(0.3) * p.x + std::sin(0.3) * p.z, p.y,
                               std::cos(0.3) * p.z - std::sin(0.3) * p.x);
            return v;
        }(),
        cube().triangles);
    for (const MeshShape *slider : {&box, &turned}) {
        CHECK(describe(contact(*slider, {{-4, 2, 0.3}, {2, 0, 0.1}, {0, 0, 0}}, box,
                               at_rest({0, 0, 0}), 5.0)) == "none");
        CHECK(describe(contact(*slider, {{-12, 1, 0.3}, {2, 0, 0.5}, {0, 0, 0}}, floor,
                               at_rest({0, 0, 0}), 5.0)) == "none");
        const auto side =
            contact(*slider, {{-4, 1.9, 0.3}, {2, 0, 0}, {0, 0, 0}}, box, at_rest({0, 0, 0}), 5.0);
        REQUIRE(side);
        check_normal(side->normal, {-1, 0, 0});
    }
    // A closed mesh turned inside out is a room: a box inside meets its walls from within, and
    // one outside passes through them.
    const MeshShape unit = cube(5.0);
    Triangles inward = unit.triangles;
    for (auto &t : inward) std::swap(t[1], t[2]);
    const MeshShape room = MeshShape::build(unit.vertices, inward);
    const auto wall = contact(box, {{0, 0, 0}, {2, 0, 0}, gravity}, room, at_rest({0, 0, 0}), 5.0);
    REQUIRE(wall);
    CHECK(wall->t == Approx(std::sqrt(2.0 * 4.0 / G)).epsilon(1e-12)); // the floor, 4 below
    check_normal(wall->normal, {0, 1, 0});
    CHECK(describe(contact(box, {{-8, 0, 0}, {2, 0, 0}, {0, 0, 0}}, room, at_rest({0, 0, 0}),
                           2.0)) == "none");
    // The pyramid's apex touching the cube's bottom: leaving, or sliding along it.
    const MeshShape spike = pyramid({0.3, 0.5, 0.1});
    CHECK(describe(contact(box, {{0, 1.5, 0}, {0, 1, 0}, {0, 0, 0}}, spike, at_rest({0, 0, 0}),
                           5.0)) == "none");
    CHECK(describe(contact(box, {{0, 1.5, 0}, {0.1, 0, 0.05}, {0, 0, 0}}, spike, at_rest({0, 0, 0}),
                           5.0)) == "none");
    // The crossed edges touching: parting, or sliding along A's edge.
    const MeshShape a = cube(1.0, pi / 4.0, 0.0), b = cube(1.0, 0.0, pi / 4.0);
    const double top = 2.0 * std::sqrt(2.0);
    CHECK(describe(contact(a, {{0, top, 0}, {0, 1, 0}, {0, 0, 0}}, b, at_rest({0, 0, 0}), 5.0)) ==
          "none");
    CHECK(describe(contact(a, {{0, top, 0}, {0.2, 0, 0}, {0, 0, 0}}, b, at_rest({0, 0, 0}), 5.0)) ==
          "none");
    const auto crossed =
        contact(a, {{0, top, 0}, {0, -1, 0}, {0, 0, 0}}, b, at_rest({0, 0, 0}), 5.0);
    REQUIRE(crossed);
    CHECK(crossed->t == 0.0); // touching (up to the rounding of the edges' heights) and approaching

    // Passing by: beside the floor's rim, and two spheres that miss.
    CHECK(describe(contact(box, falling_from({11.5, 5, 0}), floor, at_rest({0, 0, 0}), 10.0)) ==
          "none");
    const MeshShape ball = icosphere(2, 1.0);
    CHECK(describe(contact(ball, {{-5, 2.1, 0}, {3, 0, 0}, {0, 0, 0}}, ball, at_rest({0, 0, 0}),
                           10.0)) == "none");
    // A negative or NaN horizon: nothing.
    CHECK_FALSE(mesh_mesh(box, falling_from({0, 2, 0}), floor, at_rest({0, 0, 0}), -1.0));
    CHECK_FALSE(mesh_mesh(box, falling_from({0, 2, 0}), floor, at_rest({0, 0, 0}), std::nan("")));
}

TEST_CASE("a cube bouncing on a floor sheet keeps its period despite rounding at each bounce") {
    // Turned about Y so that its corners' coordinates are rounded, and falling face-down from h:
    // it lands every 2 sqrt(2 (h - 1) / G) after the first landing.
    const MeshShape box = MeshShape::build(
        [] {
            Vertices v = cube().vertices;
            for (auto &p : v)
                p = glm::dvec3(std::cos(0.3) * p.x + std::sin(0.3) * p.z, p.y,
                               std::cos(0.3) * p.z - std::sin(0.3) * p.x);
            return v;
        }(),
        cube().triangles);
    const MeshShape floor = floor_square(10.0, 4);
    const double h = 3.0, fall = std::sqrt(2.0 * (h - 1.0) / G);
    Path path = falling_from({0.5, h, 0.2});
    double now = 0.0;
    for (int bounce = 0; bounce < 20; ++bounce) {
        CAPTURE(bounce);
        const auto c = contact(box, path, floor, at_rest({0, 0, 0}), 100.0);
        REQUIRE(c);
        now += c->t;
        CHECK(now == Approx(fall * (2 * bounce + 1)).epsilon(1e-12));
        check_normal(c->normal, {0, 1, 0});
        path = Path{path.at(c->t), reflect(path.velocity(c->t), c->normal), gravity};
    }
    // A rounding error below the sheet and leaving it upwards: not met again from below.
    CHECK(describe(contact(box, {{0, 1.0 - 1e-15, 0}, {0, 1, 0}, gravity}, floor,
                           at_rest({0, 0, 0}), 0.1)) == "none");
    // ... and still coming down: a contact at once.
    const auto late =
        contact(box, {{0, 1.0 - 1e-15, 0}, {0, -1, 0}, gravity}, floor, at_rest({0, 0, 0}), 0.1);
    REQUIRE(late);
    CHECK(late->t == 0.0);
    check_normal(late->normal, {0, 1, 0});
}

TEST_CASE("axis-aligned boxes meet when the box-box formula says, touching and grazing included") {
    // Boxes on a grid of quarters, moving at a few axis speeds: they start touching, slide along
    // each other, graze edges and corners. The truth: along each axis the centers' gap is below
    // the sum of the half sizes on an open interval of time; the boxes collide when the three
    // intervals share a moment, first at the start of the shared part (a mere touch is none).
    std::mt19937_64 rng(99);
    auto quarters = [&](int lo, int hi) {
        return std::uniform_int_distribution<int>(lo, hi)(rng) / 4.0;
    };
    const double speeds[] = {-2, -1, -0.5, 0, 0, 0.5, 1, 2}, t_max = 10.0;
    int hits = 0, touching = 0, grazing = 0;
    for (int i = 0; i < 5000; ++i) {
        const glm::dvec3 ha(quarters(1, 8), quarters(1, 8), quarters(1, 8)),
            hb(quarters(1, 8), quarters(1, 8), quarters(1, 8)), reach = ha + hb;
        const glm::dvec3 gap(quarters(-24, 24), quarters(-24, 24), quarters(-24, 24));
        const glm::dvec3 v(speeds[rng() % 8], speeds[rng() % 8], speeds[rng() % 8]);
        const glm::dvec3 shift(quarters(-8, 8), quarters(-8, 8), quarters(-8, 8));
        if (std::abs(gap.x) < reach.x && std::abs(gap.y) < reach.y && std::abs(gap.z) < reach.z)
            continue; // overlapping from the start
        double from = -std::numeric_limits<double>::infinity(), to = -from;
        bool apart = false; // along an axis without motion
        for (int k = 0; k < 3; ++k) {
            if (v[k] == 0.0) {
                apart = apart || !(std::abs(gap[k]) < reach[k]);
                continue;
            }
            const double t1 = (-reach[k] - gap[k]) / v[k], t2 = (reach[k] - gap[k]) / v[k];
            from = std::max(from, std::min(t1, t2));
            to = std::min(to, std::max(t1, t2));
        }
        const bool collides = !apart && from < to && from <= t_max && to > 0.0;
        touching +=
            std::abs(gap.x) == reach.x || std::abs(gap.y) == reach.y || std::abs(gap.z) == reach.z;
        grazing += !apart && from == to && from >= 0.0 && from <= t_max;
        CAPTURE(i, ha.x, ha.y, ha.z, hb.x, hb.y, hb.z, gap.x, gap.y, gap.z, v.x, v.y, v.z);
        const auto c =
            contact(box_of(ha), {shift + gap, v, {0, 0, 0}}, box_of(hb), at_rest(shift), t_max);
        REQUIRE(c.has_value() == collides);
        if (!c) continue;
        ++hits;
        CHECK(c->t == Approx(std::max(from, 0.0)).margin(1e-12 * t_max));
    }
    CAPTURE(hits, touching, grazing);
    CHECK(hits > 250);
    CHECK(touching > 400);
    CHECK(grazing > 20);
}

TEST_CASE("the hierarchy and the brute force agree on random queries") {
    std::mt19937_64 rng(20240611);
    std::uniform_real_distribution<double> unit(-1.0, 1.0), zero_one(0.0, 1.0);
    auto random_unit = [&] {
        for (;;) {
            const glm::dvec3 v(unit(rng), unit(rng), unit(rng));
            const double l = glm::length(v);
            if (l > 0.1 && l <= 1.0) return v / l;
        }
    };
    // A random rotation: a random axis and angle (Rodrigues).
    auto rotated = [&](Vertices v) {
        const glm::dvec3 k = random_unit();
        const double angle = pi * unit(rng), c = std::cos(angle), s = std::sin(angle);
        for (auto &p : v) p = p * c + glm::cross(k, p) * s + k * glm::dot(k, p) * (1.0 - c);
        return v;
    };
    const Triangles uv = uv_sphere_triangles(10, 11); // 198 triangles
    auto random_shape = [&](double &radius) {
        switch (rng() % 4) {
        case 0: {
            radius = 0.5 + zero_one(rng);
            const Vertices v = uv_sphere_vertices(10, 11, radius);
            return MeshShape::build(rotated(v), facing_out(v, uv));
        }
        case 1: {
            const MeshShape c = cube(0.3 + 0.7 * zero_one(rng));
            radius = std::sqrt(3.0) * c.vertices[7].x;
            return MeshShape::build(rotated(c.vertices), c.triangles);
        }
        case 2: { // a blob: the sphere's vertices moved in and out at random
            Vertices v = uv_sphere_vertices(10, 11, 1.0);
            for (auto &p : v) p *= 0.7 + 0.6 * zero_one(rng);
            radius = 1.3;
            return MeshShape::build(rotated(v), facing_out(v, uv));
        }
        default: { // a tiled square, 512 triangles: open
            const MeshShape f = floor_square(1.5, 16);
            radius = 1.5 * std::sqrt(2.0);
            return MeshShape::build(rotated(f.vertices), f.triangles);
        }
        }
    };

    int hits = 0;
    const int queries = 2000;
    for (int i = 0; i < queries; ++i) {
        double ra = 0.0, rb = 0.0;
        const MeshShape a = random_shape(ra), b = random_shape(rb);
        // B near the origin, A apart from it, mostly aimed at it.
        const glm::dvec3 pb = 0.3 * random_unit(),
                         pa = pb + (ra + rb + 0.5 * zero_one(rng)) * random_unit();
        const double t_max = 0.2 + 3.0 * zero_one(rng);
        const glm::dvec3 aim = (pb + 0.6 * (ra + rb) * zero_one(rng) * random_unit()) - pa;
        glm::dvec3 relative = aim / (0.3 + 2.0 * zero_one(rng));
        if (zero_one(rng) < 0.2) relative = 3.0 * random_unit();
        const double share = zero_one(rng);
        Path path_a{pa, share * relative, glm::dvec3(0.0)},
            path_b{pb, (share - 1.0) * relative, glm::dvec3(0.0)};
        if (zero_one(rng) < 0.5) path_a.a = gravity;
        if (zero_one(rng) < 0.3) path_b.a = 2.0 * glm::dvec3(unit(rng), unit(rng), unit(rng));
        CAPTURE(i, t_max);

        PairStats fast_stats, brute_stats;
        const auto fast = mesh_mesh(a, path_a, b, path_b, t_max, &fast_stats);
        const auto brute = mesh_mesh_brute(a, path_a, b, path_b, t_max, &brute_stats);
        REQUIRE(fast.has_value() == brute.has_value());
        CHECK(fast_stats.primitive_tests <= brute_stats.primitive_tests);
        // Independently of both: the meshes do not cross before the contact (or at all, without
        // one), looked at a few times, every fourth query.
        if (i % 4 == 0) {
            const double end = fast ? fast->t - 1e-9 * t_max : t_max;
            for (int k = 1; k <= 4 && end > 0.0; ++k) {
                const double t = end * k / 4.0;
                CAPTURE(t);
                CHECK_FALSE(overlapping(a, path_a.at(t), b, path_b.at(t)));
            }
        }
        if (!fast) continue;
        ++hits;
        CHECK(std::abs(fast->t - brute->t) <= 1e-12 * t_max);
        // Both pick among simultaneous contacts by the same rule, so the normals agree even
        // where several features touch at once.
        CHECK(glm::length(fast->normal - brute->normal) <= 1e-9);
        CHECK(glm::length(fast->point - brute->point) <= 1e-9);
        CHECK(std::abs(glm::length(fast->normal) - 1.0) < 1e-12);
    }
    CAPTURE(hits);
    CHECK(hits > queries * 3 / 10);
    CHECK(hits < queries * 9 / 10);
}

TEST_CASE("the hierarchy tests under 2% of the feature pairs of the brute force on big meshes") {
    const MeshShape a = icosphere(4, 1.0), b = icosphere(4, 1.5);
    REQUIRE(a.triangles.size() == 5120);
    const Path pa{{-4, 0.4, 0.3}, {2, 0, 0}, {0, 0, 0}}, pb = at_rest({0, 0, 0});
    PairStats fast_stats, brute_stats;
    const auto fast = mesh_mesh(a, pa, b, pb, 3.0, &fast_stats);
    const auto brute = mesh_mesh_brute(a, pa, b, pb, 3.0, &brute_stats);
    REQUIRE(fast);
    REQUIRE(brute);
    CHECK(fast->t == brute->t);
    CHECK(fast->normal == brute->normal);
    // Close to the spheres' answer: the gap of 2.5 between centers closes at 2, less a little
    // for the flat facets (inscribed polyhedra meet later, never earlier).
    const double sphere_t = (4.0 - std::sqrt(2.5 * 2.5 - 0.4 * 0.4 - 0.3 * 0.3)) / 2.0;
    CHECK(fast->t >= sphere_t);
    CHECK(fast->t < sphere_t + 0.01);
    CAPTURE(fast_stats.primitive_tests, fast_stats.nodes_visited, brute_stats.primitive_tests);
    CHECK(brute_stats.primitive_tests == 2562ull * 5120 * 2 + 7680ull * 7680);
    CHECK(fast_stats.primitive_tests * 50 < brute_stats.primitive_tests);
}

TEST_CASE("spheres built as meshes touch at a point on both surfaces, and bounce apart") {
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    const MeshShape a = icosphere(3, 1.0), b = icosphere(2, 0.7);
    int contacts = 0;
    for (int i = 0; i < 200; ++i) {
        CAPTURE(i);
        // Oblique approaches aimed within the spheres' reach, one of them falling.
        const Path pb{
            {unit(rng), unit(rng), unit(rng)}, {unit(rng), unit(rng), unit(rng)}, {0, 0, 0}};
        const glm::dvec3 start(-4, unit(rng), unit(rng)),
            aim = pb.at(1.0) + glm::dvec3(0, unit(rng), unit(rng));
        const Path pa{start, aim - start, i % 2 ? gravity : glm::dvec3(0.0)};
        const auto c = mesh_mesh(a, pa, b, pb, 3.0); // the brute force agrees: see above
        if (!c) continue;
        ++contacts;
        CHECK(distance_to(a, pa.at(c->t), c->point) <= 1e-9);
        CHECK(distance_to(b, pb.at(c->t), c->point) <= 1e-9);
        // Bounce: equal masses exchange their velocities along the normal. From the moment of
        // contact on, they separate: no contact at once, and no sticking.
        auto [va, vb] = elastic_exchange(1.0, pa.velocity(c->t), 1.0, pb.velocity(c->t), c->normal);
        const Path after_a{pa.at(c->t), va, pa.a}, after_b{pb.at(c->t), vb, pb.a};
        CHECK(glm::dot(va - vb, c->normal) > 0.0);
        const auto again = mesh_mesh(a, after_a, b, after_b, 3.0);
        if (again) CHECK(again->t > 0.0);
    }
    CHECK(contacts > 100);
}
