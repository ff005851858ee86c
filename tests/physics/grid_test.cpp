// physics.custom's uniform grid (grid.hpp): the cells' lists, linked through arrays, against a
// plain record of where each body is, after random filing, moves and removals; in the array of
// cells and in the hashed cells of a vast region.
#include "grid.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <map>
#include <random>
#include <vector>

using physics_custom::Box;
using physics_custom::Cell;
using physics_custom::UniformGrid;

namespace {

void check_against_record(double width, double cell) {
    const Box region{glm::dvec3(0.0), glm::dvec3(width)};
    UniformGrid grid(region, cell);
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> where(0.0, width);
    // A small corner of the region, so that cells hold several bodies and neighbours are many.
    std::uniform_real_distribution<double> near(0.0, std::min(width, 6.0 * cell));
    std::map<uint32_t, Cell> filed; // the record
    const uint32_t bodies = 400;
    for (int step = 0; step < 5000; ++step) {
        const auto body = static_cast<uint32_t>(rng() % bodies);
        const int action = static_cast<int>(rng() % 4);
        const glm::dvec3 p = rng() % 2 ? glm::dvec3(near(rng), near(rng), near(rng))
                                       : glm::dvec3(where(rng), where(rng), where(rng));
        const Cell c = grid.cell_of(p);
        if (action == 0) {
            // Removing from a cell it is not in changes nothing.
            grid.remove(body, c);
            const auto it = filed.find(body);
            if (it != filed.end() && it->second == c) filed.erase(it);
        } else if (action == 1 && filed.count(body)) {
            grid.remove(body, filed[body]);
            filed.erase(body);
        } else {
            grid.insert(body, c); // a body filed elsewhere moves
            filed[body] = c;
        }
        if (step % 50 != 0) continue;
        const Cell probe = grid.cell_of(p);
        std::vector<uint32_t> found, expected;
        grid.for_neighbours(probe, [&](uint32_t b) { found.push_back(b); });
        for (const auto &[b, at] : filed) {
            bool adjacent = true;
            for (size_t axis = 0; axis < 3; ++axis)
                adjacent = adjacent && at[axis] >= probe[axis] - 1 && at[axis] <= probe[axis] + 1;
            if (adjacent) expected.push_back(b);
        }
        std::sort(found.begin(), found.end());
        REQUIRE(found == expected); // each once
    }
}

} // namespace

TEST_CASE("the grid's cells list the bodies filed in them, in an array of cells") {
    check_against_record(10.0, 0.5); // 22^3 cells
}

TEST_CASE("the grid's cells list the bodies filed in them, hashed in a vast region") {
    check_against_record(1e6, 0.5); // widened to 2^20 cells per axis, hashed
}
