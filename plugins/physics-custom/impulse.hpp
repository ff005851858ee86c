// The impulse at one contact point between two rigid bodies (issue 18): Newton's law of
// restitution on the normal relative velocity of the touching points and Coulomb friction during
// the impact, with a sticking clamp. This is the simple "Newton + Coulomb" impact model (Stronge,
// "Impact Mechanics", ch. 3-4; Mirtich's thesis, ch. 4, before his integration of the impulse):
//
//   u   = (v_a + w_a x r_a) - (v_b + w_b x r_b)      relative velocity of the touching points
//   K   = (1/m_a + 1/m_b) 1 - [r_a] I_a^-1 [r_a] - [r_b] I_b^-1 [r_b]     (delta u = K P)
//   P   impulse on a (b gets -P), so linear and angular momentum of the pair are kept exactly.
//   1. sticking: P = K^-1 (-(1 + e) u_n n - u_t): the slip stops and u_n' = -e u_n. Taken when
//      it lies in the friction cone |P_t| <= mu P_n.
//   2. otherwise slipping: P = j (n - mu t), t = u_t / |u_t| the slip's direction at the start,
//      with j from n . K P = -(1 + e) u_n: the friction is mu times the normal impulse.
//
// Caveats of the model (Stronge): with friction and a K that couples the normal and tangential
// directions (a contact point off the line through the centres, as for a tilted box), the
// fixed-direction slip of case 2 can stop and reverse during a real impact, and Newton's
// kinematic coefficient can then create energy. For spheres (r along n: K is diagonal in the
// normal/tangent frame) neither happens; impulse_test checks energy never grows there for
// e <= 1 rather than assuming it. For the others (a tumbling cube), where the impulse would
// create energy, its friction part (beyond the frictionless impulse, which never does for
// e <= 1) is scaled down to the largest fraction that does not: the kinetic energy of the pair
// never grows at an impact.
#pragma once

#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

namespace physics_custom {

struct ImpulseBody {
    double inv_mass = 0.0;       // 0: infinite mass (static or keyed)
    glm::dmat3 inv_inertia{0.0}; // world inverse inertia; 0: does not turn
    glm::dvec3 v{0.0}, w{0.0};   // velocity and angular velocity
    glm::dvec3 r{0.0};           // contact point minus centre of mass
};

struct ImpulseResult {
    glm::dvec3 impulse{0.0}; // on a (b receives -impulse)
    double normal = 0.0;     // impulse . n
    bool sticks = false;     // the slip stopped (case 1)
    glm::dvec3 va{0.0}, wa{0.0}, vb{0.0}, wb{0.0};
};

// n: unit normal pointing from b toward a (a is pushed along +n). e in [0, 1] and mu >= 0, the
// pair's combined values. Touching points that are not approaching (u . n >= 0), or two bodies
// of infinite mass, get no impulse.
ImpulseResult contact_impulse(const ImpulseBody &a, const ImpulseBody &b, const glm::dvec3 &n,
                              double e, double mu);

// The same with the normal impulse given (> 0: several points pushing at once,
// simultaneous_contact.hpp): `normal` along n on a, and Coulomb friction at the point: the
// tangential impulse that stops the slip if it is within mu times the normal one, otherwise mu
// times it against the slip's direction at the start.
ImpulseResult contact_impulse_of(const ImpulseBody &a, const ImpulseBody &b, const glm::dvec3 &n,
                                 double normal, double mu);

// The normal impulse at a's point against infinite mass that makes the point leave along n at
// `speed` (a microcollision's least speed, bake_response.cpp); none if it leaves faster. With
// mu > 0 that impulse brings Coulomb friction with it, as contact_impulse_of's.
ImpulseResult leave_at(const ImpulseBody &a, const glm::dvec3 &n, double speed, double mu = 0.0);
// The same between two bodies: the normal impulse (a gets it along n, b against) that makes their
// touching points part along n at `speed`; none if they part faster.
ImpulseResult leave_at(const ImpulseBody &a, const ImpulseBody &b, const glm::dvec3 &n,
                       double speed);

// The contact's values from the two models' (physics.md): the lower restitution, the higher
// friction.
inline double combined_restitution(double ea, double eb) {
    return ea < eb ? ea : eb;
}
inline double combined_friction(double mua, double mub) {
    return mua > mub ? mua : mub;
}

// The velocity of the point at offset r from the centre of a body.
glm::dvec3 point_velocity_of(const ImpulseBody &b);

} // namespace physics_custom
