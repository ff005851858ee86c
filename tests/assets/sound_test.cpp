// The generated sounds: WAV format, length, level, onset, ending, loop seam and pitch.
#include "asset_readers.hpp"

#include <catch2/catch.hpp>
#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <string>

using namespace animator::test::assets;

namespace {

struct SoundSpec {
    const char *name;
    double seconds;
    bool one_shot; // fades out at the end; the hum loops instead
};
const SoundSpec kSounds[] = {{"click", 0.015, true},
                             {"knock", 0.150, true},
                             {"ping", 1.0, true},
                             {"thud", 0.250, true},
                             {"hum", 2.0, false}};

Wav load(const std::string &name) {
    return read_wav(generated_dir() / "sounds" / (name + ".wav"));
}

int peak(const Wav &w) {
    int p = 0;
    for (const auto s : w.samples) p = std::max(p, std::abs(static_cast<int>(s)));
    return p;
}

// Energy in [lo, hi] Hz, from Goertzel filters every 5 Hz.
double band_energy(const Wav &w, double lo, double hi) {
    double total = 0.0;
    for (double f = lo; f <= hi; f += 5.0) {
        const double k = 2.0 * std::cos(2.0 * glm::pi<double>() * f / w.sample_rate);
        double s1 = 0.0, s2 = 0.0;
        for (const auto x : w.samples) {
            const double s0 = x + k * s1 - s2;
            s2 = s1;
            s1 = s0;
        }
        total += s1 * s1 + s2 * s2 - k * s1 * s2;
    }
    return total / ((hi - lo) / 5.0 + 1.0);
}

} // namespace

TEST_CASE("sounds are 16-bit mono 44.1 kHz PCM WAV files") {
    for (const auto &spec : kSounds) {
        INFO(spec.name);
        const Wav w = load(spec.name);
        CHECK(w.format == 1);
        CHECK(w.channels == 1);
        CHECK(w.sample_rate == 44100);
        CHECK(w.bits_per_sample == 16);
        CHECK(w.block_align == 2);
        CHECK(w.byte_rate == 88200);
        CHECK(!w.samples.empty());
    }
}

TEST_CASE("sound durations are as documented, within 10 percent") {
    for (const auto &spec : kSounds) {
        INFO(spec.name);
        const Wav w = load(spec.name);
        const double seconds = static_cast<double>(w.samples.size()) / w.sample_rate;
        CHECK(seconds == Approx(spec.seconds).epsilon(0.10));
    }
}

TEST_CASE("sounds are peak-normalised to about 0.9 of full scale") {
    for (const auto &spec : kSounds) {
        INFO(spec.name);
        const double level = peak(load(spec.name)) / 32768.0;
        CHECK(level >= 0.8);
        CHECK(level <= 0.95);
    }
}

TEST_CASE("sounds start within their first 2 ms") {
    for (const auto &spec : kSounds) {
        INFO(spec.name);
        const Wav w = load(spec.name);
        const int threshold = peak(w) / 10;
        const auto first = std::find_if(w.samples.begin(), w.samples.end(), [&](std::int16_t s) {
            return std::abs(static_cast<int>(s)) > threshold;
        });
        CHECK(first - w.samples.begin() < 88);
    }
}

TEST_CASE("one-shot sounds fade out to silence, so they end without a click") {
    for (const auto &spec : kSounds) {
        if (!spec.one_shot) continue;
        INFO(spec.name);
        const Wav w = load(spec.name);
        const int p = peak(w);
        CHECK(std::abs(static_cast<int>(w.samples.back())) <= p / 100);
        int last_ms = 0;
        for (std::size_t i = w.samples.size() - 44; i < w.samples.size(); ++i)
            last_ms = std::max(last_ms, std::abs(static_cast<int>(w.samples[i])));
        CHECK(last_ms <= p / 10);
    }
}

TEST_CASE("hum.wav loops: its end runs smoothly into its start") {
    const Wav w = load("hum");
    const int p = peak(w);
    const int n = static_cast<int>(w.samples.size());
    auto at = [&](int i) { return static_cast<int>(w.samples[static_cast<std::size_t>(i)]); };
    const int join = std::abs(at(n - 1) - at(0));
    // The largest step between neighbours within the last and first 100 samples.
    int steepest = 0;
    for (int i = 0; i < 99; ++i) {
        steepest = std::max(steepest, std::abs(at(i + 1) - at(i)));
        steepest = std::max(steepest, std::abs(at(n - 100 + i + 1) - at(n - 100 + i)));
    }
    INFO("join " << join << ", steepest step nearby " << steepest << ", peak " << p);
    CHECK(join < p / 20);
    CHECK(join <= 2 * steepest + 2);
}

TEST_CASE("each impact sound has its energy in its documented band") {
    struct Band {
        double lo, hi;
    };
    const Band low{40, 100}, mid{180, 650}, high{1000, 1500};
    const struct {
        const char *name;
        int dominant; // 0 low (thud), 1 mid (knock), 2 high (ping)
    } cases[] = {{"thud", 0}, {"knock", 1}, {"ping", 2}};
    for (const auto &c : cases) {
        INFO(c.name);
        const Wav w = load(c.name);
        const double energy[3] = {band_energy(w, low.lo, low.hi), band_energy(w, mid.lo, mid.hi),
                                  band_energy(w, high.lo, high.hi)};
        INFO("low " << energy[0] << ", mid " << energy[1] << ", high " << energy[2]);
        for (int b = 0; b < 3; ++b)
            if (b != c.dominant) CHECK(energy[c.dominant] > 3.0 * energy[b]);
    }
}
