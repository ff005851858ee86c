// Unit quaternions for the camera's rotation, and the spherical linear interpolation (slerp)
// between two of them.
#pragma once

#include "segments.hpp"

#include <array>
#include <vector>

namespace interp {

// w + xi + yj + zk. A unit quaternion q turns a vector v (body frame) into q v q* (world frame).
struct Quat {
    double w, x, y, z;
};

struct Vec3 {
    double x, y, z;
};

Quat multiply(const Quat &a, const Quat &b);
Quat conjugate(const Quat &q);
double dot(const Quat &a, const Quat &b);
double norm(const Quat &q);
// q / |q|; q must not be zero.
Quat normalized(const Quat &q);
// The vector v turned by the unit quaternion q.
Vec3 rotate(const Quat &q, const Vec3 &v);
// The 3x3 rotation matrix of the unit quaternion q, row-major.
std::array<double, 9> to_matrix(const Quat &q);

// The slerp from one orientation to another along the shorter arc, prepared once per segment.
class Slerp {
  public:
    Slerp(const Quat &from, const Quat &to);
    // The orientation a fraction u in [0, 1] of the way; a unit quaternion.
    Quat at(double u) const;
    // The whole rotation from `from` to `to` as a vector in the world frame: its direction is the
    // axis and its length the angle in radians (at most pi). The angular velocity is this times
    // du/dt: slerp turns about one fixed axis at a steady rate.
    Vec3 rotation_vector() const { return rotation_; }
    // The angle of the whole rotation in radians, in [0, pi].
    double angle() const { return angle_; }

  private:
    Quat from_;
    Vec3 v_;          // the vector part of from* to (the rotation in from's body frame)
    double sin_half_; // |v_|, the sine of half the angle
    double angle_;
    Vec3 rotation_;
};

// The camera's rotation between keys: per segment, the slerp from one key's quaternion to the
// next's, at the segment's fraction s passed through the Hermite blend with end derivative
// `blend_tangent` (1: s itself, steady turning; 0: smoothstep, easing in and out of each key).
// The rate is the angular velocity in rad/s, world frame, in rate[0..2].
class SlerpCurve : public Curve {
  public:
    SlerpCurve(const ani_key *keys, uint32_t key_count, double blend_tangent);
    void key_value(uint32_t k, double value[4]) const override;
    void segment(uint32_t k, double tau, double value[4], double rate[4]) const override;

  private:
    const ani_key *keys_;
    double blend_tangent_;
    std::vector<Slerp> slerps_;
};

} // namespace interp
