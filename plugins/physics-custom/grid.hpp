// The broad phase of the event-driven bake for many bodies: a uniform grid of cells at least as
// wide as the largest sphere, over the region where the scene happens. A body is filed under the
// cell its center is in; two spheres can only touch when their cells are neighbours (of the 27
// around either), and a body changes cell at an exact cell-crossing time, which is an event of
// its own. Cells are an array when the region has few enough of them, hashed otherwise, so a
// vast empty region costs nothing.
#pragma once

#include "time_of_impact.hpp"

#include <array>
#include <cstdint>
#include <optional>
#include <unordered_map>
#include <vector>

namespace physics_custom {

using Cell = std::array<int64_t, 3>;

// The first time s in [0, t_max] at which the center on `path` crosses a wall of `box` outwards:
// the time, the axis (0, 1, 2) and the direction (+1 through the upper wall, -1 the lower). A
// center on a wall (or beyond it by rounding) and moving out crosses at 0; one moving in does not.
struct Exit {
    double t = 0.0;
    int axis = 0;
    int direction = 0;
};
std::optional<Exit> first_exit(const Path &path, const Box &box, double t_max);

// The first s in [0, t_max] at which g(s) = g0 + g1 s + g2 s^2 crosses zero upwards (0 if it is
// already >= 0 and rising), with the numerically stable roots of the quadratic.
std::optional<double> upward_root(double g0, double g1, double g2, double t_max);

class UniformGrid {
  public:
    // Cells of side `cell` (widened if the region would need more than 2^20 per axis) covering
    // `region`. Bodies outside the region are not filed.
    UniformGrid(const Box &region, double cell);

    double cell_size() const { return cell_; }
    const glm::dvec3 &origin() const { return origin_; }
    const Cell &counts() const { return counts_; }
    bool dense() const { return !dense_.empty(); } // cells in an array, not hashed
    Cell cell_of(const glm::dvec3 &p) const;
    bool inside(const Cell &c) const;
    Box bounds(const Cell &c) const;

    void insert(uint32_t body, const Cell &c);
    void remove(uint32_t body, const Cell &c); // nothing if the body is not filed there
    // (A body is in one cell at a time: inserting it again moves it.)

    // Calls f(body) for every body filed in the 27 cells around c (c included).
    template <class F> void for_neighbours(const Cell &c, F &&f) const {
        for (int64_t dz = -1; dz <= 1; ++dz)
            for (int64_t dy = -1; dy <= 1; ++dy)
                for (int64_t dx = -1; dx <= 1; ++dx)
                    for (int32_t body = head({c[0] + dx, c[1] + dy, c[2] + dz}); body >= 0;
                         body = next_[static_cast<size_t>(body)])
                        f(static_cast<uint32_t>(body));
    }

  private:
    // Each cell's bodies are a list linked through arrays indexed by body (the fast codes' cell
    // lists): a cell is one number, its first body (-1: none), in an array when the region has
    // few enough cells, hashed otherwise; no allocation per cell, and the 27 cells around a body
    // are read from a few cache lines (docs/performance.md, the gas).
    int32_t head(const Cell &c) const {
        if (!dense_.empty()) return dense_[key(c)];
        const auto it = cells_.find(key(c));
        return it == cells_.end() ? -1 : it->second;
    }
    int32_t &head_at(uint64_t k) {
        if (!dense_.empty()) return dense_[k];
        return cells_.try_emplace(k, -1).first->second;
    }
    void unlink(uint32_t body);

    // Cells run from -1 to counts_ per axis (the neighbours of the edge cells): an index into
    // the array, or 21 bits each for the hash.
    uint64_t key(const Cell &c) const {
        if (!dense_.empty())
            return static_cast<uint64_t>(
                ((c[2] + 1) * (counts_[1] + 2) + (c[1] + 1)) * (counts_[0] + 2) + (c[0] + 1));
        return static_cast<uint64_t>(c[0] + 1) | static_cast<uint64_t>(c[1] + 1) << 21 |
               static_cast<uint64_t>(c[2] + 1) << 42;
    }

    glm::dvec3 origin_;
    double cell_;
    Cell counts_;
    std::vector<int32_t> dense_;                  // each cell's first body, when few enough cells
    std::unordered_map<uint64_t, int32_t> cells_; // otherwise
    // Per body: the next and previous body of its cell (-1: none), and its cell's key (or
    // kNowhere: not filed).
    std::vector<int32_t> next_, previous_;
    std::vector<uint64_t> filed_;
    static constexpr uint64_t kNowhere = ~uint64_t{0};
};

} // namespace physics_custom
