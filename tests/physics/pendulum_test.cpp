// The pendulum psi'' = -w^2 sin psi in closed form (animator/pendulum.hpp), the motion of a hinge
// segment: against a fine Runge-Kutta integration of the equation, the energy it keeps, the
// periods known from tables, and the first time it reaches an angle against a scan of the motion.
#include "animator/pendulum.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

using ani::Pendulum;

namespace {

// psi'' = -w2 sin psi by classical Runge-Kutta in `steps` steps over [0, tau]: the truth,
// written apart from the closed form.
void rk4(double w2, double &psi, double &rate, double tau, int steps) {
    const double h = tau / steps;
    for (int i = 0; i < steps; ++i) {
        const double k1p = rate, k1r = -w2 * std::sin(psi);
        const double k2p = rate + 0.5 * h * k1r, k2r = -w2 * std::sin(psi + 0.5 * h * k1p);
        const double k3p = rate + 0.5 * h * k2r, k3r = -w2 * std::sin(psi + 0.5 * h * k2p);
        const double k4p = rate + h * k3r, k4r = -w2 * std::sin(psi + h * k3p);
        psi += h / 6.0 * (k1p + 2.0 * k2p + 2.0 * k3p + k4p);
        rate += h / 6.0 * (k1r + 2.0 * k2r + 2.0 * k3r + k4r);
    }
}

double energy(double w2, double psi, double rate) {
    return 0.5 * rate * rate + 2.0 * w2 * std::pow(std::sin(0.5 * psi), 2);
}

struct Start {
    const char *what;
    double w2, angle, rate;
};

const std::vector<Start> kStarts = {
    {"a small swing", 9.0, 0.1, 0.0},
    {"a swing from the side, moving", 4.0, 1.2, -1.5},
    {"a cube tipping from 30 degrees off balance", 10.403, M_PI - M_PI / 6.0, 0.0},
    {"a swing within 1e-6 rad of the top", 2.0, M_PI - 1e-6, 0.0},
    {"over the top, forwards", 3.0, 0.5, 4.0},
    {"over the top, backwards, after two turns", 3.0, 4.0 * M_PI + 0.5, -4.0},
    {"a swing started turns away", 1.0, -6.0 * M_PI + 2.5, 0.3},
};

} // namespace

TEST_CASE("the pendulum's closed form follows a fine integration of psi'' = -w^2 sin psi") {
    for (const Start &s : kStarts) {
        CAPTURE(s.what);
        const double t0 = 0.75;
        const Pendulum p(s.w2, s.angle, s.rate, t0);
        double psi = s.angle, rate = s.rate, t = t0;
        for (double tau : {0.01, 0.3, 1.0, 2.5}) { // each piece from where the last ended
            rk4(s.w2, psi, rate, tau - (t - t0), 40000);
            t = t0 + tau;
            double a, r;
            p.evaluate(t, a, r);
            CAPTURE(tau);
            CHECK(std::abs(a - psi) < 1e-9);
            CHECK(std::abs(r - rate) < 1e-9 * std::max(1.0, std::abs(rate)));
        }
        double a, r;
        p.evaluate(t0, a, r);
        CHECK(std::abs(a - s.angle) < 1e-14 * std::max(1.0, std::abs(s.angle)));
        CHECK(std::abs(r - s.rate) < 1e-13);
    }
}

TEST_CASE("the pendulum keeps its energy to rounding over a long time, and never outruns its "
          "bound") {
    for (const Start &s : kStarts) {
        CAPTURE(s.what);
        const Pendulum p(s.w2, s.angle, s.rate, 0.0);
        const double e0 = energy(s.w2, s.angle, s.rate);
        for (double t = 0.0; t < 1000.0; t += 7.31) {
            double a, r;
            p.evaluate(t, a, r);
            CHECK(std::abs(energy(s.w2, a, r) - e0) <= 1e-12 * std::max(1.0, e0));
            CHECK(std::abs(r) <= p.max_rate() * (1.0 + 1e-12));
        }
    }
}

TEST_CASE("the pendulum's periods are the tables' (K(k) of Abramowitz and Stegun, 17.3)") {
    // From rest at 90 degrees: k = sin 45 degrees, K = 1.854074677301372, period 4 K / w.
    const double w2 = 5.0, w = std::sqrt(w2);
    const Pendulum quarter(w2, M_PI / 2.0, 0.0, 0.0);
    const double period = 4.0 * 1.854074677301372 / w;
    CHECK(std::abs(quarter.angle(period) - M_PI / 2.0) < 1e-12);
    CHECK(std::abs(quarter.angle(period / 2.0) + M_PI / 2.0) < 1e-12);
    CHECK(std::abs(quarter.angle(period / 4.0)) < 1e-12);
    // From rest at 1 degree: within (1/16) theta^2 of 2 pi / w.
    const Pendulum small(w2, M_PI / 180.0, 0.0, 0.0);
    CHECK(std::abs(small.angle(2.0 * M_PI / w) - M_PI / 180.0) < 1e-7);
    // Over the top from the bottom at 4 w: k = 2, one turn in 2 K(1/2) / (k w), K(1/2) =
    // 1.685750354812596 (k^2 = 1/4).
    const Pendulum over(w2, 0.0, 4.0 * w, 0.0);
    CHECK(std::abs(over.angle(2.0 * 1.685750354812596 / (2.0 * w)) - 2.0 * M_PI) < 1e-12);
    // Hanging still, it stays. Released at rest from M_PI, 1.2246e-16 rad short of the top, it
    // falls away from it as the linearised equation says, x(t) = x0 cosh(w t).
    CHECK(Pendulum(w2, 0.0, 0.0, 0.0).angle(100.0) == 0.0);
    const double x0 = 1.2246467991473532e-16;
    const Pendulum top(w2, M_PI, 0.0, 0.0);
    for (double t : {3.0, 6.0, 9.0}) {
        const double x = x0 * std::cosh(w * t); // still small: the linear equation holds
        CHECK(std::abs((M_PI - top.angle(t)) - (x - x0)) < 1e-3 * x + 1e-15); // and the rounding of pi
    }
    // On the separatrix (rising from the bottom at 2 w): sin(psi / 2) = tanh(w t).
    const Pendulum rising(w2, 0.0, 2.0 * w, 0.0);
    CHECK(rising.kind() == Pendulum::Kind::separatrix);
    CHECK(std::abs(std::sin(0.5 * rising.angle(1.3)) - std::tanh(w * 1.3)) < 1e-14);
}

TEST_CASE("the first time the pendulum reaches an angle is the first crossing a scan finds") {
    for (const Start &s : kStarts) {
        CAPTURE(s.what);
        const Pendulum p(s.w2, s.angle, s.rate, 0.5);
        for (double target : {-2.5, -1.0, 0.05, 1.5, 3.0, M_PI - 0.5e-6}) {
            CAPTURE(target);
            const double from = 0.9;
            const double t = p.first_time_at(target, from);
            // The scan: the first step over which angle - target (modulo 2 pi) changes sign.
            auto off = [&](double time) { return std::remainder(p.angle(time) - target, 2.0 * M_PI); };
            double found = std::numeric_limits<double>::infinity();
            const double h = 1e-4;
            for (double a = from; a < from + 30.0; a += h) {
                const double x = off(a), y = off(a + h);
                if (x == 0.0 || (x * y < 0.0 && std::abs(x - y) < 1.0)) {
                    found = a;
                    break;
                }
            }
            if (std::isinf(found)) {
                CHECK(t > from + 30.0);
            } else {
                CHECK(t >= found - 1e-9);
                CHECK(t <= found + h + 1e-9);
                CHECK(std::abs(off(t)) < 1e-9);
            }
        }
    }
}
