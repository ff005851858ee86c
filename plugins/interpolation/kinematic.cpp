#include "kinematic.hpp"

#include <array>

namespace interp {

std::vector<KinematicSegment> kinematic_segments(const std::vector<double> &times,
                                                 const std::vector<double> &positions,
                                                 double initial_velocity) {
    std::vector<KinematicSegment> segments;
    if (times.size() < 2) return segments;
    segments.reserve(times.size() - 1);
    // Seed, "Keyframe Interpolation with Kinematic Equations": d = v0 t + a t^2 / 2 rearranged
    // gives prev.a = 2 (prev.d - t prev.v0) / t^2, and new.v0 = prev.v0 + t prev.a. Each segment
    // is fixed by its start velocity alone, so an uneven key can make the next segments
    // overshoot and oscillate (docs/interpolation.md).
    double v0 = initial_velocity;
    for (size_t i = 0; i + 1 < times.size(); ++i) {
        const double dt = times[i + 1] - times[i];
        const double d = positions[i + 1] - positions[i];
        const double a = 2.0 * (d - v0 * dt) / (dt * dt);
        segments.push_back({v0, a});
        v0 += a * dt;
    }
    return segments;
}

ValueRate kinematic_at(double p0, const KinematicSegment &segment, double tau) {
    return {p0 + segment.v0 * tau + 0.5 * segment.a * tau * tau, segment.v0 + segment.a * tau};
}

namespace {

class KinematicCurve : public Curve {
  public:
    explicit KinematicCurve(const ani_channel &channel) : keys_(channel.keys) {
        for (int c = 0; c < 3; ++c) initial_rate_[c] = channel.initial_rate[c];
        // One key: no segment, nothing to allocate (a gas of 100,000 balls keyed once each asks
        // for every ball's start through here).
        if (channel.key_count < 2) return;
        std::vector<double> times(channel.key_count);
        for (uint32_t k = 0; k < channel.key_count; ++k) times[k] = channel.keys[k].time;
        for (int c = 0; c < 3; ++c) {
            std::vector<double> positions(channel.key_count);
            for (uint32_t k = 0; k < channel.key_count; ++k) positions[k] = channel.keys[k].value[c];
            segments_[c] = kinematic_segments(times, positions, channel.initial_rate[c]);
        }
    }

    void key_value(uint32_t k, double value[4]) const override {
        for (int c = 0; c < 3; ++c) value[c] = keys_[k].value[c];
        value[3] = 0.0;
    }

    void segment(uint32_t k, double tau, double value[4], double rate[4]) const override {
        for (int c = 0; c < 3; ++c) {
            const ValueRate p = kinematic_at(keys_[k].value[c], segments_[c][k], tau);
            value[c] = p.value;
            rate[c] = p.rate;
        }
        value[3] = rate[3] = 0.0;
    }

    // The model moves with its initial velocity before the first key and when only one key
    // pins it: that is the velocity the physics backend starts it with.
    void resting_rate(double rate[4]) const override {
        for (int c = 0; c < 3; ++c) rate[c] = initial_rate_[c];
        rate[3] = 0.0;
    }

  private:
    const ani_key *keys_;
    std::array<double, 3> initial_rate_{};
    std::array<std::vector<KinematicSegment>, 3> segments_;
};

} // namespace

void evaluate_kinematic(const ani_channel &channel, const double *times, uint32_t count, double *values,
                        double *rates) {
    evaluate_curve(KinematicCurve(channel), channel.keys, channel.key_count, times, count, values, rates);
}

} // namespace interp
