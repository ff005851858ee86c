#include "polynomial.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace physics_custom {

double evaluate(const Quartic &c, double t) {
    return (((c[4] * t + c[3]) * t + c[2]) * t + c[1]) * t + c[0];
}

Quartic derivative(const Quartic &c) { return {c[1], 2.0 * c[2], 3.0 * c[3], 4.0 * c[4], 0.0}; }

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

// The roots of p in [lo, hi] that delimit its monotone pieces: the critical points, found
// recursively from the roots of the derivative (all of them, sorted).
void critical_points(const Quartic &p, double lo, double hi, std::vector<double> &out) {
    const Quartic d = derivative(p);
    if (degree(d) == 0) return;
    std::vector<double> inner;
    critical_points(d, lo, hi, inner); // where d itself turns
    std::vector<double> edges = {lo};
    edges.insert(edges.end(), inner.begin(), inner.end());
    edges.push_back(hi);
    for (size_t i = 0; i + 1 < edges.size(); ++i) {
        const double a = edges[i], b = edges[i + 1];
        const double fa = evaluate(d, a), fb = evaluate(d, b);
        if (fa == 0.0) out.push_back(a);
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
            out.push_back(0.5 * (x + y));
        }
    }
    if (evaluate(d, hi) == 0.0) out.push_back(hi);
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
}

} // namespace

std::optional<double> first_contact(const Quartic &p, double lo, double hi) {
    if (!(lo <= hi)) return std::nullopt;
    if (evaluate(p, lo) <= 0.0) return lo;
    std::vector<double> points = {lo};
    std::vector<double> critical;
    critical_points(p, lo, hi, critical);
    for (double c : critical)
        if (c > lo && c < hi) points.push_back(c);
    points.push_back(hi);
    for (size_t i = 0; i + 1 < points.size(); ++i) {
        const double a = points[i], b = points[i + 1];
        if (evaluate(p, b) <= 0.0) return bisect(p, a, b); // p is monotone on [a, b]
    }
    return std::nullopt;
}

} // namespace physics_custom
