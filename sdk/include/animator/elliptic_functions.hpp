// Jacobi elliptic functions and the elliptic integrals of the exact torque-free rotation
// (free_rotation.hpp), for a modulus given by its complement k' = sqrt(1 - k^2), so that a
// body spun within a hair of the separatrix (k' far below sqrt(eps)) keeps its true k.
#pragma once

namespace ani {

class EllipticModulus {
  public:
    explicit EllipticModulus(double k_complement_squared); // k'^2 in (0, 1]

    double quarter_period() const { return K_; } // K(k)
    // sn, cn, dn of u, for |u| <= K (Bulirsch's descending Gauss transformation, from k'^2).
    void sn_cn_dn(double u, double &sn, double &cn, double &dn) const;
    // F(phi, k) for the amplitude with sin phi = sn, cos phi = cn >= 0, dn^2 = 1 - k^2 sn^2
    // (Carlson: sn R_F(cn^2, dn^2, 1)).
    double first_kind(double sn, double cn, double dn) const;
    // Pi(n; phi, k) = integral_0^phi dt / ((1 - n sin^2 t) sqrt(1 - k^2 sin^2 t)) for the same
    // amplitude (Carlson: F + n/3 sn^3 R_J(cn^2, dn^2, 1, 1 - n sn^2)), and at phi = pi/2.
    double third_kind(double n, double sn, double cn, double dn) const;
    double complete_third_kind(double n) const;

  private:
    double kc2_, K_;
};

} // namespace ani
