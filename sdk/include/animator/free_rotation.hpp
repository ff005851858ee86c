// animator SDK, optional C++ helper (library animator_free_rotation): the closed form that an
// ABI 1.4 free-rotation segment (physics.h, ani_free_rotation_segment) names, shared by the host
// that evaluates such segments and the backends that report them.
//
// Torque-free rotation of a rigid body, in closed form: the orientation and angular velocity at
// any time from those at t0, at a cost that does not grow with t - t0.
//  - spherical top (I1 = I2 = I3): the angular velocity is constant, q(t) = exp(w (t-t0)/2) q0;
//  - symmetric top (two equal moments): regular precession, the product of a rotation about the
//    fixed angular momentum L at rate |L|/I_perp and one about the body's symmetry axis;
//  - asymmetric top: the exact solution (Landau & Lifshitz, Mechanics, section 37; in the form of
//    van Zon & Schofield, J. Comput. Phys. 225 (2007) 145): the body angular velocity from the
//    Jacobi elliptic functions sn, cn, dn, and the orientation as a rotation about L whose angle
//    holds an incomplete elliptic integral of the third kind (elliptic_functions.hpp, driven by
//    k' = sqrt(1 - k^2) so that a spin next to the intermediate axis keeps its true k); on the
//    separatrix itself (k = 1) their limits tanh and sech.
// The quaternion's sign is not continuous in t (q and -q are the same orientation).
// Moments are equal when they differ by no more than 1e-12 of the largest.
#pragma once

#include "animator/elliptic_functions.hpp"

#include <glm/gtc/quaternion.hpp>
#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

#include <string>

namespace ani {

// An ABI 1.5 spin-up segment's orientation (physics.h, ani_spin_up_segment) tau seconds after its
// start: the solution of dq/dtau = (w(tau) / 2) q, w(tau) = w0 + alpha tau, from q0. About a fixed
// axis (w0 and alpha parallel within 1e-12, or either 0) the closed form; otherwise (a ball with
// side spin skidding) the fourth-order Magnus integrator, in steps in which the body turns by at
// most 3e-3 rad and alpha h^2 is at most 3e-3 rad: within 4e-14 rad of a Runge-Kutta integration
// in 400,000 steps over 1.5 s at up to 22 rad/s (free_rotation_test.cpp), in about 200 us.
glm::dquat spun_up(const glm::dquat &q0, const glm::dvec3 &w0, const glm::dvec3 &alpha, double tau);

// The rotation matrix's unit quaternion (Shepperd's method), w >= 0.
glm::dquat quaternion_of(const glm::dmat3 &rotation);

// For a model with mass properties p (physics.custom's mass_properties.hpp) and world orientation q_model, the
// principal frame's orientation is q_model * p.principal_orientation, and the model's world
// orientation at t is q(t) * conjugate(p.principal_orientation); it turns about its centre of
// mass.
class FreeRotation {
  public:
    // `moments` I1 <= I2 <= I3 (> 0, finite); `orientation` the world orientation of the principal
    // frame at t0 (unit); `angular_velocity` in world axes at t0 (rad/s, finite).
    FreeRotation(const glm::dvec3 &moments, const glm::dquat &orientation,
                 const glm::dvec3 &angular_velocity, double t0);

    // Why these moments or this angular velocity cannot be used ("" when they can): moments not
    // positive, not ascending, not finite, or breaking I1 + I2 >= I3 beyond rounding; an angular
    // velocity not finite.
    static std::string refusal(const glm::dvec3 &moments, const glm::dvec3 &angular_velocity);

    // The principal frame's world orientation and the world angular velocity at time t.
    void evaluate(double t, glm::dquat &orientation, glm::dvec3 &angular_velocity) const;

    enum class Kind { constant, symmetric, asymmetric };
    Kind kind() const { return kind_; }
    // The angular velocity's period in the body (asymmetric: 4K(k)/|omega_p|; symmetric:
    // 2 pi / |omega_body|); 0 when it is constant in the body, infinite on the separatrix.
    double body_period() const;

  private:
    Kind kind_ = Kind::constant;
    double t0_ = 0.0;
    glm::dvec3 moments_{1.0};
    glm::dquat q0_{1.0, 0.0, 0.0, 0.0};
    glm::dvec3 w0_{0.0}; // world
    glm::dvec3 L_{0.0};  // world angular momentum
    // Symmetric top: the symmetry axis (body index), the other moment, the body spin rate c.
    int axis_ = 2;
    double perp_ = 1.0, spin_ = 0.0;
    // Asymmetric top, in the right-handed frame (a, b, c) of the principal axes where the body
    // angular velocity circles axis c: w = (A cn u, B sn u, sign C dn u), u = wp (t - t0) + u0.
    glm::dmat3 to_principal_{1.0}; // abc coordinates -> principal coordinates (P)
    double Ia_ = 1.0, Ib_ = 1.0, Ic_ = 1.0;
    double A_ = 0.0, B_ = 0.0, C_ = 0.0, wp_ = 0.0, n_ = 0.0, u0_ = 0.0;
    bool separatrix_ = false; // k = 1 exactly: sn = tanh, cn = dn = sech
    EllipticModulus modulus_{1.0};
    double K_ = 0.0, Pi_ = 0.0, P0_ = 0.0, Lnorm_ = 0.0;
    glm::dmat3 Q_{1.0}; // world <- intermediate frame, constant
    void elliptic_at(double u, double &sn, double &cn, double &dn, double &P) const;
};

} // namespace ani
