#include "polynomial.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>

namespace physics_custom {

double evaluate(const Quartic &c, double t) {
    return (((c[4] * t + c[3]) * t + c[2]) * t + c[1]) * t + c[0];
}

Quartic derivative(const Quartic &c) {
    return {c[1], 2.0 * c[2], 3.0 * c[3], 4.0 * c[4], 0.0};
}

namespace {

int degree(const Quartic &c) {
    for (int d = 4; d > 0; --d)
        if (c[static_cast<size_t>(d)] != 0.0) return d;
    return 0;
}

// A root of p in [lo, hi] where p is monotone and p(lo), p(hi) have opposite signs (or one is
// zero): bisection to adjacent doubles, keeping the side where p is still positive.
double bisect(const Quartic &p, double lo, double hi) {
    double flo = evaluate(p, lo);
    for (int i = 0; i < 200; ++i) {
        const double mid = 0.5 * (lo + hi);
        if (mid <= lo || mid >= hi) break;
        const double fmid = evaluate(p, mid);
        if ((fmid > 0.0) == (flo > 0.0)) {
            lo = mid;
            flo = fmid;
        } else {
            hi = mid;
        }
    }
    return hi; // the first double at which p is no longer positive
}

// A few sorted doubles without touching the heap (a quartic has at most 3 critical points).
struct Points {
    std::array<double, 8> at{};
    std::size_t size = 0;
    void push(double x) {
        if (size < at.size()) at[size++] = x;
    }
    const double *begin() const { return at.data(); }
    const double *end() const { return at.data() + size; }
};

// The roots of p in [lo, hi] that delimit its monotone pieces: the critical points, found
// recursively from the roots of the derivative (all of them, sorted).
void critical_points(const Quartic &p, double lo, double hi, Points &out) {
    const Quartic d = derivative(p);
    if (degree(d) == 0) return;
    Points inner;
    critical_points(d, lo, hi, inner); // where d itself turns
    Points edges;
    edges.push(lo);
    for (double x : inner) edges.push(x);
    edges.push(hi);
    for (size_t i = 0; i + 1 < edges.size; ++i) {
        const double a = edges.at[i], b = edges.at[i + 1];
        const double fa = evaluate(d, a), fb = evaluate(d, b);
        if (fa == 0.0) out.push(a);
        if ((fa < 0.0 && fb > 0.0) || (fa > 0.0 && fb < 0.0)) {
            // d is monotone on [a, b] and changes sign: one root.
            double x = a, y = b, fx = fa;
            for (int k = 0; k < 200; ++k) {
                const double m = 0.5 * (x + y);
                if (m <= x || m >= y) break;
                const double fm = evaluate(d, m);
                if ((fm > 0.0) == (fx > 0.0)) {
                    x = m;
                    fx = fm;
                } else {
                    y = m;
                }
            }
            out.push(0.5 * (x + y));
        }
    }
    if (evaluate(d, hi) == 0.0) out.push(hi);
    std::sort(out.at.begin(), out.at.begin() + static_cast<std::ptrdiff_t>(out.size));
    out.size = static_cast<std::size_t>(
        std::unique(out.at.begin(), out.at.begin() + static_cast<std::ptrdiff_t>(out.size)) -
        out.at.begin());
}

} // namespace

std::optional<double> first_contact(const Quartic &p, double lo, double hi) {
    if (!(lo <= hi)) return std::nullopt;
    if (evaluate(p, lo) <= 0.0) return lo;
    Points points;
    points.push(lo);
    Points critical;
    critical_points(p, lo, hi, critical);
    for (double c : critical)
        if (c > lo && c < hi) points.push(c);
    points.push(hi);
    for (size_t i = 0; i + 1 < points.size; ++i) {
        const double a = points.at[i], b = points.at[i + 1];
        if (evaluate(p, b) <= 0.0) return bisect(p, a, b); // p is monotone on [a, b]
    }
    return std::nullopt;
}

} // namespace physics_custom
