#include "meshes.hpp"

#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

namespace animator::assetgen {

namespace {

constexpr double kTwoPi = 2.0 * glm::pi<double>();

// Angle around Y measured so that u grows to the right when the surface is seen from outside:
// x = cos(theta), z = -sin(theta).
glm::dvec3 radial(double theta) {
    return {std::cos(theta), 0.0, -std::sin(theta)};
}

std::uint32_t u32(int i) {
    return static_cast<std::uint32_t>(i);
}

} // namespace

Mesh uv_sphere(int stacks, int slices) {
    Mesh m;
    // Positions and normals share indices: on a unit sphere the normal is the position.
    auto add_vertex = [&m](const glm::dvec3 &p) {
        m.add_normal(p);
        return m.add_position(p);
    };
    const std::uint32_t north = add_vertex({0.0, 1.0, 0.0});
    for (int i = 1; i < stacks; ++i) {
        const double phi = glm::pi<double>() * i / stacks;
        for (int j = 0; j < slices; ++j)
            add_vertex(radial(kTwoPi * j / slices) * std::sin(phi) +
                       glm::dvec3(0.0, std::cos(phi), 0.0));
    }
    const std::uint32_t south = add_vertex({0.0, -1.0, 0.0});

    // UVs need one more column than positions: the seam at u = 0 and u = 1 is one position.
    // Pole rows put u at the middle of each slice so the pole triangles are not sheared.
    for (int i = 0; i <= stacks; ++i) {
        for (int j = 0; j <= slices; ++j) {
            const bool pole = i == 0 || i == stacks;
            m.add_uv({(j + (pole ? 0.5 : 0.0)) / slices, 1.0 - static_cast<double>(i) / stacks});
        }
    }
    auto corner = [&](int i, int j) {
        std::uint32_t v;
        if (i == 0) {
            v = north;
        } else if (i == stacks) {
            v = south;
        } else {
            v = 1 + u32((i - 1) * slices + j % slices);
        }
        return Corner{v, u32(i * (slices + 1) + j), v};
    };
    for (int j = 0; j < slices; ++j) m.add_triangle(corner(0, j), corner(1, j), corner(1, j + 1));
    for (int i = 1; i + 1 < stacks; ++i)
        for (int j = 0; j < slices; ++j)
            m.add_quad(corner(i, j), corner(i + 1, j), corner(i + 1, j + 1), corner(i, j + 1));
    for (int j = 0; j < slices; ++j)
        m.add_triangle(corner(stacks - 1, j), corner(stacks, j), corner(stacks - 1, j + 1));
    return m;
}

Mesh icosphere(int subdivisions) {
    const double t = (1.0 + std::sqrt(5.0)) / 2.0;
    std::vector<glm::dvec3> points = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0},
                                      {0, -1, t}, {0, 1, t}, {0, -1, -t}, {0, 1, -t},
                                      {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
    for (auto &p : points) p = glm::normalize(p);
    std::vector<std::array<std::uint32_t, 3>> faces = {
        {0, 11, 5},  {0, 5, 1},  {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
        {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
        {3, 8, 9},   {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};

    for (int s = 0; s < subdivisions; ++s) {
        // Each edge's midpoint is made once, so neighbouring faces share it: no cracks.
        std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> midpoints;
        auto midpoint = [&](std::uint32_t a, std::uint32_t b) {
            const auto key = std::minmax(a, b);
            const auto found = midpoints.find(key);
            if (found != midpoints.end()) return found->second;
            points.push_back(glm::normalize(points[a] + points[b]));
            const auto index = static_cast<std::uint32_t>(points.size() - 1);
            midpoints.emplace(key, index);
            return index;
        };
        std::vector<std::array<std::uint32_t, 3>> finer;
        for (const auto &f : faces) {
            const std::uint32_t ab = midpoint(f[0], f[1]), bc = midpoint(f[1], f[2]),
                                ca = midpoint(f[2], f[0]);
            finer.push_back({f[0], ab, ca});
            finer.push_back({f[1], bc, ab});
            finer.push_back({f[2], ca, bc});
            finer.push_back({ab, bc, ca});
        }
        faces = std::move(finer);
    }

    Mesh m;
    for (const auto &p : points) {
        m.add_position(p);
        m.add_normal(p);
    }
    for (auto f : faces) {
        const glm::dvec3 a = points[f[0]], b = points[f[1]], c = points[f[2]];
        // The solid is convex around the origin, so this settles the winding whatever the
        // source table's convention.
        if (glm::dot(glm::cross(b - a, c - a), a + b + c) < 0.0) std::swap(f[1], f[2]);
        // Spherical UVs per corner; a triangle straddling the u = 0/1 seam gets its small u
        // values lifted past 1 so it does not stretch backwards across the whole texture.
        std::array<glm::dvec2, 3> uv;
        for (int k = 0; k < 3; ++k) {
            const glm::dvec3 &p = points[f[u32(k)]];
            double u = std::atan2(-p.z, p.x) / kTwoPi;
            if (u < 0.0) u += 1.0;
            uv[u32(k)] = {u, 1.0 - std::acos(std::clamp(p.y, -1.0, 1.0)) / glm::pi<double>()};
        }
        const double lo = std::min({uv[0].x, uv[1].x, uv[2].x});
        const double hi = std::max({uv[0].x, uv[1].x, uv[2].x});
        if (hi - lo > 0.5)
            for (auto &corner_uv : uv)
                if (corner_uv.x < 0.5) corner_uv.x += 1.0;
        Corner corners[3];
        for (int k = 0; k < 3; ++k) corners[k] = {f[u32(k)], m.add_uv(uv[u32(k)]), f[u32(k)]};
        m.add_triangle(corners[0], corners[1], corners[2]);
    }
    return m;
}

Mesh cube() {
    Mesh m;
    // Position index from the signs of its coordinates: bit 2 = x > 0, bit 1 = y > 0, bit 0 = z.
    for (int i = 0; i < 8; ++i)
        m.add_position({(i & 4) ? 1.0 : -1.0, (i & 2) ? 1.0 : -1.0, (i & 1) ? 1.0 : -1.0});
    auto index_of = [](const glm::dvec3 &p) {
        return u32((p.x > 0 ? 4 : 0) + (p.y > 0 ? 2 : 0) + (p.z > 0 ? 1 : 0));
    };
    const std::uint32_t uv[4] = {m.add_uv({0, 0}), m.add_uv({1, 0}), m.add_uv({1, 1}),
                                 m.add_uv({0, 1})};
    // Each face as (normal, right, up) with right x up = normal, so the corners
    // centre -right-up, +right-up, +right+up, -right+up run counter-clockwise seen from outside
    // and the texture reads upright.
    const glm::dvec3 faces[6][3] = {
        {{1, 0, 0}, {0, 0, -1}, {0, 1, 0}}, {{-1, 0, 0}, {0, 0, 1}, {0, 1, 0}},
        {{0, 1, 0}, {1, 0, 0}, {0, 0, -1}}, {{0, -1, 0}, {1, 0, 0}, {0, 0, 1}},
        {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}},  {{0, 0, -1}, {-1, 0, 0}, {0, 1, 0}}};
    for (const auto &f : faces) {
        const glm::dvec3 &n = f[0], &r = f[1], &u = f[2];
        const std::uint32_t vn = m.add_normal(n);
        const glm::dvec3 p[4] = {n - r - u, n + r - u, n + r + u, n - r + u};
        Corner c[4];
        for (int k = 0; k < 4; ++k) c[k] = {index_of(p[k]), uv[k], vn};
        m.add_quad(c[0], c[1], c[2], c[3]);
    }
    return m;
}

Mesh floor_grid(int cells) {
    Mesh m;
    const std::uint32_t up = m.add_normal({0, 1, 0});
    // Rows run from z = +1 to z = -1 so that, seen from above with -Z up the page, u grows to
    // the right and v upwards.
    for (int k = 0; k <= cells; ++k) {
        for (int i = 0; i <= cells; ++i) {
            const double s = static_cast<double>(i) / cells, t = static_cast<double>(k) / cells;
            m.add_position({-1.0 + 2.0 * s, 0.0, 1.0 - 2.0 * t});
            m.add_uv({s, t});
        }
    }
    auto corner = [&](int i, int k) {
        const std::uint32_t index = u32(k * (cells + 1) + i);
        return Corner{index, index, up};
    };
    for (int k = 0; k < cells; ++k)
        for (int i = 0; i < cells; ++i)
            m.add_quad(corner(i, k), corner(i + 1, k), corner(i + 1, k + 1), corner(i, k + 1));
    return m;
}

Mesh cylinder(int slices) {
    Mesh m;
    const std::uint32_t top_centre = m.add_position({0, 1, 0});
    const std::uint32_t bottom_centre = m.add_position({0, -1, 0});
    const std::uint32_t up = m.add_normal({0, 1, 0}), down = m.add_normal({0, -1, 0});
    const std::uint32_t centre_uv = m.add_uv({0.5, 0.5});
    std::vector<std::uint32_t> top, bottom, side_n, side_top_uv, side_bottom_uv, top_uv, bottom_uv;
    for (int j = 0; j <= slices; ++j) {
        const glm::dvec3 r = radial(kTwoPi * j / slices);
        if (j < slices) {
            top.push_back(m.add_position(r + glm::dvec3(0, 1, 0)));
            bottom.push_back(m.add_position(r - glm::dvec3(0, 1, 0)));
            side_n.push_back(m.add_normal(r));
            // Caps are mapped as seen from outside: from above, -Z is up the page; from below, +Z.
            top_uv.push_back(m.add_uv({0.5 + 0.5 * r.x, 0.5 - 0.5 * r.z}));
            bottom_uv.push_back(m.add_uv({0.5 + 0.5 * r.x, 0.5 + 0.5 * r.z}));
        }
        const double u = static_cast<double>(j) / slices;
        side_top_uv.push_back(m.add_uv({u, 1.0}));
        side_bottom_uv.push_back(m.add_uv({u, 0.0}));
    }
    for (int j = 0; j < slices; ++j) {
        const auto a = u32(j), b = u32((j + 1) % slices), bu = u32(j + 1);
        m.add_quad({top[a], side_top_uv[a], side_n[a]}, {bottom[a], side_bottom_uv[a], side_n[a]},
                   {bottom[b], side_bottom_uv[bu], side_n[b]},
                   {top[b], side_top_uv[bu], side_n[b]});
        m.add_triangle({top_centre, centre_uv, up}, {top[a], top_uv[a], up},
                       {top[b], top_uv[b], up});
        m.add_triangle({bottom_centre, centre_uv, down}, {bottom[b], bottom_uv[b], down},
                       {bottom[a], bottom_uv[a], down});
    }
    return m;
}

Mesh cone(int slices) {
    Mesh m;
    const std::uint32_t apex = m.add_position({0, 1, 0});
    const std::uint32_t base_centre = m.add_position({0, -1, 0});
    const std::uint32_t down = m.add_normal({0, -1, 0});
    const std::uint32_t centre_uv = m.add_uv({0.5, 0.5});
    // Height 2 over radius 1: the slant's outward normal is 2 * radial + 1 * up, normalised.
    auto side_normal = [](double theta) { return radial(theta) * 2.0 + glm::dvec3(0, 1, 0); };
    std::vector<std::uint32_t> ring, ring_n, ring_uv, base_uv;
    for (int j = 0; j <= slices; ++j) {
        const double theta = kTwoPi * j / slices;
        if (j < slices) {
            const glm::dvec3 r = radial(theta);
            ring.push_back(m.add_position(r - glm::dvec3(0, 1, 0)));
            ring_n.push_back(m.add_normal(side_normal(theta)));
            base_uv.push_back(m.add_uv({0.5 + 0.5 * r.x, 0.5 + 0.5 * r.z}));
        }
        ring_uv.push_back(m.add_uv({static_cast<double>(j) / slices, 0.0}));
    }
    for (int j = 0; j < slices; ++j) {
        const auto a = u32(j), b = u32((j + 1) % slices), bu = u32(j + 1);
        // The apex is one position, but its normal and UV follow the middle of each slice; a
        // single apex normal would shade the whole tip as if it were flat.
        const double mid = kTwoPi * (j + 0.5) / slices;
        const Corner tip{apex, m.add_uv({(j + 0.5) / slices, 1.0}), m.add_normal(side_normal(mid))};
        m.add_triangle(tip, {ring[a], ring_uv[a], ring_n[a]}, {ring[b], ring_uv[bu], ring_n[b]});
        m.add_triangle({base_centre, centre_uv, down}, {ring[b], base_uv[b], down},
                       {ring[a], base_uv[a], down});
    }
    return m;
}

Mesh torus(double major_radius, double minor_radius, int major_segments, int minor_segments) {
    Mesh m;
    for (int i = 0; i < minor_segments; ++i) {
        const double phi = kTwoPi * i / minor_segments;
        for (int j = 0; j < major_segments; ++j) {
            const glm::dvec3 r = radial(kTwoPi * j / major_segments);
            const glm::dvec3 n = r * std::cos(phi) + glm::dvec3(0, std::sin(phi), 0);
            m.add_position(r * major_radius + n * minor_radius);
            m.add_normal(n);
        }
    }
    for (int i = 0; i <= minor_segments; ++i)
        for (int j = 0; j <= major_segments; ++j)
            m.add_uv(
                {static_cast<double>(j) / major_segments, static_cast<double>(i) / minor_segments});
    auto corner = [&](int i, int j) {
        const std::uint32_t v = u32((i % minor_segments) * major_segments + j % major_segments);
        return Corner{v, u32(i * (major_segments + 1) + j), v};
    };
    // phi grows outward-then-up and theta towards -Z, so the counter-clockwise order seen from
    // outside is (i, j), (i, j+1), (i+1, j+1), (i+1, j).
    for (int i = 0; i < minor_segments; ++i)
        for (int j = 0; j < major_segments; ++j)
            m.add_quad(corner(i, j), corner(i, j + 1), corner(i + 1, j + 1), corner(i + 1, j));
    return m;
}

// Stairs: the XY profile below extruded from z = -1 to z = 1 (2 wide). Step k (k = 0..4) spans
// x in [k, k+1] (1 deep) and rises from y = 0 to y = 2.5 - 0.5 k, so the top step's tread is at
// y = 2.5, the lowest at y = 0.5, each riser is 0.5 high and the steps descend along +X. The
// solid sits on y = 0 from x = 0 to x = 5; its volume is 2 * (2.5 + 2 + 1.5 + 1 + 0.5) = 15.
// UVs are in world units (one texture repeat per metre).
Mesh stairs() {
    constexpr int kSteps = 5;
    // The profile, counter-clockwise seen from +Z, starting at the origin.
    std::vector<glm::dvec2> profile = {{0, 0}, {kSteps, 0}};
    for (int k = kSteps - 1; k >= 0; --k) {
        const double height = 0.5 * (kSteps - k);
        profile.push_back({k + 1, height});
        profile.push_back({k, height});
    }
    // profile now ends at (0, 2.5); the edge back to (0, 0) closes it.
    const auto count = u32(static_cast<int>(profile.size()));

    Mesh m;
    std::vector<std::uint32_t> front, back;
    for (const auto &p : profile) {
        front.push_back(m.add_position({p.x, p.y, 1.0}));
        back.push_back(m.add_position({p.x, p.y, -1.0}));
    }
    // The profile is star-shaped from the origin (the height never increases with x), so a fan
    // from the origin triangulates it using only profile vertices: no T-junctions, so every
    // outline edge meets exactly one side wall.
    const std::uint32_t front_n = m.add_normal({0, 0, 1}), back_n = m.add_normal({0, 0, -1});
    for (std::uint32_t k = 1; k + 1 < count; ++k) {
        auto front_corner = [&](std::uint32_t i) {
            return Corner{front[i], m.add_uv(profile[i]), front_n};
        };
        // Seen from -Z the x axis runs right to left.
        auto back_corner = [&](std::uint32_t i) {
            return Corner{back[i], m.add_uv({kSteps - profile[i].x, profile[i].y}), back_n};
        };
        m.add_triangle(front_corner(0), front_corner(k), front_corner(k + 1));
        m.add_triangle(back_corner(0), back_corner(k + 1), back_corner(k));
    }
    for (std::uint32_t i = 0; i < count; ++i) {
        const std::uint32_t j = (i + 1) % count;
        const glm::dvec2 edge = profile[j] - profile[i];
        // Outward for a counter-clockwise outline: the edge turned clockwise.
        const std::uint32_t n = m.add_normal({edge.y, -edge.x, 0.0});
        // u runs from profile[j] (0) to profile[i] (edge length), v = 1 - z: upright and not
        // mirrored seen from outside.
        const double length = glm::length(edge);
        m.add_quad({front[i], m.add_uv({length, 0.0}), n}, {back[i], m.add_uv({length, 2.0}), n},
                   {back[j], m.add_uv({0.0, 2.0}), n}, {front[j], m.add_uv({0.0, 0.0}), n});
    }
    return m;
}

std::vector<NamedMesh> all_meshes() {
    std::vector<NamedMesh> meshes;
    meshes.push_back(
        {"sphere.obj", "UV sphere, radius 1, 32 stacks x 32 slices", uv_sphere(32, 32)});
    meshes.push_back({"sphere_low.obj", "icosphere, radius 1, subdivided once", icosphere(1)});
    meshes.push_back(
        {"sphere_high.obj", "UV sphere, radius 1, 100 stacks x 100 slices", uv_sphere(100, 100)});
    meshes.push_back({"cube.obj", "cube from -1 to 1, flat normals, UVs 0..1 per face", cube()});
    meshes.push_back({"plane.obj", "floor: x and z from -1 to 1 at y = 0, facing +Y, single-sided",
                      floor_grid(1)});
    meshes.push_back({"floor_fine.obj",
                      "floor: x and z from -1 to 1 at y = 0, facing +Y, 64 x 64 quads",
                      floor_grid(64)});
    meshes.push_back(
        {"cylinder.obj", "cylinder, radius 1, y from -1 to 1, capped, 32 slices", cylinder(32)});
    meshes.push_back(
        {"cone.obj", "cone, base radius 1 at y = -1, apex at y = 1, capped, 32 slices", cone(32)});
    meshes.push_back({"torus.obj",
                      "torus in the XZ plane, major radius 1, minor radius 0.3, 48 x 24 segments",
                      torus(1.0, 0.3, 48, 24)});
    meshes.push_back({"stairs.obj",
                      "stairs: 5 steps descending along +X from x = 0 to 5, each 1 deep and 0.5 "
                      "high,\ntop tread at y = 2.5, bottom at y = 0, z from -1 to 1; volume 15",
                      stairs()});
    return meshes;
}

} // namespace animator::assetgen
