#include "audio/voices.hpp"

#include "audio/sound_cues.hpp"

#include <algorithm>
#include <cmath>

namespace animator::audio {

Admission admit_voice(const std::vector<double> &playing, double loudness, std::size_t limit) {
    if (playing.size() < limit) return {true, std::nullopt};
    if (playing.empty()) return {false, std::nullopt}; // a pool of no voices plays nothing
    // min_element gives the first of equals: the earliest started.
    const auto quietest = std::min_element(playing.begin(), playing.end());
    if (loudness > *quietest) return {true, static_cast<std::size_t>(quietest - playing.begin())};
    return {false, std::nullopt};
}

VoiceEngine::VoiceEngine(int rate, std::size_t limit)
    : rate_(rate), limit_(limit),
      fade_frames_(
          std::max<std::size_t>(1, static_cast<std::size_t>(std::lround(kFadeSeconds * rate)))),
      ramp_frames_(
          std::max<std::size_t>(1, static_cast<std::size_t>(std::lround(kRampSeconds * rate)))) {}

bool VoiceEngine::admit(double loudness) {
    std::vector<double> playing;
    std::vector<std::size_t> index;
    for (std::size_t i = 0; i < voices_.size(); ++i) {
        if (voices_[i].fading || voices_[i].done) continue;
        playing.push_back(voices_[i].loudness);
        index.push_back(i);
    }
    const Admission a = admit_voice(playing, loudness, limit_);
    if (!a.start) {
        ++stats_.refused;
        return false;
    }
    if (a.drop) {
        fade_out(voices_[index[*a.drop]]);
        ++stats_.dropped;
    }
    return true;
}

void VoiceEngine::fade_out(Voice &v) {
    if (v.fading || v.done) return;
    v.fading = true;
    v.fade = fade_frames_;
}

bool VoiceEngine::play(std::shared_ptr<const SoundData> sound, double volume, double pan) {
    return start(std::move(sound), volume, pan, -1);
}

bool VoiceEngine::start(std::shared_ptr<const SoundData> sound, double volume, double pan, int loop_key) {
    if (!sound || sound->samples.empty() || !(volume > 0.0)) return false;
    if (!admit(volume)) return false;
    Voice v;
    v.step = static_cast<double>(sound->rate) / rate_;
    v.sound = std::move(sound);
    v.loudness = volume;
    const StereoGain g = pan_gains(pan);
    v.left = v.target_left = volume / 100.0 * g.left;
    v.right = v.target_right = volume / 100.0 * g.right;
    v.loop_key = loop_key;
    voices_.push_back(std::move(v));
    ++stats_.started;
    stats_.peak = std::max(stats_.peak, sounding());
    return true;
}

bool VoiceEngine::loop(int key, std::shared_ptr<const SoundData> sound, double volume, double pan) {
    const StereoGain g = pan_gains(pan);
    if (Voice *v = find_loop(key)) {
        v->loudness = volume;
        v->target_left = volume / 100.0 * g.left;
        v->target_right = volume / 100.0 * g.right;
        v->ramp = ramp_frames_;
        return true;
    }
    return start(std::move(sound), volume, pan, key);
}

void VoiceEngine::stop_loop(int key) {
    if (Voice *v = find_loop(key)) fade_out(*v);
}

void VoiceEngine::stop_all() {
    for (Voice &v : voices_) fade_out(v);
}

VoiceEngine::Voice *VoiceEngine::find_loop(int key) {
    for (Voice &v : voices_)
        if (v.loop_key == key && !v.fading && !v.done) return &v;
    return nullptr;
}

const VoiceEngine::Voice *VoiceEngine::find_loop(int key) const {
    for (const Voice &v : voices_)
        if (v.loop_key == key && !v.fading && !v.done) return &v;
    return nullptr;
}

bool VoiceEngine::looping(int key) const {
    return find_loop(key) != nullptr;
}

std::size_t VoiceEngine::sounding() const {
    return static_cast<std::size_t>(std::count_if(
        voices_.begin(), voices_.end(), [](const Voice &v) { return !v.fading && !v.done; }));
}

void VoiceEngine::render(float *out, std::size_t frames) {
    for (Voice &v : voices_) {
        const std::vector<float> &s = v.sound->samples;
        const double n = static_cast<double>(s.size());
        const bool looped = v.loop_key >= 0;
        for (std::size_t i = 0; i < frames && !v.done; ++i) {
            // Linear interpolation between the sound's samples; at the same rate the position
            // stays a whole number and the samples come through exactly.
            const auto k = static_cast<std::size_t>(v.position);
            const double frac = v.position - static_cast<double>(k);
            double x = s[k];
            if (frac > 0.0) {
                const std::size_t next = k + 1 < s.size() ? k + 1 : 0;
                const double y = k + 1 < s.size() || looped ? s[next] : 0.0;
                x += (y - x) * frac;
            }
            if (v.ramp > 0) {
                v.left += (v.target_left - v.left) / static_cast<double>(v.ramp);
                v.right += (v.target_right - v.right) / static_cast<double>(v.ramp);
                --v.ramp;
            }
            double fade = 1.0;
            if (v.fading) {
                fade = static_cast<double>(v.fade) / static_cast<double>(fade_frames_);
                if (v.fade == 0) {
                    v.done = true;
                    break;
                }
                --v.fade;
            }
            out[2 * i] += static_cast<float>(x * v.left * fade);
            out[2 * i + 1] += static_cast<float>(x * v.right * fade);
            v.position += v.step;
            if (v.position >= n) {
                if (looped)
                    v.position = std::fmod(v.position, n);
                else
                    v.done = true;
            }
        }
    }
    voices_.erase(
        std::remove_if(voices_.begin(), voices_.end(), [](const Voice &v) { return v.done; }),
        voices_.end());
}

} // namespace animator::audio
