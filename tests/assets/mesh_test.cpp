// The generated meshes: counts, unit normals, watertightness, outward winding, volumes and
// extents, all checked against the geometry docs/assets.md states.
#include "asset_readers.hpp"

#include <catch2/catch.hpp>
#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <tuple>
#include <utility>

using namespace animator::test::assets;

namespace {

constexpr double kPi = glm::pi<double>();

struct MeshSpec {
    const char *name;
    std::size_t min_triangles, max_triangles;
    bool solid;          // closed; everything but the two floors
    glm::dvec3 min, max; // the documented bounding box
};

const std::vector<MeshSpec> &specs() {
    static const std::vector<MeshSpec> all = {
        {"sphere", 1800, 2200, true, {-1, -1, -1}, {1, 1, 1}},
        {"sphere_low", 80, 200, true, {-1, -1, -1}, {1, 1, 1}},
        {"sphere_high", 18000, 22000, true, {-1, -1, -1}, {1, 1, 1}},
        {"cube", 12, 12, true, {-1, -1, -1}, {1, 1, 1}},
        {"plane", 2, 2, false, {-1, 0, -1}, {1, 0, 1}},
        {"floor_fine", 8192, 8192, false, {-1, 0, -1}, {1, 0, 1}},
        {"cylinder", 4 * 32, 4 * 32, true, {-1, -1, -1}, {1, 1, 1}}, // side 2 x 32, caps 2 x 32
        {"cone", 2 * 32, 2 * 32, true, {-1, -1, -1}, {1, 1, 1}},
        {"torus", 2 * 48 * 24, 2 * 48 * 24, true, {-1.3, -0.3, -1.3}, {1.3, 0.3, 1.3}},
        {"stairs", 44, 44, true, {0, 0, -1}, {5, 2.5, 1}},
    };
    return all;
}

ObjMesh load(const std::string &name) {
    return read_obj(generated_dir() / "meshes" / (name + ".obj"));
}

glm::dvec3 face_normal(const ObjMesh &m, const std::array<ObjCorner, 3> &t) {
    const glm::dvec3 &a = m.positions[t[0].v], &b = m.positions[t[1].v], &c = m.positions[t[2].v];
    return glm::cross(b - a, c - a); // length = twice the area
}

// Divergence theorem: the sum of signed tetrahedra from the origin. Positive when the triangles
// wind counter-clockwise seen from outside.
double signed_volume(const ObjMesh &m) {
    double volume = 0.0;
    for (const auto &t : m.triangles)
        volume +=
            glm::dot(m.positions[t[0].v], glm::cross(m.positions[t[1].v], m.positions[t[2].v])) /
            6.0;
    return volume;
}

// Regular n-gon of circumradius 1: the polygon the cylinder and cone are built on.
double ngon_area(int n) {
    return 0.5 * n * std::sin(2.0 * kPi / n);
}

} // namespace

TEST_CASE("every mesh parses as triangles with v/vt/vn corners and has the documented count") {
    for (const auto &spec : specs()) {
        INFO(spec.name);
        const ObjMesh m = load(spec.name);
        CHECK(m.triangles.size() >= spec.min_triangles);
        CHECK(m.triangles.size() <= spec.max_triangles);
    }
}

TEST_CASE("every mesh normal is unit length") {
    for (const auto &spec : specs()) {
        INFO(spec.name);
        const ObjMesh m = load(spec.name);
        REQUIRE(!m.normals.empty());
        double worst = 0.0;
        for (const auto &n : m.normals) worst = std::max(worst, std::fabs(glm::length(n) - 1.0));
        CHECK(worst <= 1e-6);
    }
}

TEST_CASE("no mesh has a degenerate triangle") {
    for (const auto &spec : specs()) {
        INFO(spec.name);
        const ObjMesh m = load(spec.name);
        double smallest = 1e300;
        for (const auto &t : m.triangles)
            smallest = std::min(smallest, 0.5 * glm::length(face_normal(m, t)));
        CHECK(smallest > 1e-12);
    }
}

TEST_CASE("each corner normal points to the same side as its triangle's winding") {
    for (const auto &spec : specs()) {
        INFO(spec.name);
        const ObjMesh m = load(spec.name);
        int disagreeing = 0;
        for (const auto &t : m.triangles) {
            const glm::dvec3 n = glm::normalize(face_normal(m, t));
            for (const auto &c : t)
                if (glm::dot(n, m.normals[c.vn]) <= 0.0) ++disagreeing;
        }
        CHECK(disagreeing == 0);
    }
}

TEST_CASE("the solid meshes are closed: each position edge is in exactly two triangles") {
    for (const auto &spec : specs()) {
        if (!spec.solid) continue;
        INFO(spec.name);
        const ObjMesh m = load(spec.name);
        // Directed edges: in a closed, consistently wound mesh each appears once and its reverse
        // once, so each undirected edge is shared by exactly two triangles.
        std::map<std::pair<int, int>, int> directed;
        for (const auto &t : m.triangles)
            for (int k = 0; k < 3; ++k) ++directed[{t[k].v, t[(k + 1) % 3].v}];
        int repeated = 0, unmatched = 0;
        for (const auto &[edge, count] : directed) {
            if (count != 1) ++repeated;
            const auto reverse = directed.find({edge.second, edge.first});
            if (reverse == directed.end() || reverse->second != 1) ++unmatched;
        }
        CHECK(repeated == 0);
        CHECK(unmatched == 0);
        // And no position is unused or duplicated (which would hide an open seam).
        std::vector<int> used(m.positions.size(), 0);
        for (const auto &t : m.triangles)
            for (const auto &c : t) used[static_cast<std::size_t>(c.v)] = 1;
        CHECK(std::count(used.begin(), used.end(), 0) == 0);
        auto sorted = m.positions;
        std::sort(sorted.begin(), sorted.end(), [](const glm::dvec3 &a, const glm::dvec3 &b) {
            return std::tie(a.x, a.y, a.z) < std::tie(b.x, b.y, b.z);
        });
        CHECK(std::adjacent_find(sorted.begin(), sorted.end()) == sorted.end());
    }
}

TEST_CASE("the solid meshes wind outward: their signed volume is positive") {
    for (const auto &spec : specs()) {
        if (!spec.solid) continue;
        INFO(spec.name);
        CHECK(signed_volume(load(spec.name)) > 0.0);
    }
}

TEST_CASE("sphere volumes approach 4/3 pi") {
    const double ball = 4.0 / 3.0 * kPi;
    CHECK(signed_volume(load("sphere")) == Approx(ball).epsilon(0.02));
    CHECK(signed_volume(load("sphere_high")) == Approx(ball).epsilon(0.02));
    CHECK(signed_volume(load("sphere_low")) == Approx(ball).epsilon(0.25));
}

TEST_CASE("sphere positions lie at radius 1 and each pole of the UV spheres is one position") {
    for (const char *name : {"sphere", "sphere_low", "sphere_high"}) {
        INFO(name);
        const ObjMesh m = load(name);
        double worst = 0.0;
        for (const auto &p : m.positions) worst = std::max(worst, std::fabs(glm::length(p) - 1.0));
        CHECK(worst <= 1e-6);
    }
    for (const char *name : {"sphere", "sphere_high"}) {
        INFO(name);
        const ObjMesh m = load(name);
        for (double y : {1.0, -1.0}) {
            const auto at_pole =
                std::count_if(m.positions.begin(), m.positions.end(), [y](const glm::dvec3 &p) {
                    return glm::length(p - glm::dvec3(0, y, 0)) < 1e-6;
                });
            CHECK(at_pole == 1);
        }
    }
}

TEST_CASE("cube and stairs volumes are exact, cylinder and cone match their polygons") {
    CHECK(std::fabs(signed_volume(load("cube")) - 8.0) <= 1e-9);
    // Five steps, each 1 deep, 2 wide and 0.5 k high (k = 1..5).
    double stairs = 0.0;
    for (int k = 1; k <= 5; ++k) stairs += 1.0 * 2.0 * 0.5 * k;
    CHECK(stairs == 15.0);
    CHECK(std::fabs(signed_volume(load("stairs")) - stairs) <= 1e-9);
    // Prism and pyramid over a 32-gon of circumradius 1, height 2 (coordinates are printed to 9
    // significant digits, hence the tolerance).
    CHECK(signed_volume(load("cylinder")) == Approx(ngon_area(32) * 2.0).epsilon(1e-6));
    CHECK(signed_volume(load("cone")) == Approx(ngon_area(32) * 2.0 / 3.0).epsilon(1e-6));
    // Pappus: 2 pi R * pi r^2; the 48 x 24 polygon loses about 1.5 %.
    CHECK(signed_volume(load("torus")) == Approx(2.0 * kPi * kPi * 1.0 * 0.3 * 0.3).epsilon(0.03));
}

TEST_CASE("meshes span their documented bounding boxes") {
    for (const auto &spec : specs()) {
        INFO(spec.name);
        const ObjMesh m = load(spec.name);
        glm::dvec3 lo(1e300), hi(-1e300);
        for (const auto &p : m.positions) {
            lo = glm::min(lo, p);
            hi = glm::max(hi, p);
        }
        for (int i = 0; i < 3; ++i) {
            INFO("axis " << i);
            CHECK(lo[i] == Approx(spec.min[i]).margin(1e-6));
            CHECK(hi[i] == Approx(spec.max[i]).margin(1e-6));
        }
    }
}

TEST_CASE("the cube has six flat faces with one axis normal each") {
    const ObjMesh m = load("cube");
    std::map<std::tuple<double, double, double>, int> per_normal;
    for (const auto &t : m.triangles) {
        const glm::dvec3 n = m.normals[t[0].vn];
        CHECK(m.normals[t[1].vn] == n);
        CHECK(m.normals[t[2].vn] == n);
        CHECK(glm::length(glm::normalize(face_normal(m, t)) - n) < 1e-12);
        ++per_normal[{n.x, n.y, n.z}];
        for (const auto &c : t) {
            CHECK(m.uvs[c.vt].x >= 0.0);
            CHECK(m.uvs[c.vt].x <= 1.0);
            CHECK(m.uvs[c.vt].y >= 0.0);
            CHECK(m.uvs[c.vt].y <= 1.0);
        }
    }
    CHECK(per_normal.size() == 6);
    for (const auto &entry : per_normal) CHECK(entry.second == 2);
}

TEST_CASE("plane and floor_fine lie at y = 0 and face +Y") {
    for (const char *name : {"plane", "floor_fine"}) {
        INFO(name);
        const ObjMesh m = load(name);
        for (const auto &p : m.positions) CHECK(p.y == 0.0);
        int wrong_normals = 0, downward = 0;
        for (const auto &t : m.triangles) {
            for (const auto &c : t)
                if (m.normals[c.vn] != glm::dvec3(0, 1, 0)) ++wrong_normals;
            if (face_normal(m, t).y <= 0.0) ++downward;
        }
        CHECK(wrong_normals == 0);
        CHECK(downward == 0);
        // The floor's area is the full 2 x 2 square, with no overlaps or holes.
        double area = 0.0;
        for (const auto &t : m.triangles) area += 0.5 * face_normal(m, t).y;
        CHECK(area == Approx(4.0).epsilon(1e-12));
    }
}

TEST_CASE("the stairs are five 1-deep, 0.5-high steps descending along +X") {
    const ObjMesh m = load("stairs");
    // Every upward-facing triangle is a tread at the height of its step.
    double tread_area = 0.0;
    for (const auto &t : m.triangles) {
        const glm::dvec3 n = face_normal(m, t);
        if (n.y <= 0.0 || std::fabs(n.x) > 1e-12 || std::fabs(n.z) > 1e-12) continue;
        tread_area += 0.5 * n.y;
        for (const auto &c : t) {
            const glm::dvec3 &p = m.positions[c.v];
            const double x =
                (m.positions[t[0].v].x + m.positions[t[1].v].x + m.positions[t[2].v].x) / 3.0;
            const int step = static_cast<int>(std::floor(x));
            INFO("tread point " << p.x << ", " << p.y << ", " << p.z);
            CHECK(p.y == Approx(2.5 - 0.5 * step));
        }
    }
    CHECK(tread_area == Approx(5 * 1.0 * 2.0)); // five treads, each 1 x 2
}
