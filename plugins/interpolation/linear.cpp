#include "linear.hpp"

#include "angles.hpp"
#include "rotation.hpp"

namespace interp {

double lerp(double prev, double next, double s) { return prev + s * (next - prev); }

double lerp_angle(double prev, double next, double turn, double s) {
    return wrap_degrees(prev + s * turn_delta(prev, next, turn));
}

namespace {

// POSITION, SCALE, CAMERA_POSITION: each component on its own straight line.
class LinearVectorCurve : public Curve {
  public:
    explicit LinearVectorCurve(const ani_key *keys) : keys_(keys) {}

    void key_value(uint32_t k, double value[4]) const override {
        for (int c = 0; c < 3; ++c) value[c] = keys_[k].value[c];
        value[3] = 0.0;
    }

    void segment(uint32_t k, double tau, double value[4], double rate[4]) const override {
        const ani_key &prev = keys_[k], &next = keys_[k + 1];
        const double dt = next.time - prev.time;
        const double s = tau / dt;
        for (int c = 0; c < 3; ++c) {
            value[c] = lerp(prev.value[c], next.value[c], s);
            rate[c] = (next.value[c] - prev.value[c]) / dt;
        }
        value[3] = rate[3] = 0.0;
    }

  private:
    const ani_key *keys_;
};

// ANGLES: each axis turns by turn_delta, in the direction recorded on the segment's next key.
class LinearAngleCurve : public Curve {
  public:
    explicit LinearAngleCurve(const ani_key *keys) : keys_(keys) {}

    void key_value(uint32_t k, double value[4]) const override {
        // Wrapping leaves an angle already in [0, 360) as it is, bit for bit.
        for (int c = 0; c < 3; ++c) value[c] = wrap_degrees(keys_[k].value[c]);
        value[3] = 0.0;
    }

    void segment(uint32_t k, double tau, double value[4], double rate[4]) const override {
        const ani_key &prev = keys_[k], &next = keys_[k + 1];
        const double dt = next.time - prev.time;
        const double s = tau / dt;
        for (int c = 0; c < 3; ++c) {
            const double from = wrap_degrees(prev.value[c]);
            const double delta = turn_delta(from, wrap_degrees(next.value[c]), next.turn[c]);
            value[c] = wrap_degrees(from + s * delta);
            rate[c] = delta / dt;
        }
        value[3] = rate[3] = 0.0;
    }

  private:
    const ani_key *keys_;
};

} // namespace

void evaluate_linear(const ani_channel &channel, const double *times, uint32_t count, double *values,
                     double *rates) {
    const auto on = [&](const Curve &curve) {
        evaluate_curve(curve, channel.keys, channel.key_count, times, count, values, rates);
    };
    switch (channel.kind) {
    case ANI_CHANNEL_ANGLES: return on(LinearAngleCurve(channel.keys));
    // A blend tangent of 1 is the blend s itself: plain slerp.
    case ANI_CHANNEL_CAMERA_ROTATION: return on(SlerpCurve(channel.keys, channel.key_count, 1.0));
    default: return on(LinearVectorCurve(channel.keys));
    }
}

} // namespace interp
