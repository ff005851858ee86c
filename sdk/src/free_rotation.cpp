#include "animator/free_rotation.hpp"

#include "animator/elliptic_functions.hpp"

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_access.hpp>
#include <glm/mat3x3.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace ani {

glm::dquat spun_up(const glm::dquat &q0, const glm::dvec3 &w0, const glm::dvec3 &alpha,
                   double tau) {
    auto turn = [](const glm::dvec3 &rotation) { // exp of a rotation vector, as a quaternion
        const double angle = glm::length(rotation);
        if (!(angle > 0.0)) return glm::dquat(1.0, 0.0, 0.0, 0.0);
        return glm::angleAxis(angle, rotation / angle);
    };
    const double spin = glm::length(w0), rate = glm::length(alpha);
    if (rate == 0.0 || spin == 0.0 || glm::length(glm::cross(w0, alpha)) <= 1e-12 * spin * rate) {
        // About a fixed axis: w0 tau + alpha tau^2 / 2 is along it.
        return glm::normalize(turn(w0 * tau + 0.5 * tau * tau * alpha) * q0);
    }
    // Magnus, fourth order, for a w linear in time: over a step of h from w_a,
    // Omega = h w(h / 2) + h^3 / 12 alpha x w_a (the first two terms of the expansion, exact up
    // to h^5), and q <- exp(Omega / 2) q. Steps in which it turns by at most 3e-3 rad and
    // alpha h^2 is at most 3e-3 rad (its error is then at the rounding of the steps).
    const double reach = std::abs(tau);
    const double w_max = spin + rate * reach;
    double h = std::min(3e-3 / w_max, 3e-3 / std::sqrt(rate));
    const double steps = std::ceil(reach / h);
    if (!(steps < 1e9)) return glm::dquat(std::nan(""), 0.0, 0.0, 0.0); // not evaluable
    const int n = std::max(1, static_cast<int>(steps));
    h = tau / n;
    glm::dquat q = q0;
    for (int k = 0; k < n; ++k) {
        const glm::dvec3 w_a = w0 + (k * h) * alpha;
        const glm::dvec3 omega =
            h * (w_a + 0.5 * h * alpha) + (h * h * h / 12.0) * glm::cross(alpha, w_a);
        q = turn(omega) * q;
        if (k % 64 == 63) q = glm::normalize(q);
    }
    return glm::normalize(q);
}

namespace {

constexpr double equal_moments = 1e-12; // relative to the largest moment

// The rotation by the angle |v| about v, as a quaternion: exp(v / 2).
glm::dquat rotation_by(const glm::dvec3 &v) {
    const double angle = glm::length(v);
    if (angle == 0.0) return {1.0, 0.0, 0.0, 0.0};
    const glm::dvec3 axis = v / angle;
    const double s = std::sin(0.5 * angle);
    return {std::cos(0.5 * angle), s * axis.x, s * axis.y, s * axis.z};
}

// The rotation matrix whose rows are the intermediate frame's axes in the body (abc) frame:
// z along the body's unit angular momentum l, x = (lb, -la, 0) / rho perpendicular to l and to
// axis c, y = z cross x. Its angular velocity about z gives the precession rate below.
glm::dmat3 to_intermediate(const glm::dvec3 &l) {
    const double rho = std::sqrt(l.x * l.x + l.y * l.y);
    const glm::dvec3 ex(l.y / rho, -l.x / rho, 0.0);
    const glm::dvec3 ey(l.z * l.x / rho, l.z * l.y / rho, -rho);
    return glm::transpose(glm::dmat3(ex, ey, l)); // glm's constructor takes columns
}

} // namespace

std::string FreeRotation::refusal(const glm::dvec3 &I, const glm::dvec3 &w) {
    for (int i = 0; i < 3; ++i) {
        if (!std::isfinite(I[i]) || !(I[i] > 0.0)) return "a principal moment is not positive";
        if (!std::isfinite(w[i])) return "the angular velocity is not finite";
    }
    if (I.x > I.y || I.y > I.z) return "the principal moments are not in ascending order";
    if (I.x + I.y < I.z * (1.0 - 1e-9)) return "the principal moments break I1 + I2 >= I3";
    return "";
}

FreeRotation::FreeRotation(const glm::dvec3 &I, const glm::dquat &q0, const glm::dvec3 &w0,
                           double t0)
    : t0_(t0), moments_(I), q0_(glm::normalize(q0)), w0_(w0) {
    const glm::dvec3 wb = glm::conjugate(q0_) * w0; // body (principal) axes
    L_ = q0_ * (I * wb);
    const double tol = equal_moments * I.z;
    const bool low_equal = I.y - I.x <= tol, high_equal = I.z - I.y <= tol;
    // Rotation about one principal axis alone is steady (Euler's equations: each product
    // w_i w_j vanishes), as is any rotation of a spherical top. About the axis of the smallest
    // or the largest moment, which are stable, a tilt below 1e-15 stays below it, so such a
    // rotation is taken as steady (the elliptic form would divide by the tilt); about the
    // intermediate axis, which is unstable, only an exact one.
    int spinning = -1;
    const double tilt = 1e-15 * glm::length(wb);
    if (std::hypot(wb.y, wb.z) <= tilt) spinning = 0;
    if (std::hypot(wb.x, wb.y) <= tilt) spinning = 2;
    if (wb.x == 0.0 && wb.z == 0.0) spinning = 1;
    if ((low_equal && high_equal) || spinning >= 0) {
        kind_ = Kind::constant;
        return;
    }
    if (low_equal || high_equal) {
        // Symmetric top with symmetry axis s and I_perp the other moment: the world angular
        // velocity is L / I_perp + c e_s(t), c = w_s (I_perp - I_s) / I_perp, so that
        // R(t) = Rot(L, |L| t / I_perp) R0 Rot(e_s, c t) (the derivative of this product has
        // exactly that angular velocity, and e_s(t) = Rot(L, ...) R0 e_s).
        kind_ = Kind::symmetric;
        axis_ = low_equal ? 2 : 0;
        perp_ = low_equal ? 0.5 * (I.x + I.y) : 0.5 * (I.y + I.z);
        spin_ = wb[axis_] * (perp_ - I[axis_]) / perp_;
        return;
    }
    kind_ = Kind::asymmetric;
    // The body angular velocity circles the axis of the largest moment when L^2 >= 2 E I2,
    // else the smallest; L^2 - 2 E I2 = I1 (I1 - I2) w1^2 + I3 (I3 - I2) w3^2 without
    // cancellation. With c = axis 1 the frame (a, b, c) = (e3, e2, -e1) stays right-handed.
    const bool around_largest =
        I.x * (I.x - I.y) * wb.x * wb.x + I.z * (I.z - I.y) * wb.z * wb.z >= 0.0;
    glm::dvec3 w; // body angular velocity in abc
    if (around_largest) {
        to_principal_ = glm::dmat3(1.0);
        Ia_ = I.x, Ib_ = I.y, Ic_ = I.z;
        w = wb;
    } else {
        to_principal_ = glm::dmat3(glm::dvec3(0, 0, 1), glm::dvec3(0, 1, 0), glm::dvec3(-1, 0, 0));
        Ia_ = I.z, Ib_ = I.y, Ic_ = I.x;
        w = glm::transpose(to_principal_) * wb;
    }
    // D1 = 2 E Ic - L^2 and D2 = L^2 - 2 E Ia as sums of terms of one sign.
    const double D1 = Ia_ * (Ic_ - Ia_) * w.x * w.x + Ib_ * (Ic_ - Ib_) * w.y * w.y;
    const double D2 = Ib_ * (Ib_ - Ia_) * w.y * w.y + Ic_ * (Ic_ - Ia_) * w.z * w.z;
    // Landau & Lifshitz 37.10: w = (A cn u, B sn u, C dn u) with u = wp t, and
    // k^2 = (Ib - Ia) D1 / ((Ic - Ib) D2), each ratio below positive in both labelings.
    A_ = std::sqrt(D1 / (Ia_ * (Ic_ - Ia_)));
    B_ = std::sqrt(D1 / (Ib_ * (Ic_ - Ib_)));
    C_ = std::sqrt(D2 / (Ic_ * (Ic_ - Ia_)));
    // k'^2 = 1 - k^2 = (Ic - Ia) (Ic (Ic - Ib) wc^2 - Ia (Ib - Ia) wa^2) / ((Ic - Ib) D2): the
    // wb^2 terms cancel exactly, so a body near the separatrix (wa, wc small) keeps its k'.
    const double kc2 = std::max(
        0.0, (Ic_ - Ia_) * (Ic_ * (Ic_ - Ib_) * w.z * w.z - Ia_ * (Ib_ - Ia_) * w.x * w.x) /
                 ((Ic_ - Ib_) * D2));
    separatrix_ = !(kc2 > 0.0);
    // Signs from Euler's equations: with wc of sign s (dn > 0) and wa = sigma A cn,
    // Ib B wp = sigma s (Ic - Ia) C A, so wp has the sign of sigma s (Ic - Ia). Off the
    // separatrix sigma = 1 and the phase u0 puts cn and sn at wa / A and wb / B; on it cn > 0
    // always and sigma is the sign of wa.
    const double s = w.z > 0.0 ? 1.0 : -1.0;
    const double sigma = separatrix_ && w.x < 0.0 ? -1.0 : 1.0;
    wp_ = sigma * s * (Ic_ > Ia_ ? 1.0 : -1.0) * std::sqrt((Ic_ - Ib_) * D2 / (Ia_ * Ib_ * Ic_));
    C_ *= s;
    A_ *= sigma;
    // The precession angle about L: phi' = L (Ia wa^2 + Ib wb^2) / (Ia^2 wa^2 + Ib^2 wb^2)
    //   = L / Ic + L (Ic - Ia) / (Ia Ic) / (1 - n sn^2 u),  n = -Ic (Ib - Ia) / (Ia (Ic - Ib)),
    // so phi(t) = L (t - t0) / Ic + L (Ic - Ia) / (Ia Ic wp) (P(u) - P(u0)), P(u) = Pi(n; am u, k).
    n_ = -Ic_ * (Ib_ - Ia_) / (Ia_ * (Ic_ - Ib_));
    const double sn0 = w.y / B_, cn0 = w.x / A_, r0 = std::hypot(sn0, cn0);
    if (separatrix_) {
        // sn = tanh u, cn = dn = sech u (k = 1): no period, the body tends to the axis b.
        u0_ = std::atanh(std::clamp(sn0 / r0, -1.0 + 1e-16, 1.0 - 1e-16));
    } else {
        modulus_ = EllipticModulus(kc2);
        K_ = modulus_.quarter_period();
        Pi_ = modulus_.complete_third_kind(n_);
        // The amplitude of (sn0, cn0); for cn0 < 0, u0 = 2K - v with sn v = sn0, cn v = -cn0.
        const double sn = sn0 / r0, cn = std::abs(cn0) / r0;
        const double v = modulus_.first_kind(sn, cn, std::sqrt(cn * cn + kc2 * sn * sn));
        u0_ = cn0 >= 0.0 ? v : 2.0 * K_ - v;
    }
    Lnorm_ = glm::length(I * wb);
    double sn, cn, dn;
    elliptic_at(u0_, sn, cn, dn, P0_);
    // Q from the given w0 (not from the elliptic functions at u0, which differ from it by
    // their rounding, and by more where k is clamped) keeps L exactly where w0 puts it.
    const glm::dmat3 R0 = glm::mat3_cast(q0_) * to_principal_; // world <- abc at t0
    const glm::dvec3 Iabc(Ia_, Ib_, Ic_);
    Q_ = R0 * glm::transpose(to_intermediate(glm::normalize(Iabc * w)));
}

// sn, cn, dn of u and P(u) = integral_0^u du' / (1 - n sn^2 u'), with u reduced to r in
// [-K, K] by u = 2 K m + r (sn and cn change sign with each half period 2K, P grows by 2 Pi).
// On the separatrix P(u) = (u + sqrt(-n) atan(sqrt(-n) tanh u)) / (1 - n), from
// 1 / ((1 - y^2)(1 - n y^2)) = (1 / (1 - y^2) - n / (1 - n y^2)) / (1 - n) with y = tanh u.
void FreeRotation::elliptic_at(double u, double &sn, double &cn, double &dn, double &P) const {
    if (separatrix_) {
        sn = std::tanh(u);
        cn = dn = 1.0 / std::cosh(u);
        const double root = std::sqrt(-n_);
        P = (u + root * std::atan(root * sn)) / (1.0 - n_);
        return;
    }
    const double m = std::round(u / (2.0 * K_));
    const double r = u - 2.0 * K_ * m;
    modulus_.sn_cn_dn(r, sn, cn, dn);
    P = 2.0 * m * Pi_ + modulus_.third_kind(n_, sn, cn, dn);
    if (std::fmod(std::abs(m), 2.0) == 1.0) {
        sn = -sn;
        cn = -cn;
    }
}

double FreeRotation::body_period() const {
    switch (kind_) {
    case Kind::asymmetric:
        return separatrix_ ? std::numeric_limits<double>::infinity() : 4.0 * K_ / std::abs(wp_);
    case Kind::symmetric:
        return spin_ == 0.0 ? 0.0 : 2.0 * M_PI / std::abs(spin_);
    default:
        return 0.0;
    }
}

void FreeRotation::evaluate(double t, glm::dquat &q, glm::dvec3 &w) const {
    const double dt = t - t0_;
    switch (kind_) {
    case Kind::constant:
        w = w0_;
        q = glm::normalize(rotation_by(w0_ * dt) * q0_);
        return;
    case Kind::symmetric: {
        glm::dvec3 axis(0.0);
        axis[axis_] = 1.0;
        q = glm::normalize(rotation_by(L_ * (dt / perp_)) * q0_ * rotation_by(axis * (spin_ * dt)));
        w = L_ / perp_ + spin_ * (q * axis);
        return;
    }
    case Kind::asymmetric: {
        double sn, cn, dn, P;
        elliptic_at(wp_ * dt + u0_, sn, cn, dn, P);
        const glm::dvec3 wabc(A_ * cn, B_ * sn, C_ * dn);
        const glm::dvec3 Iabc(Ia_, Ib_, Ic_);
        const double phi = Lnorm_ * dt / Ic_ + Lnorm_ * (Ic_ - Ia_) / (Ia_ * Ic_ * wp_) * (P - P0_);
        const double c = std::cos(phi), s = std::sin(phi);
        const glm::dmat3 Rz(glm::dvec3(c, s, 0), glm::dvec3(-s, c, 0), glm::dvec3(0, 0, 1));
        const glm::dmat3 R = Q_ * Rz * to_intermediate(glm::normalize(Iabc * wabc));
        w = R * wabc;
        q = quaternion_of(R * glm::transpose(to_principal_));
        return;
    }
    }
}

glm::dquat quaternion_of(const glm::dmat3 &m) {
    // Shepperd: take the largest of 4w^2, 4x^2, 4y^2, 4z^2 to divide by. m[c][r] is column c.
    const double trace = m[0][0] + m[1][1] + m[2][2];
    glm::dquat q;
    if (trace >= m[0][0] && trace >= m[1][1] && trace >= m[2][2]) {
        const double s = 2.0 * std::sqrt(1.0 + trace);
        q = glm::dquat(0.25 * s, (m[1][2] - m[2][1]) / s, (m[2][0] - m[0][2]) / s,
                       (m[0][1] - m[1][0]) / s);
    } else if (m[0][0] >= m[1][1] && m[0][0] >= m[2][2]) {
        const double s = 2.0 * std::sqrt(1.0 + m[0][0] - m[1][1] - m[2][2]);
        q = glm::dquat((m[1][2] - m[2][1]) / s, 0.25 * s, (m[1][0] + m[0][1]) / s,
                       (m[2][0] + m[0][2]) / s);
    } else if (m[1][1] >= m[2][2]) {
        const double s = 2.0 * std::sqrt(1.0 + m[1][1] - m[0][0] - m[2][2]);
        q = glm::dquat((m[2][0] - m[0][2]) / s, (m[1][0] + m[0][1]) / s, 0.25 * s,
                       (m[2][1] + m[1][2]) / s);
    } else {
        const double s = 2.0 * std::sqrt(1.0 + m[2][2] - m[0][0] - m[1][1]);
        q = glm::dquat((m[0][1] - m[1][0]) / s, (m[2][0] + m[0][2]) / s, (m[2][1] + m[1][2]) / s,
                       0.25 * s);
    }
    if (q.w < 0.0) q = -q;
    return glm::normalize(q);
}

} // namespace ani
