// Keys that hold motion as glTF animation samplers can (docs/export.md): a position or scale as
// cubic Hermite keys (glTF's CUBICSPLINE: a value, and the derivatives per second coming in and
// going out), exact for any motion that is a polynomial of degree 3 or less between two keys
// (the parabola of free flight, the seed's linear keys, the smooth and kinematic interpolators'
// spans); a rotation as unit quaternions slerped between keys (glTF's LINEAR), sampled where it is
// not a turn about a fixed axis at a constant rate, so that it strays less than a bound.
//
// Plain math over functions of time: no glTF, no document.
#pragma once

#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>

#include <cstddef>
#include <functional>
#include <vector>

namespace animator::motion_keys {

struct VecKey {
    double t = 0.0;
    glm::dvec3 in{0.0}; // derivative per second arriving at the key
    glm::dvec3 value{0.0};
    glm::dvec3 out{0.0}; // derivative per second leaving it
};

// One smooth piece of motion: the value at any time of a closed interval [t0, t1], and, when it
// knows it, the derivative there (the one-sided derivative at the ends).
struct Piece {
    std::function<glm::dvec3(double)> value;
    std::function<glm::dvec3(double)> rate; // empty: taken from the cubic through 4 values
};

// What adding pieces found.
struct PieceStats {
    std::size_t exact = 0;   // pieces held by one Hermite span (to `tolerance`)
    std::size_t sampled = 0; // pieces that had to be split
};

// Appends the keys of `piece` over [t0, t1] to `keys` (whose last key, if any, is at t0: its
// out-tangent is set, its value kept). The Hermite span through the ends' values and
// derivatives is checked at 7 inner points; where it strays more than `tolerance`, the piece is
// split in two, down to spans of `min_span` seconds.
void append_piece(std::vector<VecKey> &keys, double t0, double t1, const Piece &piece,
                  double tolerance, PieceStats *stats = nullptr, double min_span = 1e-6);

// Whether the keys are straight lines between each other (every tangent the chord's slope,
// within `tolerance` of position along the span): then glTF's LINEAR holds them.
bool is_linear(const std::vector<VecKey> &keys, double tolerance);

// The value of the Hermite keys at t (between the first and the last key), as glTF evaluates
// CUBICSPLINE: for tests and for checks.
glm::dvec3 hermite_at(const std::vector<VecKey> &keys, double t);

struct QuatKey {
    double t = 0.0;
    glm::dquat q{1.0, 0.0, 0.0, 0.0};
};

// The largest angle, in radians, between two keys (slerp takes the shorter way; keys at most 90
// degrees apart leave no doubt, and keep the components' linear blend that some clients use close).
constexpr double kMaxKeyTurn = 1.5707963267948966;

// Appends the keys of a continuous rotation over [t0, t1] (as append_piece): slerp between keys
// strays at most `tolerance` radians from `rotation` at 7 inner points of every span, and no two
// keys are more than kMaxKeyTurn apart. Each key's sign is chosen to be nearest the one before.
void append_rotation(std::vector<QuatKey> &keys, double t0, double t1,
                     const std::function<glm::dquat(double)> &rotation, double tolerance,
                     PieceStats *stats = nullptr, double min_span = 1e-6);

// Slerp of the keys at t, as glTF evaluates LINEAR rotations.
glm::dquat slerp_at(const std::vector<QuatKey> &keys, double t);

// The angle in radians between two orientations (q and -q are one).
double angle_between(const glm::dquat &a, const glm::dquat &b);

// Keys as glTF stores them: times as float32, shifted by -`origin`, strictly increasing. Keys that
// float32 cannot tell apart from the one before are merged into it (its in-tangent and value
// stay, the out-tangent is the last one's; a rotation key keeps the first). Returns how many were
// merged.
std::size_t merge_float_times(std::vector<VecKey> &keys, double origin, std::vector<float> &times);
std::size_t merge_float_times(std::vector<QuatKey> &keys, double origin, std::vector<float> &times);

} // namespace animator::motion_keys
