#include "simultaneous_contact.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>

namespace physics_custom {

namespace {

// The normal velocity change at a point per unit impulse along n at point x, for one body:
// J_x = (1, (x - c) x n) in (linear, angular) parts, A_kl = J_k M^-1 J_l^T.
double delassus(const ImpulseBody &body, const glm::dvec3 &com, const glm::dvec3 &xk,
                const glm::dvec3 &xl, const glm::dvec3 &n) {
    const glm::dvec3 ak = glm::cross(xk - com, n), al = glm::cross(xl - com, n);
    return body.inv_mass + glm::dot(ak, body.inv_inertia * al);
}

double det2(double a, double b, double c, double d) {
    return a * d - b * c;
}

// Solves the k x k system (k <= 3) by Cramer's rule: symmetric inputs give symmetric outputs
// bit for bit (two corners with the same row get the same impulse). False when singular
// relative to the entries' size.
bool solve(const std::array<std::array<double, 3>, 3> &m, const std::array<double, 3> &r,
           std::size_t k, std::array<double, 3> &x) {
    double scale = 0.0;
    for (std::size_t i = 0; i < k; ++i)
        for (std::size_t j = 0; j < k; ++j) scale = std::max(scale, std::abs(m[i][j]));
    if (!(scale > 0.0)) return false;
    const double tiny = 1e-10 * std::pow(scale, static_cast<double>(k));
    if (k == 1) {
        if (!(std::abs(m[0][0]) > tiny)) return false;
        x[0] = r[0] / m[0][0];
        return true;
    }
    if (k == 2) {
        const double d = det2(m[0][0], m[0][1], m[1][0], m[1][1]);
        if (!(std::abs(d) > tiny)) return false;
        x[0] = det2(r[0], m[0][1], r[1], m[1][1]) / d;
        x[1] = det2(m[0][0], r[0], m[1][0], r[1]) / d;
        return true;
    }
    auto det3 = [](const std::array<std::array<double, 3>, 3> &a) {
        return a[0][0] * det2(a[1][1], a[1][2], a[2][1], a[2][2]) -
               a[0][1] * det2(a[1][0], a[1][2], a[2][0], a[2][2]) +
               a[0][2] * det2(a[1][0], a[1][1], a[2][0], a[2][1]);
    };
    const double d = det3(m);
    if (!(std::abs(d) > tiny)) return false;
    for (std::size_t c = 0; c < 3; ++c) {
        std::array<std::array<double, 3>, 3> mc = m;
        for (std::size_t i = 0; i < 3; ++i) mc[i][c] = r[i];
        x[c] = det3(mc) / d;
    }
    return true;
}

} // namespace

std::optional<SimultaneousImpulse>
simultaneous_impulse(const ImpulseBody &a, const glm::dvec3 &com_a, const ImpulseBody &b,
                     const glm::dvec3 &com_b, const std::vector<glm::dvec3> &points,
                     const glm::dvec3 &n, double e) {
    const std::size_t count = points.size();
    if (count == 0) return std::nullopt;
    std::vector<double> u(count);
    double speed = 0.0;
    bool approaching = false;
    for (std::size_t k = 0; k < count; ++k) {
        ImpulseBody pa = a, pb = b;
        pa.r = points[k] - com_a;
        pb.r = points[k] - com_b;
        u[k] = glm::dot(point_velocity_of(pa) - point_velocity_of(pb), n);
        speed = std::max(speed, std::abs(u[k]));
        approaching = approaching || u[k] < 0.0;
    }
    if (!approaching) return std::nullopt;
    std::vector<double> big_a(count * count);
    for (std::size_t k = 0; k < count; ++k)
        for (std::size_t l = 0; l < count; ++l)
            big_a[k * count + l] = delassus(a, com_a, points[k], points[l], n) +
                                   delassus(b, com_b, points[k], points[l], n);
    const double slack = 1e-12 * speed;

    // Tries the active set `set` (size k): true with the centre of pressure when it solves the
    // whole problem.
    auto attempt = [&](const std::array<std::size_t, 3> &set, std::size_t k,
                       SimultaneousImpulse &found) {
        std::array<std::array<double, 3>, 3> m{};
        std::array<double, 3> r{}, lambda{};
        for (std::size_t i = 0; i < k; ++i) {
            for (std::size_t j = 0; j < k; ++j) m[i][j] = big_a[set[i] * count + set[j]];
            r[i] = -u[set[i]]; // the compression stops it: u'_k = 0
        }
        if (!solve(m, r, k, lambda)) return false;
        double total = 0.0;
        for (std::size_t i = 0; i < k; ++i) {
            if (!(lambda[i] >= 0.0)) return false;
            total += lambda[i];
        }
        if (!(total > 0.0)) return false;
        for (std::size_t p = 0; p < count; ++p) {
            double after = u[p];
            for (std::size_t i = 0; i < k; ++i) after += big_a[p * count + set[i]] * lambda[i];
            if (after < -slack) return false; // none still approaching
        }
        glm::dvec3 weighted(0.0);
        for (std::size_t i = 0; i < k; ++i) weighted += lambda[i] * points[set[i]];
        found.centre = weighted / total;
        found.normal = (1.0 + e) * total; // and restitution: e times it again
        return true;
    };
    SimultaneousImpulse centre;
    for (std::size_t i = 0; i < count; ++i)
        if (attempt({i, 0, 0}, 1, centre)) return centre;
    for (std::size_t i = 0; i < count; ++i)
        for (std::size_t j = i + 1; j < count; ++j)
            if (attempt({i, j, 0}, 2, centre)) return centre;
    for (std::size_t i = 0; i < count; ++i)
        for (std::size_t j = i + 1; j < count; ++j)
            for (std::size_t l = j + 1; l < count; ++l)
                if (attempt({i, j, l}, 3, centre)) return centre;
    return std::nullopt;
}

} // namespace physics_custom
