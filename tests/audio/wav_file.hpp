// The tests' own WAV reader and writer, written apart from host/audio's so that a mistake in the
// program's WAV writer cannot hide behind the same mistake in the check.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace audio_test {

struct Wav {
    int format = 0; // 1: integer PCM
    int channels = 0;
    int rate = 0;
    int bits = 0;
    std::vector<std::int16_t> samples; // interleaved
    std::size_t frames() const {
        return channels ? samples.size() / static_cast<std::size_t>(channels) : 0;
    }
    std::int16_t at(std::size_t frame, int channel) const {
        return samples[frame * static_cast<std::size_t>(channels) +
                       static_cast<std::size_t>(channel)];
    }
};

// Reads a 16-bit PCM WAV file; throws std::runtime_error when it is anything else or malformed
// (sizes that disagree with the file's length included).
Wav read_wav(const std::filesystem::path &path);

// Writes mono 16-bit PCM samples (each in [-1, 1]) at `rate`.
void write_mono_wav(const std::filesystem::path &path, const std::vector<double> &samples,
                    int rate);

// Where each sound starts in channel `channel`: the first frame whose magnitude exceeds
// `threshold` after at least `gap` frames below it. In seconds.
std::vector<double> onsets(const Wav &wav, int channel, int threshold, std::size_t gap);

// The largest magnitude in channel `channel` over frames [from, to).
int peak(const Wav &wav, int channel, std::size_t from, std::size_t to);

} // namespace audio_test
