#include "smooth.hpp"

#include "angles.hpp"
#include "hermite.hpp"
#include "rotation.hpp"

#include <array>

namespace interp {

std::vector<double> catmull_rom_tangents(const std::vector<double> &times,
                                         const std::vector<double> &values, double tension,
                                         bool ease) {
    const size_t n = times.size();
    std::vector<double> m(n, 0.0);
    if (ease || n < 2) return m;
    const double k = 1.0 - tension;
    // The chord through the neighbours over the time between them (Catmull-Rom's tangent for
    // non-uniform key times): keys on a straight line get that line's slope everywhere, so the
    // curve reproduces the line instead of bulging.
    for (size_t i = 1; i + 1 < n; ++i)
        m[i] = k * (values[i + 1] - values[i - 1]) / (times[i + 1] - times[i - 1]);
    m[0] = k * (values[1] - values[0]) / (times[1] - times[0]);
    m[n - 1] = k * (values[n - 1] - values[n - 2]) / (times[n - 1] - times[n - 2]);
    return m;
}

namespace {

// POSITION, SCALE, CAMERA_POSITION and (unwrapped first, wrapped after) ANGLES.
class SmoothVectorCurve : public Curve {
  public:
    SmoothVectorCurve(const ani_channel &channel, const SmoothSettings &settings)
        : keys_(channel.keys), angles_(channel.kind == ANI_CHANNEL_ANGLES) {
        std::vector<double> times(channel.key_count);
        for (uint32_t k = 0; k < channel.key_count; ++k) times[k] = channel.keys[k].time;
        for (int c = 0; c < 3; ++c) {
            std::vector<double> values(channel.key_count);
            for (uint32_t k = 0; k < channel.key_count; ++k) values[k] = key_component(k, c);
            if (angles_) {
                std::vector<double> turns(channel.key_count);
                for (uint32_t k = 0; k < channel.key_count; ++k) turns[k] = channel.keys[k].turn[c];
                values = unwrap_angles(values, turns);
            }
            tangents_[c] = catmull_rom_tangents(times, values, settings.tension, settings.ease);
            values_[c] = std::move(values);
        }
    }

    void key_value(uint32_t k, double value[4]) const override {
        for (int c = 0; c < 3; ++c) value[c] = key_component(k, c);
        value[3] = 0.0;
    }

    void segment(uint32_t k, double tau, double value[4], double rate[4]) const override {
        const double dt = keys_[k + 1].time - keys_[k].time;
        for (int c = 0; c < 3; ++c) {
            const auto &p = values_[c];
            const auto &m = tangents_[c];
            const ValueRate h = hermite(p[k], p[k + 1], m[k], m[k + 1], dt, tau);
            value[c] = angles_ ? wrap_degrees(h.value) : h.value;
            rate[c] = h.rate;
        }
        value[3] = rate[3] = 0.0;
    }

  private:
    double key_component(uint32_t k, int c) const {
        return angles_ ? wrap_degrees(keys_[k].value[c]) : keys_[k].value[c];
    }

    const ani_key *keys_;
    bool angles_;
    std::array<std::vector<double>, 3> values_;   // unwrapped for angles
    std::array<std::vector<double>, 3> tangents_; // per second
};

} // namespace

std::unique_ptr<Curve> make_smooth_curve(const ani_channel &channel, const SmoothSettings &settings) {
    if (channel.kind == ANI_CHANNEL_CAMERA_ROTATION) {
        // The blend of 0 and 1 with the Catmull-Rom end tangent of that pair, (1 - tension): s
        // itself by default, smoothstep with ease (or full tension). A rotation is not smoothed
        // across keys (that would be a spline in the quaternion sphere, e.g. squad).
        const double tangent = settings.ease ? 0.0 : 1.0 - settings.tension;
        return std::make_unique<SlerpCurve>(channel.keys, channel.key_count, tangent);
    }
    return std::make_unique<SmoothVectorCurve>(channel, settings);
}

} // namespace interp
