// A ball coming to rest on a flat static support (issue 18): with restitution e < 1 it bounces
// infinitely often in finite time. Leaving the face at normal speed v under gravity's component
// g_n into the face, it lands after 2 v / g_n and leaves again at e v, so the bounces after this
// one take sum_k 2 e^k v / g_n = 2 v / (g_n (1 - e)) in all: the accumulation time. Once the
// highest of the bounces left, v^2 / (2 g_n), is below kZenoHeight times the size of the
// coordinates (below what a double can place), the bake puts the ball on the support at once
// and reports it resting (or sliding, frictionless) from the exact accumulation time: no event
// ever gets shorter than that.
#pragma once

namespace physics_custom {

inline constexpr double kZenoHeight = 1e-9; // relative to max(1, |centre|)

// The time the bounces that start at t with normal speed v (> 0) accumulate at.
inline double zeno_accumulation(double t, double v, double g_n, double e) {
    return t + 2.0 * v / (g_n * (1.0 - e));
}

// Whether the bounces left are too small to follow (see above).
inline bool zeno_settles(double v, double g_n, double e, double scale) {
    return e < 1.0 && g_n > 0.0 && v >= 0.0 && v * v / (2.0 * g_n) <= kZenoHeight * scale;
}

} // namespace physics_custom
