// The reference for a cube tipping over about its edge (docs/physics.md, "Tipping"), shared by
// tests/physics/sliding_test.cpp, sticking_test.cpp and bench/rest.cpp: a cube of side s held at
// an edge turns about it as an upside-down pendulum, I phi'' = m g d sin(phi) with d = s / sqrt(2)
// and I = 2/3 m s^2 about an edge, so phi'' = w2 sin(phi), w2 = 3 g / (2 sqrt(2) s) (phi: its
// centre of mass past the vertical through the edge). Integrated by classical Runge-Kutta: in steps of 1e-6 s its
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

// The pendulum phi'' = w2 sin(phi) from phi0 at rest, by Runge-Kutta in steps of 1e-6 s, to the
// first time `stop(phi)` holds, that last step refined by bisection on its length.
template <class Stop> double until(double w2, double phi0, Stop stop) {
    double phi = phi0, rate = 0.0, t = 0.0;
    const double h = 1e-6;
    for (;;) {
        double p = phi, r = rate;
        step(w2, h, p, r);
        if (stop(p)) break;
        phi = p;
        rate = r;
        t += h;
    }
    double lo = 0.0, hi = h;
    for (int k = 0; k < 60; ++k) {
        const double mid = 0.5 * (lo + hi);
        double p = phi, r = rate;
        step(w2, mid, p, r);
        (stop(p) ? hi : lo) = mid;
    }
    return t + lo;
}

// The pendulum phi'' = w2 sin(phi) from phi0 at rest, in Runge-Kutta steps of 1e-6 s, to `until`:
// at(t, phi, rate) every `every` seconds of it.
template <class At> void follow(double w2, double phi0, double until, double every, At at) {
    double phi = phi0, rate = 0.0, t = 0.0, next = every;
    const double h = 1e-6;
    while (t < until) {
        step(w2, h, phi, rate);
        t += h;
        if (t >= next - 0.5 * h) {
            at(t, phi, rate);
            next += every;
        }
    }
}

// A box lying with its face across an edge, turning about it from phi0 at rest (phi: the angle of
// its centre of mass, rho from the edge, from the vertical through it, away from the support;
// w2 = g rho / (I_edge / m)): whether the edge's force on it at phi (per kg: g up plus its
// centre's acceleration) pulls, or leans further from the normal of its face (tilted by
// phi - phi0 with it) than friction mu allows.
inline bool over_edge_slips(double g, double w2, double rho, double phi0, double mu, double phi) {
    const double acc = w2 * std::sin(phi), rate2 = 2.0 * w2 * (std::cos(phi0) - std::cos(phi));
    const double fx = rho * (acc * std::cos(phi) - rate2 * std::sin(phi));
    const double fy = g + rho * (-acc * std::sin(phi) - rate2 * std::cos(phi));
    const double delta = phi - phi0;
    const double N = fx * std::sin(delta) + fy * std::cos(delta);
    const double T = fx * std::cos(delta) - fy * std::sin(delta);
    return N < 0.0 || std::abs(T) > mu * N;
}

} // namespace animator::tipping
