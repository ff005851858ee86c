// Live sound while the editor plays: the collision cues of each stretch of animation played and
// the moving loops, mixed by the same voice engine as the offline soundtrack (voices.hpp) and
// streamed to the audio device through one SFML sound stream, so live playback and
// `animator soundtrack` have the same volumes, pans and voice limit.
//
// Without an audio device (a server, CI) it logs one warning line and does nothing after; a
// document without sounds never touches the device at all.
#pragma once

#include "assets/asset_paths.hpp"
#include "audio/mixer.hpp"
#include "audio/voices.hpp"
#include "document/document.hpp"
#include "timeline/timeline.hpp"

#include <functional>
#include <memory>
#include <mutex>
#include <set>
#include <string>

namespace animator::audio {

class LivePlayer {
  public:
    using LogSink = std::function<void(const std::string &)>;

    // `assets` must outlive the player. `log` gets one line per problem (no device, a sound that
    // cannot be read), each said once.
    LivePlayer(const AssetPaths &assets, LogSink log);
    ~LivePlayer();
    LivePlayer(const LivePlayer &) = delete;
    LivePlayer &operator=(const LivePlayer &) = delete;

    // Takes the document being played; sounds are read when they first play. Stops what plays.
    void set_document(const Document &doc);
    // Plays the collision cues with from < t <= to (the editor calls this as it plays forward,
    // each frame) and starts, moves or stops each model's moving loop to match time `to`.
    // `timeline` must be baked up to `to`.
    void advance(const Timeline &timeline, double from, double to);
    // Silences everything (the editor paused, scrubbed or jumped).
    void stop_all();

    // Whether this player has an open device.
    bool has_device() const { return stream_ != nullptr; }
    // How many times any player tried to open the audio device in this process: the proof that
    // a document without sounds never does.
    static int device_open_attempts();
    // The voices started, refused and dropped so far (under the engine's lock).
    VoiceStats stats() const;

    // The output rate of the stream.
    static constexpr int kRate = 44100;

  private:
    class Stream;
    friend class Stream;
    // Opens the device on first need; false (said once) when there is none.
    bool ensure_device();
    std::shared_ptr<const SoundData> sound(const std::string &id);
    // The engine's next chunk as 16-bit samples, for the stream's thread.
    void fill(std::int16_t *out, std::size_t frames);

    LogSink log_;
    SoundBank bank_;
    std::set<std::string> reported_; // sounds already said to be missing
    bool sounds_ = false;            // the document names a sound
    bool tried_device_ = false;
    std::vector<std::string> moving_sounds_; // per model, "" for none

    mutable std::mutex mutex_; // guards engine_: the stream's thread renders it
    VoiceEngine engine_{kRate};
    std::vector<float> mix_;
    std::unique_ptr<Stream> stream_;
};

} // namespace animator::audio
