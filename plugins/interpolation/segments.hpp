// Evaluating a keyed channel at many sorted times: one sweep over the keys finds each time's
// segment (O(keys + times)), and a Curve says what happens inside a segment.
#pragma once

#include <animator/interpolator.h>

#include <cstdint>

namespace interp {

// Where a time lies among the keys.
struct Location {
    enum Kind { before, at_key, inside, after } kind;
    uint32_t key; // at_key: the key; inside: the segment (from this key to the next)
    double tau;   // inside: seconds since the segment's first key
};

// Locates times given in non-decreasing order, moving forward through the keys only.
class SegmentSweep {
  public:
    SegmentSweep(const ani_key *keys, uint32_t key_count) : keys_(keys), count_(key_count) {}
    // Throws std::logic_error when t is earlier than the previous time.
    Location locate(double t);

  private:
    const ani_key *keys_;
    uint32_t count_;
    uint32_t k_ = 0;
    double last_t_ = 0.0;
    bool started_ = false;
};

// One interpolation scheme applied to one validated channel. Values and rates have 4 entries;
// three-component channels leave the fourth at 0.
class Curve {
  public:
    virtual ~Curve() = default;
    // Key k's value, exactly as the keyframe holds it: keyframes are reached bit for bit.
    virtual void key_value(uint32_t k, double value[4]) const = 0;
    // Value and rate tau seconds into segment k (key k to key k + 1), 0 <= tau <= its length.
    virtual void segment(uint32_t k, double tau, double value[4], double rate[4]) const = 0;
    // The rate before the first key, and at any time when there is only one key.
    virtual void resting_rate(double rate[4]) const;
};

// Writes 4 values and 4 rates per time. Before the first key: the first key's value and the
// resting rate. At a key: its value, and the rate of the segment it starts. At or after the last
// key: its value and the rate the last segment ends with, from which the physics backend
// continues a Dynamics model.
void evaluate_curve(const Curve &curve, const ani_key *keys, uint32_t key_count,
                    const double *times, uint32_t count, double *values, double *rates);

} // namespace interp
