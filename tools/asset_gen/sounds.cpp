#include "sounds.hpp"

#include "noise.hpp"
#include "wav_writer.hpp"

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace animator::assetgen {

namespace {

constexpr double kTwoPi = 2.0 * glm::pi<double>();

std::size_t samples_for(double seconds) {
    return static_cast<std::size_t>(std::lround(seconds * kSampleRate));
}
double time_of(std::size_t i) {
    return static_cast<double>(i) / kSampleRate;
}

// White noise in [-1, 1) from the hash, so it is the same on every run and platform.
double white(std::size_t i, std::uint32_t seed) {
    return 2.0 * hash01(static_cast<int>(i), 0, 0, seed) - 1.0;
}

// Raised-cosine ramps: their slope is zero at both ends, so neither starts nor ends a click.
double ramp_in(double t, double length) {
    return t >= length ? 1.0 : 0.5 - 0.5 * std::cos(glm::pi<double>() * t / length);
}

void fade_out(std::vector<double> &x, double seconds) {
    const std::size_t n = std::min(x.size(), samples_for(seconds));
    for (std::size_t k = 0; k < n; ++k) {
        // k = 0 is the last sample, which ends at exactly zero.
        const double g = 0.5 - 0.5 * std::cos(glm::pi<double>() * static_cast<double>(k) /
                                              static_cast<double>(n));
        x[x.size() - 1 - k] *= g;
    }
}

std::vector<std::int16_t> normalise(const std::vector<double> &x) {
    double peak = 0.0;
    for (const double v : x) peak = std::max(peak, std::fabs(v));
    const double gain = peak > 0.0 ? kPeak / peak : 0.0;
    std::vector<std::int16_t> out(x.size());
    for (std::size_t i = 0; i < x.size(); ++i)
        out[i] = static_cast<std::int16_t>(std::lround(x[i] * gain * 32767.0));
    return out;
}

// A damped sine partial: amplitude * exp(-t / decay) * sin(2 pi f t).
double partial(double t, double frequency, double amplitude, double decay) {
    return amplitude * std::exp(-t / decay) * std::sin(kTwoPi * frequency * t);
}

} // namespace

// A hard click: a 2 ms-decaying noise burst with a bright 3 kHz body; it peaks in its first
// samples, as a collision between hard objects does.
std::vector<std::int16_t> click_sound() {
    std::vector<double> x(samples_for(0.015));
    for (std::size_t i = 0; i < x.size(); ++i) {
        const double t = time_of(i);
        x[i] = std::exp(-t / 0.002) * (0.7 * white(i, 101) + 0.5 * std::cos(kTwoPi * 3000.0 * t));
    }
    fade_out(x, 0.003);
    return normalise(x);
}

// Wood: a few inharmonic, quickly damped partials in the 200-600 Hz range plus a short,
// low-passed noise transient for the strike.
std::vector<std::int16_t> knock_sound() {
    std::vector<double> x(samples_for(0.150));
    double lowpassed = 0.0;
    for (std::size_t i = 0; i < x.size(); ++i) {
        const double t = time_of(i);
        lowpassed += 0.35 * (white(i, 102) - lowpassed);
        x[i] = ramp_in(t, 0.0003) * (partial(t, 230.0, 1.0, 0.045) + partial(t, 376.0, 0.6, 0.030) +
                                     partial(t, 611.0, 0.3, 0.018)) +
               0.8 * std::exp(-t / 0.004) * lowpassed;
    }
    fade_out(x, 0.010);
    return normalise(x);
}

// Metal: a 1.2 kHz fundamental with the inharmonic overtones of a free bar (2.756x, 5.404x),
// the higher ones dying faster; a slightly detuned twin makes it shimmer.
std::vector<std::int16_t> ping_sound() {
    std::vector<double> x(samples_for(1.0));
    for (std::size_t i = 0; i < x.size(); ++i) {
        const double t = time_of(i);
        x[i] = ramp_in(t, 0.0005) *
               (partial(t, 1200.0, 1.0, 0.30) + partial(t, 1203.5, 0.25, 0.25) +
                partial(t, 1200.0 * 2.756, 0.35, 0.10) + partial(t, 1200.0 * 5.404, 0.15, 0.05));
    }
    fade_out(x, 0.050);
    return normalise(x);
}

// A soft body landing: a low sine sagging from 85 to 62 Hz, with a 1 ms attack so it has no
// click of its own, and a little low-passed noise.
std::vector<std::int16_t> thud_sound() {
    std::vector<double> x(samples_for(0.250));
    double phase = 0.0, lowpassed = 0.0;
    for (std::size_t i = 0; i < x.size(); ++i) {
        const double t = time_of(i);
        const double frequency = 62.0 + 23.0 * std::exp(-t / 0.04);
        lowpassed += 0.05 * (white(i, 104) - lowpassed);
        x[i] = ramp_in(t, 0.001) *
               (std::exp(-t / 0.07) * std::sin(phase) + partial(t, 131.0, 0.2, 0.03) +
                1.5 * std::exp(-t / 0.010) * lowpassed);
        phase += kTwoPi * frequency / kSampleRate;
    }
    fade_out(x, 0.020);
    return normalise(x);
}

// A rolling hum that loops: every sine has a whole number of cycles in the 2 s, i.e. a frequency
// that is a multiple of 0.5 Hz, so sample N would equal sample 0 and the loop has no seam. The
// "rolling" is amplitude modulation at 2 Hz and 0.5 Hz, also periodic in 2 s.
std::vector<std::int16_t> hum_sound() {
    constexpr double kSeconds = 2.0;
    std::vector<double> x(samples_for(kSeconds));
    struct Component {
        double frequency, amplitude, phase;
    };
    std::vector<Component> components = {
        {55.0, 1.0, 0.3}, {110.0, 0.5, 1.1}, {165.0, 0.3, 2.0}, {220.0, 0.12, 0.7}};
    // A rumble of 24 weak partials at hashed multiples of 0.5 Hz between 30 and 150 Hz.
    for (int k = 0; k < 24; ++k) {
        const int half_hertz = 60 + static_cast<int>(hash01(k, 0, 0, 105) * 240.0);
        components.push_back(
            {0.5 * half_hertz, 0.04 + 0.04 * hash01(k, 1, 0, 105), kTwoPi * hash01(k, 2, 0, 105)});
    }
    for (std::size_t i = 0; i < x.size(); ++i) {
        const double t = time_of(i);
        double sum = 0.0;
        for (const auto &c : components)
            sum += c.amplitude * std::cos(kTwoPi * c.frequency * t + c.phase);
        const double roll =
            (1.0 + 0.3 * std::sin(kTwoPi * 2.0 * t)) * (1.0 + 0.15 * std::sin(kTwoPi * 0.5 * t));
        x[i] = sum * roll;
    }
    return normalise(x);
}

std::vector<NamedSound> all_sounds() {
    return {{"click.wav", click_sound()},
            {"knock.wav", knock_sound()},
            {"ping.wav", ping_sound()},
            {"thud.wav", thud_sound()},
            {"hum.wav", hum_sound()}};
}

} // namespace animator::assetgen
