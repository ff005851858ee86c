#include "rotation.hpp"

#include "hermite.hpp"

#include <cmath>

namespace interp {

namespace {
// Below this sine of half the angle (an angle of about 2e-12 rad) the two orientations are the
// same for every purpose; the small-angle limits replace ratios whose denominator is ~0.
constexpr double kTinySinHalf = 1e-12;

Quat quat_of(const ani_key &key) { return {key.value[0], key.value[1], key.value[2], key.value[3]}; }
} // namespace

Quat multiply(const Quat &a, const Quat &b) {
    return {a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z,
            a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
            a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x,
            a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w};
}

Quat conjugate(const Quat &q) { return {q.w, -q.x, -q.y, -q.z}; }

double dot(const Quat &a, const Quat &b) { return a.w * b.w + a.x * b.x + a.y * b.y + a.z * b.z; }

double norm(const Quat &q) { return std::sqrt(dot(q, q)); }

Quat normalized(const Quat &q) {
    const double n = norm(q);
    return {q.w / n, q.x / n, q.y / n, q.z / n};
}

Vec3 rotate(const Quat &q, const Vec3 &v) {
    const Quat r = multiply(multiply(q, Quat{0.0, v.x, v.y, v.z}), conjugate(q));
    return {r.x, r.y, r.z};
}

std::array<double, 9> to_matrix(const Quat &q) {
    const double w = q.w, x = q.x, y = q.y, z = q.z;
    return {1 - 2 * (y * y + z * z), 2 * (x * y - w * z),     2 * (x * z + w * y),
            2 * (x * y + w * z),     1 - 2 * (x * x + z * z), 2 * (y * z - w * x),
            2 * (x * z - w * y),     2 * (y * z + w * x),     1 - 2 * (x * x + y * y)};
}

Slerp::Slerp(const Quat &from, const Quat &to) : from_(normalized(from)) {
    Quat target = normalized(to);
    // q and -q are the same orientation; of the two arcs to it, take the one under half a turn.
    if (dot(from_, target) < 0.0) target = {-target.w, -target.x, -target.y, -target.z};
    // The rotation still to do, seen from `from`: cos(angle/2) + sin(angle/2) axis. Its w is the
    // dot product, >= 0 now, so the angle is in [0, pi].
    const Quat r = multiply(conjugate(from_), target);
    v_ = {r.x, r.y, r.z};
    sin_half_ = std::sqrt(v_.x * v_.x + v_.y * v_.y + v_.z * v_.z);
    angle_ = 2.0 * std::atan2(sin_half_, r.w);
    // The axis in the world frame is `from` turning the body-frame axis; angle / sin(angle/2)
    // tends to 2 as the angle vanishes.
    const double scale = sin_half_ > kTinySinHalf ? angle_ / sin_half_ : 2.0;
    const Vec3 world = rotate(from_, v_);
    rotation_ = {scale * world.x, scale * world.y, scale * world.z};
}

Quat Slerp::at(double u) const {
    const double half = 0.5 * u * angle_;
    // sin(u angle/2) / sin(angle/2) tends to u as the angle vanishes.
    const double k = sin_half_ > kTinySinHalf ? std::sin(half) / sin_half_ : u;
    const Quat step{std::cos(half), k * v_.x, k * v_.y, k * v_.z};
    // Normalising removes the rounding of the products, so the matrix stays orthonormal.
    return normalized(multiply(from_, step));
}

SlerpCurve::SlerpCurve(const ani_key *keys, uint32_t key_count, double blend_tangent)
    : keys_(keys), blend_tangent_(blend_tangent) {
    slerps_.reserve(key_count - 1);
    for (uint32_t k = 0; k + 1 < key_count; ++k) slerps_.emplace_back(quat_of(keys[k]), quat_of(keys[k + 1]));
}

void SlerpCurve::key_value(uint32_t k, double value[4]) const {
    for (int c = 0; c < 4; ++c) value[c] = keys_[k].value[c];
}

void SlerpCurve::segment(uint32_t k, double tau, double value[4], double rate[4]) const {
    const double dt = keys_[k + 1].time - keys_[k].time;
    const ValueRate blend = hermite_blend(tau / dt, blend_tangent_);
    const Quat q = slerps_[k].at(blend.value);
    value[0] = q.w;
    value[1] = q.x;
    value[2] = q.y;
    value[3] = q.z;
    // Slerp turns about one world axis, so the angular velocity is the whole rotation vector
    // times d(blend)/dt = blend'(s) / dt.
    const Vec3 w = slerps_[k].rotation_vector();
    const double per_second = blend.rate / dt;
    rate[0] = w.x * per_second;
    rate[1] = w.y * per_second;
    rate[2] = w.z * per_second;
    rate[3] = 0.0;
}

} // namespace interp
