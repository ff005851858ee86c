// The voices that sound at once, mixed in software: one engine for both faces of sound, so the
// live player (live_player.hpp, which feeds it to the device through one SFML stream) and the
// offline soundtrack (mixer.hpp) make the same mix: the same gains, pans and voice limit.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace animator::audio {

// At most this many voices sound at once (docs/sound.md): a gas of a thousand collisions a
// second keeps the loudest 32, which is all an ear separates anyway, and the mixing cost stays
// bounded.
inline constexpr std::size_t kVoiceLimit = 32;

// A voice that stops before its end (dropped for a louder one, or a moving loop that stops)
// fades out over this many seconds instead of cutting off with a click.
inline constexpr double kFadeSeconds = 0.005;

// A decoded sound: mono samples in [-1, 1] at its own rate (a stereo file is averaged to mono,
// since the engine pans each voice itself).
struct SoundData {
    std::string id;
    std::filesystem::path file;
    int rate = 44100;
    std::vector<float> samples;
};

// The pool's rule, on its own so that it can be tested: when a voice of `loudness` asks to start
// while voices of loudness `playing` (in the order they started) sound and the pool holds
// `limit`: with room it starts; when full, the quietest of all of them (new or playing) is
// dropped. Ties keep what plays: the new voice starts only if it is louder than the quietest
// playing voice, which is then the earliest started of the equally quiet.
struct Admission {
    bool start = false;
    std::optional<std::size_t> drop; // the index into `playing` of the voice to drop
};
Admission admit_voice(const std::vector<double> &playing, double loudness, std::size_t limit);

struct VoiceStats {
    std::size_t started = 0; // one-shots and loops that started
    std::size_t refused = 0; // new voices dropped because they were the quietest
    std::size_t dropped = 0; // playing voices dropped for a louder new one
    std::size_t peak = 0;    // the most voices that sounded at once (fading ones not counted)
};

class VoiceEngine {
  public:
    // `rate`: the output's frames per second.
    explicit VoiceEngine(int rate, std::size_t limit = kVoiceLimit);

    // Starts a one-shot at volume 0..100 and pan -1..1; false when the pool dropped it.
    bool play(std::shared_ptr<const SoundData> sound, double volume, double pan);
    // Starts the loop of `key` (a model), or moves its volume and pan to these over
    // kRampSeconds. A loop that the pool dropped asks again at its next call. False when it does
    // not sound.
    bool loop(int key, std::shared_ptr<const SoundData> sound, double volume, double pan);
    // Fades out the loop of `key`, if it plays.
    void stop_loop(int key);
    // Fades out every voice.
    void stop_all();

    // Adds `frames` stereo frames (interleaved left, right) to `out`, and retires the voices
    // that ended.
    void render(float *out, std::size_t frames);

    std::size_t sounding() const; // voices in the pool (not those fading out)
    bool looping(int key) const;
    const VoiceStats &stats() const { return stats_; }
    int rate() const { return rate_; }

    // A loop's volume and pan move to new values over this long (the moving sounds' sample
    // step), so that a changing speed does not step the gain.
    static constexpr double kRampSeconds = 0.01;

  private:
    struct Voice {
        std::shared_ptr<const SoundData> sound;
        double position = 0.0;                        // in the sound's samples
        double step = 1.0;                            // the sound's samples per output frame
        double loudness = 0.0;                        // its volume, for the pool
        double left = 0.0, right = 0.0;               // current gains
        double target_left = 0.0, target_right = 0.0; // where a ramp goes
        std::size_t ramp = 0;                         // frames left in the ramp
        int loop_key = -1;                            // -1 for a one-shot
        std::size_t fade = 0;                         // frames left when fading out, else 0
        bool fading = false;
        bool done = false;
    };
    // Finds room for a voice of `loudness`; false when it is the one dropped.
    bool admit(double loudness);
    // A new voice (loop_key -1: a one-shot), if the pool admits it.
    bool start(std::shared_ptr<const SoundData> sound, double volume, double pan, int loop_key);
    void fade_out(Voice &v);
    Voice *find_loop(int key);
    const Voice *find_loop(int key) const;

    int rate_;
    std::size_t limit_;
    std::size_t fade_frames_, ramp_frames_;
    std::vector<Voice> voices_; // in the order they started
    VoiceStats stats_;
};

} // namespace animator::audio
