// Mesh against mesh: physics.custom's narrow phase (plugins/physics-custom/mesh_contact.hpp) on a
// detailed, irregular mesh dropped on a tessellated floor and on a second copy of itself: the time
// of one query with the bounding volume hierarchy against the brute force that tests every
// feature pair, and whether the two agree.
#include "bench.hpp"

#include "mesh_contact.hpp"
#include "physics/test_meshes.hpp"

#include <glm/geometric.hpp>

#include <cmath>
#include <iostream>
#include <map>
#include <random>

namespace animator::bench {

using namespace physics_custom;

namespace {

using namespace test_meshes;

// An irregular rock: an icosahedron subdivided `level` times (20 * 4^level triangles), its
// vertices moved in and out by smooth lumps and a little noise, then turned at random.
MeshShape rock(int level, uint64_t seed) {
    auto [v, t] = subdivided_icosahedron(level);
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
