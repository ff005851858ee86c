// Roots of the polynomials that contact between bodies on parabolic paths leads to: the
// squared distance between two points under constant accelerations is a quartic in time.
#pragma once

#include <array>
#include <optional>

namespace physics_custom {

// c[0] + c[1] t + c[2] t^2 + c[3] t^3 + c[4] t^4.
using Quartic = std::array<double, 5>;

double evaluate(const Quartic &c, double t);
Quartic derivative(const Quartic &c);

// The smallest t in [lo, hi] where p changes sign from positive to non-positive (the first time
// two bodies that are apart come into contact), found exactly up to rounding: the critical
// points split [lo, hi] into monotone pieces, and each piece with a sign change is bisected to
// the last bit. A touch without crossing (a double root) counts. None if p stays positive.
std::optional<double> first_contact(const Quartic &p, double lo, double hi);

} // namespace physics_custom
