#include "impulse.hpp"

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <cmath>

namespace physics_custom {

namespace {

// [r]x, the cross-product matrix: cross(r) * x = r x x.
glm::dmat3 cross(const glm::dvec3 &r) {
    // glm is column-major: m[c][row].
    glm::dmat3 m(0.0);
    m[1][0] = -r.z;
    m[2][0] = r.y;
    m[0][1] = r.z;
    m[2][1] = -r.x;
    m[0][2] = -r.y;
    m[1][2] = r.x;
    return m;
}

glm::dmat3 k_of(const ImpulseBody &b) {
    const glm::dmat3 rx = cross(b.r);
    return b.inv_mass * glm::dmat3(1.0) - rx * b.inv_inertia * rx;
}

// The impulse p with its friction (its part beyond the frictionless p0) scaled down, if need
// be, so that the pair's kinetic energy does not grow: the change for an impulse P at the
// point is u.P + P.K P / 2 (u the relative velocity before), a quadratic in the fraction s of
// the friction part, not positive at s = 0 (p0 alone keeps or loses energy for e <= 1); the
// largest s <= 1 where it is not positive. Stronge's caveat (impulse.hpp): for a contact point
// off the line through the centres, slipping, the Newton + Coulomb impulse can create energy.
glm::dvec3 without_work(const glm::dvec3 &p, const glm::dvec3 &p0, const glm::dvec3 &u,
                        const glm::dmat3 &k) {
    const glm::dvec3 f = p - p0;
    const double a = 0.5 * glm::dot(f, k * f), b = glm::dot(f, u) + glm::dot(f, k * p0),
                 c = glm::dot(p0, u) + 0.5 * glm::dot(p0, k * p0);
    if (a + b + c <= 0.0) return p; // no energy gained
    double s = 0.0;
    if (a > 0.0) {
        const double d = b * b - 4.0 * a * c;
        s = d >= 0.0 ? (-b + std::sqrt(d)) / (2.0 * a) : 0.0;
    } else if (b > 0.0) {
        s = -c / b;
    }
    s = std::min(1.0, std::max(0.0, s * (1.0 - 1e-12)));
    return p0 + s * f;
}

void apply(const ImpulseBody &b, const glm::dvec3 &p, glm::dvec3 &v, glm::dvec3 &w) {
    v = b.v + b.inv_mass * p;
    w = b.w + b.inv_inertia * glm::cross(b.r, p);
}

} // namespace

glm::dvec3 point_velocity_of(const ImpulseBody &b) {
    return b.v + glm::cross(b.w, b.r);
}

ImpulseResult contact_impulse(const ImpulseBody &a, const ImpulseBody &b, const glm::dvec3 &n,
                              double e, double mu) {
    ImpulseResult out;
    out.va = a.v;
    out.wa = a.w;
    out.vb = b.v;
    out.wb = b.w;
    const glm::dvec3 u = point_velocity_of(a) - point_velocity_of(b);
    const double un = glm::dot(u, n);
    const glm::dmat3 k = k_of(a) + k_of(b);
    const double knn = glm::dot(n, k * n);
    if (!(un < 0.0) || !(knn > 0.0)) return out;
    const glm::dvec3 ut = u - un * n;
    glm::dvec3 p = (-(1.0 + e) * un / knn) * n; // frictionless
    if (mu > 0.0 && ut != glm::dvec3(0.0)) {
        const double det = glm::determinant(k);
        bool stuck = false;
        if (det > 0.0) {
            const glm::dvec3 stick = glm::inverse(k) * (-(1.0 + e) * un * n - ut);
            const double pn = glm::dot(stick, n);
            if (pn > 0.0 && glm::length(stick - pn * n) <= mu * pn) {
                p = stick;
                stuck = true;
                out.sticks = true;
            }
        }
        if (!stuck) {
            const glm::dvec3 t = ut / glm::length(ut);
            const glm::dvec3 dir = n - mu * t;
            const double kd = glm::dot(n, k * dir);
            if (kd > 0.0) p = (-(1.0 + e) * un / kd) * dir;
        }
        p = without_work(p, (-(1.0 + e) * un / knn) * n, u, k);
    }
    out.impulse = p;
    out.normal = glm::dot(p, n);
    apply(a, p, out.va, out.wa);
    apply(b, -p, out.vb, out.wb);
    return out;
}

ImpulseResult leave_at(const ImpulseBody &a, const glm::dvec3 &n, double speed, double mu) {
    const double u = glm::dot(point_velocity_of(a), n), knn = glm::dot(n, k_of(a) * n);
    if (!(u < speed) || !(knn > 0.0)) {
        ImpulseResult out;
        out.va = a.v;
        out.wa = a.w;
        return out;
    }
    return contact_impulse_of(a, ImpulseBody{}, n, (speed - u) / knn, mu);
}

ImpulseResult leave_at(const ImpulseBody &a, const ImpulseBody &b, const glm::dvec3 &n,
                       double speed) {
    const double u = glm::dot(point_velocity_of(a) - point_velocity_of(b), n),
                 knn = glm::dot(n, (k_of(a) + k_of(b)) * n);
    if (!(u < speed) || !(knn > 0.0)) {
        ImpulseResult out;
        out.va = a.v;
        out.wa = a.w;
        out.vb = b.v;
        out.wb = b.w;
        return out;
    }
    return contact_impulse_of(a, b, n, (speed - u) / knn, 0.0);
}

ImpulseResult contact_impulse_of(const ImpulseBody &a, const ImpulseBody &b, const glm::dvec3 &n,
                                 double normal, double mu) {
    ImpulseResult out;
    glm::dvec3 p = normal * n;
    const glm::dmat3 k = k_of(a) + k_of(b);
    // The slip once the normal impulse has acted, and the tangential impulse that stops it: u_t +
    // (K P_t)_t = 0 within the tangent plane (a 2 x 2 system in a basis of it).
    const glm::dvec3 u = point_velocity_of(a) - point_velocity_of(b) + k * p;
    const glm::dvec3 slip = u - glm::dot(u, n) * n;
    if (mu > 0.0 && slip != glm::dvec3(0.0)) {
        const glm::dvec3 t1 = slip / glm::length(slip), t2 = glm::cross(n, t1);
        const double k11 = glm::dot(t1, k * t1), k12 = glm::dot(t1, k * t2),
                     k21 = glm::dot(t2, k * t1), k22 = glm::dot(t2, k * t2);
        const double det = k11 * k22 - k12 * k21, s1 = -glm::length(slip);
        glm::dvec3 stop(0.0);
        if (det > 0.0) stop = ((k22 * s1) / det) * t1 + ((-k21 * s1) / det) * t2;
        if (det > 0.0 && glm::length(stop) <= mu * normal) {
            p += stop;
            out.sticks = true;
        } else {
            p -= (mu * normal) * t1;
        }
        p = without_work(p, normal * n, point_velocity_of(a) - point_velocity_of(b), k);
    }
    out.impulse = p;
    out.normal = normal;
    apply(a, p, out.va, out.wa);
    apply(b, -p, out.vb, out.wb);
    return out;
}

} // namespace physics_custom
