// interpolation.smooth: cubic Hermite segments with Catmull-Rom tangents, the default curve of
// Blender and Maya users. Not in the seed.
#pragma once

#include "segments.hpp"

#include <memory>
#include <vector>

namespace interp {

struct SmoothSettings {
    double tension = 0.0; // 0: Catmull-Rom; 1: flat tangents
    bool ease = false;    // every tangent 0: ease in and out at every key
};

// One component's tangent (derivative per second) at each key, for keys at strictly increasing
// `times`: interior (1 - tension) (p[i+1] - p[i-1]) / (t[i+1] - t[i-1]); the ends one-sided
// differences times (1 - tension); all 0 with `ease`. One key gets tangent 0.
std::vector<double> catmull_rom_tangents(const std::vector<double> &times,
                                         const std::vector<double> &values, double tension,
                                         bool ease);

// The smooth curve of a validated channel of any kind. Keeps pointers into the channel's keys.
std::unique_ptr<Curve> make_smooth_curve(const ani_channel &channel, const SmoothSettings &settings);

} // namespace interp
