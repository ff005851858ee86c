// animator SDK, optional C++ helper (library animator_free_rotation): the closed form that an
// ABI 1.6 hinge segment (physics.h, ani_hinge_segment) names, shared by the host that evaluates
// such segments and the backends that report them.
//
// The pendulum psi'' = -w^2 sin psi exactly, at a cost that does not grow with t - t0: a rigid
// body turning about a fixed horizontal line under gravity (a box tipping over its edge) with psi
// the angle of its centre of mass from straight below that line and w^2 = m g r / I_line.
// With k^2 = sin^2(psi0 / 2) + (psi0' / (2 w))^2 (Whittaker, Analytical Dynamics, section 44):
//  - libration (k < 1): sin(psi / 2) = k sn(w t + u0, k), cos(psi / 2) = dn, so
//    psi = 2 atan2(k sn, dn), precise at the top of the swing as at the bottom; psi' = 2 w k cn;
//  - rotation over the top (k > 1): psi / 2 = am(k w t + v0, 1 / k), psi' = 2 w k dn;
//  - the separatrix (k = 1 exactly): sin(psi / 2) = tanh(w t + u0), psi' = 2 w sech;
//  - rest at the bottom or balanced at the top: psi constant.
// The elliptic functions are driven by k'^2 = cos^2(psi0 / 2) - (psi0' / (2 w))^2 (or its
// counterpart for 1 / k) computed directly, so a swing within a hair of the top keeps its true k.
#pragma once

#include "animator/elliptic_functions.hpp"

#include <string>

namespace ani {

class Pendulum {
  public:
    enum class Kind { rest, libration, rotation, separatrix };

    // omega2 = w^2 > 0; the angle (radians) and its rate (rad/s) at time t0; all finite.
    Pendulum(double omega2, double angle0, double rate0, double t0);

    // Why these numbers cannot be used ("" when they can): w^2 not positive, anything not finite.
    static std::string refusal(double omega2, double angle0, double rate0);

    // The angle (continuous in t: it grows past pi when the pendulum goes over the top) and its
    // rate at time t.
    void evaluate(double t, double &angle, double &rate) const;
    double angle(double t) const;

    // The first time at or after t_from at which the angle equals `target` modulo 2 pi; infinity
    // when it never does (beyond the swing's amplitude, or behind a pendulum tending to the top).
    double first_time_at(double target, double t_from) const;

    // The largest |psi'| over all time (at the bottom): sqrt(psi0'^2 + 4 w^2 sin^2(psi0 / 2)).
    double max_rate() const { return max_rate_; }
    // The largest |psi''|: w^2 (times |sin psi| <= 1).
    double omega2() const { return omega2_; }
    Kind kind() const { return kind_; }

  private:
    // Everything below is of the mirrored motion (the angle times sign_, so that its rate at t0
    // is >= 0), less offset_ (a whole number of turns).
    double omega2_, omega_, t0_, sign_ = 1.0, offset_ = 0.0, angle0_ = 0.0, max_rate_ = 0.0;
    Kind kind_ = Kind::rest;
    double k_ = 0.0;   // the modulus of the motion (libration: k; rotation: 1 / k is the functions')
    double K_ = 0.0;   // the quarter period of the functions' modulus
    double u0_ = 0.0;  // the functions' argument at t0
    double rate_ = 0.0; // d(argument)/dt: w (libration, separatrix) or k w (rotation)
    EllipticModulus modulus_{1.0};
};

} // namespace ani
