#include "segments.hpp"

#include <stdexcept>

namespace interp {

Location SegmentSweep::locate(double t) {
    if (started_ && t < last_t_) throw std::logic_error("times must be given in increasing order");
    started_ = true;
    last_t_ = t;
    if (t < keys_[0].time) return {Location::before, 0, 0.0};
    while (k_ + 1 < count_ && keys_[k_ + 1].time <= t) ++k_;
    if (t == keys_[k_].time) return {Location::at_key, k_, 0.0};
    if (k_ + 1 == count_) return {Location::after, k_, 0.0};
    return {Location::inside, k_, t - keys_[k_].time};
}

void Curve::resting_rate(double rate[4]) const {
    for (int c = 0; c < 4; ++c) rate[c] = 0.0;
}

void evaluate_curve(const Curve &curve, const ani_key *keys, uint32_t key_count,
                    const double *times, uint32_t count, double *values, double *rates) {
    const uint32_t last = key_count - 1;
    double scratch[4];
    // The last key's value and rate serve every time from it on.
    double last_value[4], last_rate[4];
    curve.key_value(last, last_value);
    if (key_count >= 2)
        curve.segment(last - 1, keys[last].time - keys[last - 1].time, scratch, last_rate);
    else
        curve.resting_rate(last_rate);

    SegmentSweep sweep(keys, key_count);
    for (uint32_t i = 0; i < count; ++i) {
        double *value = values + 4 * static_cast<size_t>(i);
        double *rate = rates + 4 * static_cast<size_t>(i);
        const Location at = sweep.locate(times[i]);
        if (at.kind == Location::inside) {
            curve.segment(at.key, at.tau, value, rate);
        } else if (at.kind == Location::before) {
            curve.key_value(0, value);
            curve.resting_rate(rate);
        } else if (at.kind == Location::at_key && at.key < last) {
            curve.key_value(at.key, value);
            curve.segment(at.key, 0.0, scratch, rate);
        } else {
            for (int c = 0; c < 4; ++c) {
                value[c] = last_value[c];
                rate[c] = last_rate[c];
            }
        }
    }
}

} // namespace interp
