#include "support_polygon.hpp"

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include <algorithm>
#include <cmath>

namespace physics_custom {

namespace {

double cross(const glm::dvec2 &o, const glm::dvec2 &a, const glm::dvec2 &b) {
    return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

// The distance from p to segment ab.
double to_segment(const glm::dvec2 &p, const glm::dvec2 &a, const glm::dvec2 &b) {
    const glm::dvec2 ab = b - a;
    const double len2 = glm::dot(ab, ab);
    const double s = len2 > 0.0 ? std::clamp(glm::dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
    return glm::length(p - (a + s * ab));
}

} // namespace

bool over_feet(const glm::dvec3 &centre, const std::vector<glm::dvec3> &feet,
               const glm::dvec3 &down, double slack) {
    if (feet.empty()) return false;
    // Coordinates across `down`: two unit axes perpendicular to it.
    const glm::dvec3 d = glm::normalize(down);
    const glm::dvec3 other = std::abs(d.x) < 0.6 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
    const glm::dvec3 e1 = glm::normalize(glm::cross(d, other)), e2 = glm::cross(d, e1);
    auto flat = [&](const glm::dvec3 &p) { return glm::dvec2(glm::dot(p, e1), glm::dot(p, e2)); };
    std::vector<glm::dvec2> pts;
    for (const glm::dvec3 &f : feet) pts.push_back(flat(f));
    const glm::dvec2 c = flat(centre);
    // The convex hull (Andrew's monotone chain), counter-clockwise.
    std::sort(pts.begin(), pts.end(), [](const glm::dvec2 &a, const glm::dvec2 &b) {
        return a.x != b.x ? a.x < b.x : a.y < b.y;
    });
    std::vector<glm::dvec2> hull(2 * pts.size());
    size_t k = 0;
    for (size_t i = 0; i < pts.size(); ++i) {
        while (k >= 2 && cross(hull[k - 2], hull[k - 1], pts[i]) <= 0.0) --k;
        hull[k++] = pts[i];
    }
    for (size_t i = pts.size() - 1, lower = k + 1; i-- > 0;) {
        while (k >= lower && cross(hull[k - 2], hull[k - 1], pts[i]) <= 0.0) --k;
        hull[k++] = pts[i];
    }
    hull.resize(pts.size() > 1 ? k - 1 : 1);
    // Within slack of the hull's boundary counts as over it (a cube balanced on its edge).
    double nearest = to_segment(c, hull.front(), hull.back());
    for (size_t i = 0; i + 1 < hull.size(); ++i)
        nearest = std::min(nearest, to_segment(c, hull[i], hull[i + 1]));
    if (nearest <= slack) return true;
    if (hull.size() < 3) return false;
    for (size_t i = 0; i < hull.size(); ++i)
        if (cross(hull[i], hull[(i + 1) % hull.size()], c) < 0.0) return false;
    return true;
}

} // namespace physics_custom
