// Canonical 44-byte-header WAV: PCM, 16-bit, mono. Written by hand (rather than via a library)
// so the bytes are fixed by this file alone.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace animator::assetgen {

constexpr int kSampleRate = 44100;

std::string to_wav(const std::vector<std::int16_t> &samples, int sample_rate);
void write_wav(const std::filesystem::path &path, const std::vector<std::int16_t> &samples,
               int sample_rate = kSampleRate);

} // namespace animator::assetgen
