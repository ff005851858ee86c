#include "angles.hpp"

#include <cmath>

namespace interp {

double wrap_degrees(double x) {
    double r = std::fmod(x, 360.0);
    if (r < 0.0) r += 360.0;
    // A tiny negative r rounds up to exactly 360 when 360 is added: that angle is 0.
    if (r >= 360.0) r = 0.0;
    return r + 0.0; // turns -0.0 into +0.0
}

double turn_delta(double prev, double next, double turn) {
    double delta = next - prev;
    // Seed, "Linear Interpolation between Keyframes": stored angles lose their sign (-10 is kept
    // as 350), so the raw difference may go the long way round; the seed adds or subtracts 360
    // degrees according to the direction the user turned (its `ccw`, negative for
    // counter-clockwise). With no direction recorded we take the shorter way; a half turn
    // (|delta| == 180) is equally short both ways and keeps the raw difference's direction.
    if (turn == 0.0) {
        if (delta > 180.0) delta -= 360.0;
        if (delta < -180.0) delta += 360.0;
    } else if (turn < 0.0) {
        if (delta < 0.0) delta += 360.0;
    } else {
        if (delta > 0.0) delta -= 360.0;
    }
    return delta;
}

std::vector<double> unwrap_angles(const std::vector<double> &angles, const std::vector<double> &turns) {
    std::vector<double> out(angles.size());
    for (size_t k = 0; k < angles.size(); ++k)
        out[k] = k == 0 ? angles[0] : out[k - 1] + turn_delta(angles[k - 1], angles[k], turns[k]);
    return out;
}

} // namespace interp
