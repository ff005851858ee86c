#include "grid.hpp"

#include <algorithm>
#include <cmath>

namespace physics_custom {

namespace {

constexpr int64_t kMaxCells = int64_t{1} << 20;

} // namespace

std::optional<double> upward_root(double g0, double g1, double g2, double t_max) {
    if (g0 >= 0.0 && (g1 > 0.0 || (g1 == 0.0 && g2 > 0.0)))
        return 0.0; // on or past the wall, leaving
    double root;
    if (g2 == 0.0) {
        if (!(g1 > 0.0)) return std::nullopt;
        root = -g0 / g1;
    } else {
        const double disc = g1 * g1 - 4.0 * g2 * g0;
        if (disc < 0.0) return std::nullopt;
        // The numerically stable pair of roots.
        const double q = -0.5 * (g1 + std::copysign(std::sqrt(disc), g1));
        if (q == 0.0) return std::nullopt; // a double root at 0: a tangent touch
        const double r1 = q / g2, r2 = g0 / q;
        // A parabola opening upwards crosses zero upwards at its larger root, one opening
        // downwards at its smaller one.
        root = g2 > 0.0 ? std::max(r1, r2) : std::min(r1, r2);
    }
    if (!(root > 0.0) || root > t_max) return std::nullopt;
    return root;
}

std::optional<Exit> first_exit(const Path &path, const Box &box, double t_max) {
    std::optional<Exit> best;
    for (int axis = 0; axis < 3; ++axis) {
        const double p = path.p[axis], v = path.v[axis], a = path.a[axis];
        for (int direction : {1, -1}) {
            const double wall = direction > 0 ? box.hi[axis] : box.lo[axis];
            const double d = direction;
            if (auto s = upward_root(d * (p - wall), d * v, d * 0.5 * a, t_max);
                s && (!best || *s < best->t))
                best = Exit{*s, axis, direction};
        }
    }
    return best;
}

UniformGrid::UniformGrid(const Box &region, double cell)
    : origin_(region.lo), cell_(cell), counts_{1, 1, 1} {
    const glm::dvec3 extent = region.hi - region.lo;
    const double widest = std::max({extent.x, extent.y, extent.z});
    if (!(cell_ > 0.0) || widest / cell_ > static_cast<double>(kMaxCells - 2))
        cell_ = widest / static_cast<double>(kMaxCells - 2);
    for (int axis = 0; axis < 3; ++axis)
        counts_[static_cast<size_t>(axis)] =
            std::max<int64_t>(1, static_cast<int64_t>(std::ceil(extent[axis] / cell_)));
    const double cells = static_cast<double>(counts_[0] + 2) * static_cast<double>(counts_[1] + 2) *
                         static_cast<double>(counts_[2] + 2);
    if (cells <= static_cast<double>(1 << 22)) dense_.resize(static_cast<size_t>(cells));
}

Cell UniformGrid::cell_of(const glm::dvec3 &p) const {
    Cell c{};
    for (int axis = 0; axis < 3; ++axis) {
        const double x = std::floor((p[axis] - origin_[axis]) / cell_);
        // Clamped just outside the grid, so far-away points do not overflow.
        c[static_cast<size_t>(axis)] = static_cast<int64_t>(
            std::clamp(x, -1.0, static_cast<double>(counts_[static_cast<size_t>(axis)])));
    }
    return c;
}

bool UniformGrid::inside(const Cell &c) const {
    for (size_t axis = 0; axis < 3; ++axis)
        if (c[axis] < 0 || c[axis] >= counts_[axis]) return false;
    return true;
}

Box UniformGrid::bounds(const Cell &c) const {
    Box b;
    for (int axis = 0; axis < 3; ++axis) {
        b.lo[axis] = origin_[axis] + static_cast<double>(c[static_cast<size_t>(axis)]) * cell_;
        b.hi[axis] = origin_[axis] + static_cast<double>(c[static_cast<size_t>(axis)] + 1) * cell_;
    }
    return b;
}

void UniformGrid::insert(uint32_t body, const Cell &c) {
    at(c).push_back(body);
}

void UniformGrid::remove(uint32_t body, const Cell &c) {
    auto &list = at(c);
    const auto found = std::find(list.begin(), list.end(), body);
    if (found == list.end()) return;
    *found = list.back();
    list.pop_back(); // the empty cell stays, ready for the next body
}

} // namespace physics_custom
