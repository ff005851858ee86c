// Jacobi elliptic functions and Carlson-form integrals from k'^2 (elliptic_functions.hpp)
// against Boost.Math's own (an independent algorithm) for ordinary moduli, and against the
// limits of Abramowitz & Stegun 16.15 and the quarter-period identities near k = 1.
#include "animator/elliptic_functions.hpp"

#include <boost/math/special_functions/ellint_1.hpp>
#include <boost/math/special_functions/ellint_3.hpp>
#include <boost/math/special_functions/jacobi_elliptic.hpp>
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

using namespace ani;

TEST_CASE("elliptic functions: sn, cn, dn, K, F and Pi agree with Boost.Math") {
    double worst = 0.0;
    for (double k : {0.0, 0.1, 0.5, 0.9, 0.999}) {
        const EllipticModulus modulus((1 - k) * (1 + k));
        const double K = modulus.quarter_period();
        worst = std::max(worst, std::abs(K - boost::math::ellint_1(k)) / K);
        for (double n : {-3.0, -0.5, 0.4}) {
            const double P = boost::math::ellint_3(k, n);
            worst = std::max(worst, std::abs(modulus.complete_third_kind(n) - P) / std::abs(P));
        }
        // At u = +-K itself Boost 1.74's dn is off (0.99599 for k = 0.1, against k' = 0.99499):
        // compared there with dn(K) = k' (A&S 16.5.3) instead.
        double sn, cn, dn;
        modulus.sn_cn_dn(K, sn, cn, dn);
        worst = std::max(
            {worst, std::abs(sn - 1.0), std::abs(cn), std::abs(dn - std::sqrt((1 - k) * (1 + k)))});
        for (int i = -19; i <= 19; ++i) {
            const double u = K * i / 20.0;
            double bcn, bdn;
            modulus.sn_cn_dn(u, sn, cn, dn);
            const double bsn = boost::math::jacobi_elliptic(k, u, &bcn, &bdn);
            worst = std::max({worst, std::abs(sn - bsn), std::abs(cn - bcn), std::abs(dn - bdn)});
            const double phi = std::atan2(sn, cn);
            worst =
                std::max(worst, std::abs(modulus.first_kind(sn, cn, dn) - u) / std::max(1.0, K));
            for (double n : {-3.0, -0.5, 0.4}) {
                const double P = boost::math::ellint_3(k, n, phi);
                worst = std::max(worst, std::abs(modulus.third_kind(n, sn, cn, dn) - P) /
                                            std::max(1.0, K));
            }
        }
    }
    INFO("largest difference " << worst);
    REQUIRE(worst <= 1e-14);
}

TEST_CASE("elliptic functions: near k = 1 the complement keeps its digits") {
    // k'^2 = 1e-20: K = ln(4/k') + O(k'^2 ln k') (A&S 17.3.26) = ln(4e10); for u well inside
    // (0, K) sn = tanh u + O(k'^2 e^{2u}) (A&S 16.15), and at the quarter period dn(K) = k',
    // sn(K - v) = cn(v) / dn(v), dn(K - v) = k' / dn(v) (A&S 16.8).
    const double kc2 = 1e-20, kc = 1e-10;
    const EllipticModulus modulus(kc2);
    const double K = modulus.quarter_period();
    REQUIRE(std::abs(K - std::log(4.0 / kc)) <= 1e-14 * K);
    double worst = 0.0;
    for (double u = 0.0; u <= 6.0; u += 0.25) {
        double sn, cn, dn;
        modulus.sn_cn_dn(u, sn, cn, dn);
        worst = std::max({worst, std::abs(sn - std::tanh(u)), std::abs(cn - 1 / std::cosh(u)),
                          std::abs(dn - 1 / std::cosh(u))});
    }
    INFO("against tanh and sech: " << worst);
    REQUIRE(worst <= 1e-14);
    for (double v : {0.0, 0.5, 2.0}) {
        double sn, cn, dn, vsn, vcn, vdn;
        modulus.sn_cn_dn(K - v, sn, cn, dn);
        modulus.sn_cn_dn(v, vsn, vcn, vdn);
        INFO("v " << v << ": dn " << dn << " want " << kc / vdn);
        REQUIRE(std::abs(sn - vcn / vdn) <= 1e-14);
        REQUIRE(std::abs(dn - kc / vdn) <= 1e-6 * kc / vdn); // the rounding of K - v, times K
    }
}
