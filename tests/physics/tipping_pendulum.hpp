// The reference for a cube tipping over about its edge (docs/physics.md, "Tipping"), shared by
// tests/physics/sliding_test.cpp and bench/rest.cpp: a cube of side s held at an edge turns about
// it as an upside-down pendulum, I phi'' = m g d sin(phi) with d = s / sqrt(2) and I = 2/3 m s^2
// about an edge, so phi'' = w2 sin(phi), w2 = 3 g / (2 sqrt(2) s) (phi: its centre of mass past
// the vertical through the edge). Integrated by classical Runge-Kutta: in steps of 1e-6 s its
// error is far below what the tests check.
#pragma once

#include <cmath>

namespace animator::tipping {

inline double pendulum_rate(double g, double side) {
    return 3.0 * g / (2.0 * std::sqrt(2.0) * side);
}

// One Runge-Kutta step of h seconds of phi'' = w2 sin(phi).
inline void step(double w2, double h, double &phi, double &rate) {
    const double k1p = rate, k1v = w2 * std::sin(phi);
    const double k2p = rate + 0.5 * h * k1v, k2v = w2 * std::sin(phi + 0.5 * h * k1p);
    const double k3p = rate + 0.5 * h * k2v, k3v = w2 * std::sin(phi + 0.5 * h * k2p);
    const double k4p = rate + h * k3v, k4v = w2 * std::sin(phi + h * k3p);
    phi += h / 6.0 * (k1p + 2.0 * k2p + 2.0 * k3p + k4p);
    rate += h / 6.0 * (k1v + 2.0 * k2v + 2.0 * k3v + k4v);
}

} // namespace animator::tipping
