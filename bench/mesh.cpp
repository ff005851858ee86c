// Mesh against mesh: physics.custom's narrow phase (plugins/physics-custom/mesh_contact.hpp) on a
// detailed, irregular mesh dropped on a tessellated floor and on a second copy of itself: the time
// of one query with the bounding volume hierarchy against the brute force that tests every
// feature pair, and whether the two agree.
#include "bench.hpp"

#include "mesh_contact.hpp"

#include <glm/geometric.hpp>

#include <cmath>
#include <iostream>
#include <map>
#include <random>

namespace animator::bench {

using namespace physics_custom;

namespace {

using Vertices = std::vector<glm::dvec3>;
using Triangles = std::vector<std::array<uint32_t, 3>>;

// Turns every triangle counter-clockwise seen from outside (the mesh is star-shaped around 0).
Triangles facing_out(const Vertices &v, Triangles tris) {
    for (auto &t : tris) {
        const glm::dvec3 n = glm::cross(v[t[1]] - v[t[0]], v[t[2]] - v[t[0]]);
        if (glm::dot(n, v[t[0]] + v[t[1]] + v[t[2]]) < 0.0) std::swap(t[1], t[2]);
    }
    return tris;
}

// An irregular rock: an icosahedron subdivided `level` times (20 * 4^level triangles), its
// vertices moved in and out by smooth lumps and a little noise, then turned at random.
MeshShape rock(int level, uint64_t seed) {
    const double p = (1.0 + std::sqrt(5.0)) / 2.0;
    Vertices v = {{-1, p, 0},  {1, p, 0},  {-1, -p, 0}, {1, -p, 0}, {0, -1, p},  {0, 1, p},
                  {0, -1, -p}, {0, 1, -p}, {p, 0, -1},  {p, 0, 1},  {-p, 0, -1}, {-p, 0, 1}};
    Triangles t = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                   {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                   {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                   {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
    for (auto &x : v) x = glm::normalize(x);
    for (int l = 0; l < level; ++l) {
        std::map<std::pair<uint32_t, uint32_t>, uint32_t> middle;
        auto mid = [&](uint32_t a, uint32_t b) {
            const auto key = std::minmax(a, b);
            const auto found = middle.find(key);
            if (found != middle.end()) return found->second;
            v.push_back(glm::normalize(v[a] + v[b]));
            return middle[key] = static_cast<uint32_t>(v.size() - 1);
        };
        Triangles next;
        for (const auto &f : t) {
            const uint32_t ab = mid(f[0], f[1]), bc = mid(f[1], f[2]), ca = mid(f[2], f[0]);
            next.push_back({f[0], ab, ca});
            next.push_back({f[1], bc, ab});
            next.push_back({f[2], ca, bc});
            next.push_back({ab, bc, ca});
        }
        t = std::move(next);
    }
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    for (auto &x : v)
        x *= 1.0 + 0.18 * std::sin(3.0 * x.x + 1.0) * std::cos(4.0 * x.y) * std::sin(5.0 * x.z + 2.0) +
             0.08 * std::sin(9.0 * x.y + 7.0 * x.z) + 0.01 * unit(rng);
    t = facing_out(v, t);
    // A random turn (Rodrigues) so the rock meets the floor at no special angle.
    glm::dvec3 k(unit(rng), unit(rng), unit(rng));
    k = glm::normalize(k);
    const double angle = 3.14159265358979 * unit(rng), c = std::cos(angle), s = std::sin(angle);
    for (auto &x : v) x = x * c + glm::cross(k, x) * s + k * glm::dot(k, x) * (1.0 - c);
    return MeshShape::build(v, t);
}

// A square of side 2 s at y = 0 in n x n cells of two triangles each (an open mesh).
MeshShape floor_square(double s, int n) {
    Vertices v;
    Triangles t;
    for (int i = 0; i <= n; ++i)
        for (int j = 0; j <= n; ++j)
            v.emplace_back(-s + 2.0 * s * i / n, 0.0, -s + 2.0 * s * j / n);
    auto at = [&](int i, int j) { return static_cast<uint32_t>(i * (n + 1) + j); };
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            t.push_back({at(i, j), at(i, j + 1), at(i + 1, j + 1)});
            t.push_back({at(i, j), at(i + 1, j + 1), at(i + 1, j)});
        }
    return MeshShape::build(v, t);
}

struct Timed {
    double us = 0.0; // median time of one query
    std::optional<Contact> contact;
    PairStats stats;
};

template <class F> Timed time_query(int runs, F &&query) {
    Timed out;
    std::vector<double> us;
    for (int r = 0; r < runs; ++r) {
        PairStats stats;
        const auto start = std::chrono::steady_clock::now();
        auto c = query(&stats);
        us.push_back(1e6 * seconds_since(start));
        out.contact = c;
        out.stats = stats;
    }
    out.us = median(us);
    return out;
}

} // namespace

void run_mesh(const Options &o) {
    const int level = o.quick ? 2 : 4;
    const int floor_cells = o.quick ? 8 : 64;
    const MeshShape a = rock(level, 1), copy = rock(level, 2),
                    floor = floor_square(4.0, floor_cells);
    const int queries = o.quick ? 2 : 3;
    Csv csv(o.out / "mesh.csv",
            {"case", "query", "triangles_a", "triangles_b", "bvh_us", "brute_us", "speedup",
             "bvh_feature_tests", "brute_feature_tests", "bvh_node_pairs", "contact",
             "time_difference", "normal_difference", "point_difference"});
    std::cout << "A rock of " << a.triangles.size() << " triangles (" << a.vertices.size()
              << " vertices, " << a.edges.size()
              << " edges), falling from rest with a sideways drift, on a floor of "
              << floor.triangles.size() << " triangles and on a second rock of "
              << copy.triangles.size() << " triangles (another seed) at rest; " << queries
              << " drops each, median of " << o.runs << " runs per query.\n";
    std::cout << "| case | query | BVH us | brute force us | speedup | feature tests BVH / brute "
                 "| agree (time, normal, point) |\n";
    const glm::dvec3 gravity(0.0, -9.81, 0.0);
    for (int c = 0; c < 2; ++c) {
        const MeshShape &b = c == 0 ? floor : copy;
        const std::string name = c == 0 ? "rock on floor" : "rock on rock";
        for (int q = 0; q < queries; ++q) {
            const glm::dvec3 start(0.37 * q - 0.3, c == 0 ? 2.0 : 3.2, 0.21 - 0.29 * q);
            const Path pa{start, {0.4, 0.0, -0.3}, gravity}, pb{{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
            const Timed fast = time_query(o.runs, [&](PairStats *s) {
                return mesh_mesh(a, pa, b, pb, 2.0, s);
            });
            const Timed brute = time_query(o.runs, [&](PairStats *s) {
                return mesh_mesh_brute(a, pa, b, pb, 2.0, s);
            });
            double dt = 0.0, dn = 0.0, dp = 0.0;
            const bool both = fast.contact.has_value() && brute.contact.has_value();
            if (both) {
                dt = std::abs(fast.contact->t - brute.contact->t);
                dn = glm::length(fast.contact->normal - brute.contact->normal);
                dp = glm::length(fast.contact->point - brute.contact->point);
            } else if (fast.contact.has_value() != brute.contact.has_value()) {
                dt = dn = dp = 1.0; // one found a contact, the other none
            }
            csv << name << static_cast<double>(q) << static_cast<double>(a.triangles.size())
                << static_cast<double>(b.triangles.size()) << fast.us << brute.us
                << brute.us / fast.us << static_cast<double>(fast.stats.primitive_tests)
                << static_cast<double>(brute.stats.primitive_tests)
                << static_cast<double>(fast.stats.nodes_visited)
                << (fast.contact ? fast.contact->t : -1.0) << dt << dn << dp;
            csv.end_row();
            std::cout << "| " << name << " | " << q << " | " << fmt(fast.us) << " | "
                      << fmt(brute.us) << " | " << fmt(brute.us / fast.us) << "x | "
                      << fast.stats.primitive_tests << " / " << brute.stats.primitive_tests
                      << " | " << (both ? "contact at t " + fmt(fast.contact->t) : "no contact")
                      << ": " << fmt(dt) << ", " << fmt(dn) << ", " << fmt(dp) << " |\n";
        }
    }
}

} // namespace animator::bench
