#include "time_of_impact.hpp"

#include "polynomial.hpp"

#include <glm/geometric.hpp>

#include <cmath>
#include <functional>

namespace physics_custom {

namespace {

// The squared length of q(t) = d + e t + h t^2, as a quartic.
Quartic squared_length(const glm::dvec3 &d, const glm::dvec3 &e, const glm::dvec3 &h) {
    return {glm::dot(d, d), 2.0 * glm::dot(d, e), glm::dot(e, e) + 2.0 * glm::dot(d, h), 2.0 * glm::dot(e, h),
            glm::dot(h, h)};
}

Quartic minus(Quartic q, double c) {
    q[0] -= c;
    return q;
}

// (u + w t + z t^2)^2 for scalars: the square of a quadratic.
Quartic square(double u, double w, double z) {
    return {u * u, 2.0 * u * w, w * w + 2.0 * u * z, 2.0 * w * z, z * z};
}

Quartic sub(const Quartic &a, const Quartic &b) {
    Quartic c{};
    for (size_t i = 0; i < 5; ++i) c[i] = a[i] - b[i];
    return c;
}

// The first approaching contact (f goes from > 0 to <= 0 while decreasing) in [0, t_max] that
// `valid` accepts; a contact at a moment when f is not decreasing (touching while separating)
// and one that `valid` rejects are stepped over to the next one.
std::optional<double> first_valid(const Quartic &f, double t_max, const std::function<bool(double)> &valid) {
    const Quartic df = derivative(f);
    Quartic negated{};
    for (size_t i = 0; i < 5; ++i) negated[i] = -f[i];
    double from = 0.0;
    for (int round = 0; round < 8 && from <= t_max; ++round) { // a quartic crosses zero 4 times at most
        const auto t = first_contact(f, from, t_max);
        if (!t) return std::nullopt;
        const bool approaching = *t > from || evaluate(df, *t) < 0.0;
        if (approaching && valid(*t)) return t;
        // Skip the stretch where f <= 0: to the first time it is positive again.
        const auto out = first_contact(negated, std::nextafter(*t, t_max + 1.0), t_max);
        if (!out) return std::nullopt;
        from = std::nextafter(*out, t_max + 1.0);
        // A root found a few ulps early leaves f <= 0 at `from`, still rising: step past it
        // (doubling the step) so that the next round does not stop there again. A ball leaving
        // a face slowly from a hair inside it (rounding) would otherwise run out of rounds and
        // miss its next landing (issue 18: the small bounces before rest).
        for (double step = std::abs(from) * 1e-16 + 1e-300; from <= t_max && evaluate(f, from) <= 0.0 &&
                                                            evaluate(df, from) > 0.0;
             step *= 2.0)
            from += step;
    }
    return std::nullopt;
}

} // namespace

Box swept_box(const Path &path, double t) {
    Box box{path.p, path.p};
    auto include = [&](const glm::dvec3 &q) {
        box.lo = glm::min(box.lo, q);
        box.hi = glm::max(box.hi, q);
    };
    include(path.at(t));
    for (int axis = 0; axis < 3; ++axis) {
        // The vertex of p + v s + a s^2 / 2 is at s = -v / a.
        if (path.a[axis] == 0.0) continue;
        const double s = -path.v[axis] / path.a[axis];
        if (s > 0.0 && s < t) include(path.at(s));
    }
    return box;
}

std::optional<Contact> sphere_sphere(const Path &a, double ra, const Path &b, double rb, double t_max) {
    const glm::dvec3 d = a.p - b.p, e = a.v - b.v, h = 0.5 * (a.a - b.a);
    const double reach = ra + rb;
    std::optional<double> t;
    if (h == glm::dvec3(0.0)) {
        // The same acceleration (both under gravity, or neither): the gap closes linearly and
        // |d + e t|^2 = reach^2 is a quadratic, e.e t^2 + 2 (d.e) t + d.d - reach^2, with the
        // numerically stable root. Only approaching (d.e < 0) pairs can meet.
        const double qa = glm::dot(e, e), qb = glm::dot(d, e), qc = glm::dot(d, d) - reach * reach;
        if (!(qb < 0.0)) return std::nullopt;
        if (qc <= 0.0) {
            t = 0.0; // touching (or overlapping) and approaching
        } else {
            const double disc = qb * qb - qa * qc;
            if (disc < 0.0) return std::nullopt;
            const double root = qc / (-qb + std::sqrt(disc));
            if (root > t_max) return std::nullopt;
            t = root;
        }
    } else {
        const Quartic f = minus(squared_length(d, e, h), reach * reach);
        t = first_valid(f, t_max, [](double) { return true; });
        if (!t) return std::nullopt;
    }
    Contact c;
    c.t = *t;
    const glm::dvec3 between = a.at(*t) - b.at(*t);
    c.normal = glm::length(between) > 0.0 ? glm::normalize(between) : glm::dvec3(0, 1, 0);
    c.point = a.at(*t) - c.normal * ra;
    return c;
}

std::optional<Contact> sphere_triangle(const Path &s, double r, const glm::dvec3 &v0, const glm::dvec3 &v1,
                                       const glm::dvec3 &v2, double t_max) {
    std::optional<Contact> best;
    auto offer = [&](double t, const glm::dvec3 &normal) {
        if (best && best->t <= t) return;
        best = Contact{t, normal, s.at(t) - normal * r};
    };
    const glm::dvec3 corners[3] = {v0, v1, v2};
    const glm::dvec3 area = glm::cross(v1 - v0, v2 - v0);
    const glm::dvec3 n = glm::length(area) > 0.0 ? glm::normalize(area) : glm::dvec3(0.0);

    // The face, from either side: signed distance n . (c(t) - v0) = +-r, a quadratic, with the
    // touching point inside the triangle. A triangle without area has only edges and corners.
    for (double side : {1.0, -1.0}) {
        if (n == glm::dvec3(0.0)) break;
        const glm::dvec3 d = s.p - v0;
        // Only the side the center is on can be met: from the other side the function is below
        // zero all along, which is not a contact.
        if (side * glm::dot(n, d) <= 0.0) continue;
        const Quartic f = {side * glm::dot(n, d) - r, side * glm::dot(n, s.v), side * 0.5 * glm::dot(n, s.a), 0.0, 0.0};
        auto inside = [&](double t) {
            const glm::dvec3 q = s.at(t) - side * r * n;
            for (int i = 0; i < 3; ++i) {
                const glm::dvec3 &a = corners[i], &b = corners[(i + 1) % 3];
                if (glm::dot(n, glm::cross(b - a, q - a)) < 0.0) return false;
            }
            return true;
        };
        if (auto t = first_valid(f, t_max, inside)) offer(*t, side * n);
    }
    // Every edge and corner lies in the triangle's plane, so none can be touched before the
    // center comes within r of it. A center farther than that now that never comes that close
    // touches nothing; one whose first approach meets the face has its earliest contact there.
    // (The common case, a ball flying at a wall, costs one quadratic instead of seven solves.)
    if (n != glm::dvec3(0.0)) {
        const double distance = glm::dot(n, s.p - v0);
        const double side = distance > 0.0 ? 1.0 : -1.0;
        if (side * distance > r) {
            const Quartic f = {side * distance - r, side * glm::dot(n, s.v), side * 0.5 * glm::dot(n, s.a), 0.0, 0.0};
            const auto first = first_contact(f, 0.0, t_max);
            if (!first) return std::nullopt;
            if (best && best->t == *first) return best;
        }
    }

    // The edges: the distance from c(t) to the edge's line equals r, with the nearest point on
    // the edge: |w|^2 - (w . u)^2 = r^2 for w = c - a and u the edge's unit direction.
    for (int i = 0; i < 3; ++i) {
        const glm::dvec3 &a = corners[i], &b = corners[(i + 1) % 3];
        const double length = glm::length(b - a);
        if (!(length > 0.0)) continue;
        const glm::dvec3 u = (b - a) / length;
        const glm::dvec3 d = s.p - a, e = s.v, h = 0.5 * s.a;
        const Quartic f = minus(sub(squared_length(d, e, h), square(glm::dot(d, u), glm::dot(e, u), glm::dot(h, u))), r * r);
        auto on_edge = [&](double t) {
            const double along = glm::dot(s.at(t) - a, u);
            return along >= 0.0 && along <= length;
        };
        if (auto t = first_valid(f, t_max, on_edge)) {
            const glm::dvec3 c = s.at(*t);
            const glm::dvec3 nearest = a + u * glm::dot(c - a, u);
            offer(*t, glm::normalize(c - nearest));
        }
    }

    // The corners: |c(t) - corner| = r.
    for (const glm::dvec3 &corner : corners) {
        const Quartic f = minus(squared_length(s.p - corner, s.v, 0.5 * s.a), r * r);
        if (auto t = first_valid(f, t_max, [](double) { return true; })) offer(*t, glm::normalize(s.at(*t) - corner));
    }
    return best;
}

std::optional<double> ray_triangle(const glm::dvec3 &start, const glm::dvec3 &ray, const glm::dvec3 &v0,
                                   const glm::dvec3 &v1, const glm::dvec3 &v2) {
    const glm::dvec3 n = glm::cross(v1 - v0, v2 - v0);
    const double facing = glm::dot(n, ray);
    if (facing == 0.0) return std::nullopt; // the ray is parallel to the triangle
    const double t = glm::dot(v0 - start, n) / facing;
    if (t < 0.0 || t > 1.0) return std::nullopt; // beyond the ray's ends
    const glm::dvec3 poi = start + t * ray;
    if (glm::dot(n, glm::cross(v1 - v0, poi - v0)) >= 0.0 && glm::dot(n, glm::cross(v2 - v1, poi - v1)) >= 0.0 &&
        glm::dot(n, glm::cross(v0 - v2, poi - v2)) >= 0.0)
        return t;
    return std::nullopt;
}

} // namespace physics_custom
