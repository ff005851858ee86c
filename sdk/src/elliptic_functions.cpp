#include "animator/elliptic_functions.hpp"

#include <boost/math/special_functions/ellint_rf.hpp>
#include <boost/math/special_functions/ellint_rj.hpp>

#include <cmath>

namespace ani {

EllipticModulus::EllipticModulus(double kc2) : kc2_(kc2) {
    // K = pi / (2 AGM(1, k')) (Gauss).
    double a = 1.0, b = std::sqrt(kc2);
    for (int i = 0; i < 64 && std::abs(a - b) > 1e-16 * a; ++i) {
        const double m = 0.5 * (a + b);
        b = std::sqrt(a * b);
        a = m;
    }
    K_ = M_PI / (a + b);
}

void EllipticModulus::sn_cn_dn(double u, double &sn, double &cn, double &dn) const {
    // Bulirsch (Numer. Math. 7, 1965, 78), as in Numerical Recipes' sncndn: the descending
    // Gauss transformation driven by k'^2 directly.
    double em[32], en[32];
    double emc = kc2_, a = 1.0, c = 1.0;
    dn = 1.0;
    int l = 0;
    for (int i = 0; i < 32; ++i) {
        l = i;
        em[i] = a;
        en[i] = emc = std::sqrt(emc);
        c = 0.5 * (a + emc);
        if (std::abs(a - emc) <= 1e-9 * a) break;
        emc *= a;
        a = c;
    }
    u *= c;
    sn = std::sin(u);
    cn = std::cos(u);
    if (sn != 0.0) {
        a = cn / sn;
        c *= a;
        for (int ii = l; ii >= 0; --ii) {
            const double b = em[ii];
            a *= c;
            c *= dn;
            dn = (en[ii] + a) / (b + a);
            a = c / b;
        }
        a = 1.0 / std::sqrt(c * c + 1.0);
        sn = sn >= 0.0 ? a : -a;
        cn = c * sn;
    }
}

double EllipticModulus::first_kind(double sn, double cn, double dn) const {
    return sn * boost::math::ellint_rf(cn * cn, dn * dn, 1.0);
}

double EllipticModulus::third_kind(double n, double sn, double cn, double dn) const {
    const double s3 = sn * sn * sn;
    return first_kind(sn, cn, dn) +
           n / 3.0 * s3 * boost::math::ellint_rj(cn * cn, dn * dn, 1.0, 1.0 - n * sn * sn);
}

double EllipticModulus::complete_third_kind(double n) const {
    return K_ + n / 3.0 * boost::math::ellint_rj(0.0, kc2_, 1.0, 1.0 - n);
}

} // namespace ani
