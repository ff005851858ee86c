#include "animator/pendulum.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ani {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// x reduced to (-pi, pi] by whole turns.
double wrapped(double x) {
    double r = std::remainder(x, 2.0 * M_PI);
    if (r <= -M_PI) r += 2.0 * M_PI;
    return r;
}

// The smallest base + period j (j whole) that is >= from.
double next_from(double base, double period, double from) {
    double j = std::ceil((from - base) / period);
    double x = base + period * j;
    if (x < from) x += period; // rounding of the division
    return x;
}

} // namespace

std::string Pendulum::refusal(double omega2, double angle0, double rate0) {
    if (!std::isfinite(omega2) || !std::isfinite(angle0) || !std::isfinite(rate0))
        return "w^2, the angle or its rate is not finite";
    if (!(omega2 > 0.0)) return "w^2 is not positive";
    return "";
}

Pendulum::Pendulum(double omega2, double angle0, double rate0, double t0)
    : omega2_(omega2), omega_(std::sqrt(omega2)), t0_(t0) {
    sign_ = rate0 < 0.0 ? -1.0 : 1.0;
    const double a = sign_ * angle0, r = std::abs(rate0);
    angle0_ = wrapped(a);
    offset_ = a - angle0_;
    const double s = std::sin(0.5 * angle0_), c = std::cos(0.5 * angle0_), h = r / (2.0 * omega_);
    max_rate_ = std::sqrt(r * r + 4.0 * omega2 * s * s);
    const double k2 = s * s + h * h, kc2 = c * c - h * h;
    if (h == 0.0 && (s == 0.0 || c == 0.0)) {
        kind_ = Kind::rest; // at the bottom, or balanced on the top
    } else if (kc2 > 0.0) {
        kind_ = Kind::libration;
        k_ = std::sqrt(k2);
        modulus_ = EllipticModulus(kc2);
        K_ = modulus_.quarter_period();
        rate_ = omega_;
        u0_ = modulus_.first_kind(s / k_, h / k_, c); // cn0 = h / k >= 0: within [-K, K]
    } else if (kc2 < 0.0) {
        kind_ = Kind::rotation;
        k_ = std::sqrt(k2);
        const double mc2 = -kc2 / k2; // 1 - 1 / k^2
        modulus_ = EllipticModulus(mc2);
        K_ = modulus_.quarter_period();
        rate_ = k_ * omega_;
        // psi / 2 in [-pi/2, pi/2]: its amplitude's argument directly.
        u0_ = modulus_.first_kind(s, c, std::sqrt(c * c + mc2 * s * s));
    } else {
        kind_ = Kind::separatrix;
        rate_ = omega_;
        u0_ = std::atanh(s); // |s| < 1: c > 0 here
    }
}

void Pendulum::evaluate(double t, double &angle, double &rate) const {
    const double u = u0_ + rate_ * (t - t0_);
    double psi = angle0_, dpsi = 0.0;
    switch (kind_) {
    case Kind::rest:
        break;
    case Kind::libration: {
        const double m = std::round(u / (2.0 * K_));
        double sn, cn, dn;
        modulus_.sn_cn_dn(u - 2.0 * K_ * m, sn, cn, dn);
        if (std::fmod(std::abs(m), 2.0) == 1.0) {
            sn = -sn;
            cn = -cn;
        }
        psi = 2.0 * std::atan2(k_ * sn, dn);
        dpsi = 2.0 * omega_ * k_ * cn;
        break;
    }
    case Kind::rotation: {
        const double m = std::round(u / (2.0 * K_));
        double sn, cn, dn;
        modulus_.sn_cn_dn(u - 2.0 * K_ * m, sn, cn, dn);
        psi = 2.0 * (M_PI * m + std::atan2(sn, cn)); // am(u), cn >= 0 within [-K, K]
        dpsi = 2.0 * omega_ * k_ * dn;
        break;
    }
    case Kind::separatrix:
        psi = 2.0 * std::atan(std::sinh(u)); // sin(psi / 2) = tanh u
        dpsi = 2.0 * omega_ / std::cosh(u);
        break;
    }
    angle = sign_ * (psi + offset_);
    rate = sign_ * dpsi;
}

double Pendulum::angle(double t) const {
    double angle, rate;
    evaluate(t, angle, rate);
    return angle;
}

double Pendulum::first_time_at(double target, double t_from) const {
    const double tg = wrapped(sign_ * target - offset_); // the mirrored angle, less whole turns
    const double u_from = u0_ + rate_ * (t_from - t0_);
    double u = kInf;
    switch (kind_) {
    case Kind::rest:
        return tg == angle0_ || (std::abs(tg) == M_PI && std::abs(angle0_) == M_PI) ? t_from : kInf;
    case Kind::libration: {
        // sn u = sin(tg / 2) / k: u = F or 2K - F, each every 4K.
        const double s = std::sin(0.5 * tg);
        if (std::abs(s) > k_) return kInf;
        const double sn = s / k_, cn = std::sqrt(std::max(0.0, (k_ - std::abs(s)) * (k_ + std::abs(s)))) / k_;
        const double F = modulus_.first_kind(sn, cn, std::cos(0.5 * tg));
        u = std::min(next_from(F, 4.0 * K_, u_from), next_from(2.0 * K_ - F, 4.0 * K_, u_from));
        break;
    }
    case Kind::rotation: {
        // am u = tg / 2 + pi j: u = F(tg / 2) + 2K j.
        const double th = 0.5 * tg, s = std::sin(th), c = std::cos(th);
        const double mc2 = 1.0 - 1.0 / (k_ * k_);
        const double F = modulus_.first_kind(s, c, std::sqrt(c * c + mc2 * s * s));
        u = next_from(F, 2.0 * K_, u_from);
        break;
    }
    case Kind::separatrix: {
        if (std::abs(tg) >= M_PI) return kInf; // the top, reached only as t grows without end
        const double v = std::asinh(std::tan(0.5 * tg));
        if (v < u_from) return kInf;
        u = v;
        break;
    }
    }
    return t0_ + (u - u0_) / rate_;
}

} // namespace ani
