// Collision and motion sounds, 44.1 kHz mono. The one-shots begin at once, with no leading
// silence (the soundtrack lines their onsets up with collision times), are peak-normalised to
// 0.9 of full scale, and end in a short fade so they stop without a click. The hum loops.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace animator::assetgen {

constexpr double kPeak = 0.9;

std::vector<std::int16_t> click_sound(); // 15 ms
std::vector<std::int16_t> knock_sound(); // 150 ms
std::vector<std::int16_t> ping_sound();  // 1 s
std::vector<std::int16_t> thud_sound();  // 250 ms
std::vector<std::int16_t> hum_sound();   // 2 s, loops

struct NamedSound {
    std::string file;
    std::vector<std::int16_t> samples;
};
std::vector<NamedSound> all_sounds();

} // namespace animator::assetgen
