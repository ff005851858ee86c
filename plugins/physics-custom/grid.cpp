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
    if (cells <= static_cast<double>(1 << 22)) dense_.assign(static_cast<size_t>(cells), -1);
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
    if (body >= filed_.size()) {
        next_.resize(body + 1, -1);
        previous_.resize(body + 1, -1);
        filed_.resize(body + 1, kNowhere);
    }
    unlink(body);
    const uint64_t k = key(c);
    int32_t &first = head_at(k);
    const auto b = static_cast<int32_t>(body);
    next_[body] = first;
    previous_[body] = -1;
    if (first >= 0) previous_[static_cast<size_t>(first)] = b;
    first = b;
    filed_[body] = k;
}

void UniformGrid::remove(uint32_t body, const Cell &c) {
    if (body < filed_.size() && filed_[body] == key(c)) unlink(body);
}

void UniformGrid::unlink(uint32_t body) {
    if (filed_[body] == kNowhere) return;
    const int32_t after = next_[body], before = previous_[body];
    if (before >= 0)
        next_[static_cast<size_t>(before)] = after;
    else
        head_at(filed_[body]) = after; // the empty cell stays, ready for the next body
    if (after >= 0) previous_[static_cast<size_t>(after)] = before;
    next_[body] = previous_[body] = -1;
    filed_[body] = kNowhere;
}

} // namespace physics_custom
