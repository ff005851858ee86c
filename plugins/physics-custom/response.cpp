#include "response.hpp"

#include <glm/geometric.hpp>

namespace physics_custom {

glm::dvec3 reflect(const glm::dvec3 &v, const glm::dvec3 &n) { return v - 2.0 * glm::dot(v, n) * n; }

glm::dvec3 reflect_off_moving_wall(const glm::dvec3 &v, const glm::dvec3 &v_wall, const glm::dvec3 &n) {
    return v - 2.0 * glm::dot(v - v_wall, n) * n;
}

std::pair<glm::dvec3, glm::dvec3> elastic_exchange(double ma, const glm::dvec3 &va, double mb, const glm::dvec3 &vb,
                                                   const glm::dvec3 &n) {
    // v = v_perp + v_par; only the components along n exchange, as in 1D:
    // va1 = ((ma - mb) va + 2 mb vb) / (ma + mb), vb1 = ((mb - ma) vb + 2 ma va) / (ma + mb).
    const double ua = glm::dot(va, n), ub = glm::dot(vb, n);
    const double total = ma + mb;
    const double ua1 = ((ma - mb) * ua + 2.0 * mb * ub) / total;
    const double ub1 = ((mb - ma) * ub + 2.0 * ma * ua) / total;
    return {va + (ua1 - ua) * n, vb + (ub1 - ub) * n};
}

} // namespace physics_custom
