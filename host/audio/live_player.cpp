#include "audio/live_player.hpp"

#include "audio/sound_cues.hpp"

#include <SFML/Audio/SoundStream.hpp>
#include <SFML/System/Err.hpp>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <fcntl.h>
#include <sstream>
#include <unistd.h>

namespace animator::audio {

namespace {

std::atomic<int> g_device_open_attempts{0};

// While probing the device, SFML reports to sf::err(), and OpenAL Soft and ALSA, underneath it,
// write straight to the process's stderr (a dozen lines on a machine without a sound card).
// Both are caught for the probe's duration so that the user sees one line of ours instead.
class QuietProbe {
  public:
    QuietProbe() : previous_(sf::err().rdbuf(caught_.rdbuf())) {
        std::fflush(stderr);
        saved_ = ::dup(STDERR_FILENO);
        const int null = ::open("/dev/null", O_WRONLY | O_CLOEXEC);
        if (saved_ >= 0 && null >= 0) ::dup2(null, STDERR_FILENO);
        if (null >= 0) ::close(null);
    }
    ~QuietProbe() {
        std::fflush(stderr);
        if (saved_ >= 0) {
            ::dup2(saved_, STDERR_FILENO);
            ::close(saved_);
        }
        sf::err().rdbuf(previous_);
    }
    QuietProbe(const QuietProbe &) = delete;
    QuietProbe &operator=(const QuietProbe &) = delete;
    std::string text() const { return caught_.str(); }

  private:
    std::ostringstream caught_;
    std::streambuf *previous_;
    int saved_ = -1;
};

} // namespace

// The one OpenAL source of a player: SFML's streaming thread pulls the engine's mix from it.
class LivePlayer::Stream : public sf::SoundStream {
  public:
    explicit Stream(LivePlayer &owner) : owner_(owner), chunk_(2 * kChunkFrames) {
        initialize(2, kRate);
    }
    ~Stream() override { stop(); } // joins the streaming thread before the members go

  private:
    // 10 ms a chunk: SFML queues three, so a collision is heard within about 30 ms.
    static constexpr std::size_t kChunkFrames = kRate / 100;

    bool onGetData(Chunk &data) override {
        owner_.fill(chunk_.data(), kChunkFrames);
        data.samples = chunk_.data();
        data.sampleCount = chunk_.size();
        return true; // a live stream never ends; stop() ends it
    }
    void onSeek(sf::Time) override {}

    LivePlayer &owner_;
    std::vector<sf::Int16> chunk_;
};

LivePlayer::LivePlayer(const AssetPaths &assets, LogSink log)
    : log_(std::move(log)), bank_(assets) {}

LivePlayer::~LivePlayer() {
    if (stream_) {
        QuietProbe quiet; // closing the device may complain too
        stream_.reset();
    }
}

int LivePlayer::device_open_attempts() {
    return g_device_open_attempts.load();
}

VoiceStats LivePlayer::stats() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return engine_.stats();
}

void LivePlayer::set_document(const Document &doc) {
    stop_all();
    sounds_ = has_sounds(doc);
    moving_sounds_.clear();
    for (const Model &m : doc.models()) moving_sounds_.push_back(m.moving_sound);
}

void LivePlayer::stop_all() {
    std::lock_guard<std::mutex> lock(mutex_);
    engine_.stop_all();
}

bool LivePlayer::ensure_device() {
    if (stream_) return true;
    if (tried_device_) return false;
    tried_device_ = true;
    ++g_device_open_attempts;
    std::string failure;
    {
        QuietProbe quiet;
        auto stream = std::make_unique<Stream>(*this);
        // SFML opens the device with its first audio object and says so on sf::err() when it
        // cannot; it has no other way to tell.
        if (quiet.text().find("Failed to open the audio device") == std::string::npos) {
            stream->play();
            if (stream->getStatus() == sf::SoundSource::Playing && quiet.text().empty())
                stream_ = std::move(stream);
        }
        if (!stream_) {
            std::string said = quiet.text();
            said = said.substr(0, said.find('\n'));
            failure = said.empty() ? "the audio device did not start" : said;
        }
        stream.reset(); // still quiet: tearing down a failed stream complains again
    }
    if (!stream_ && log_) log_("warning: no audio device (" + failure + "); playing without sound");
    return stream_ != nullptr;
}

std::shared_ptr<const SoundData> LivePlayer::sound(const std::string &id) {
    try {
        return bank_.get(id);
    } catch (const SoundError &e) {
        if (reported_.insert(id).second && log_) log_(std::string("warning: ") + e.what());
        return nullptr;
    }
}

void LivePlayer::advance(const Timeline &timeline, double from, double to) {
    if (!sounds_) return; // never opens the device
    const std::vector<CollisionCue> cues =
        to > from ? collision_cues(timeline, from, to) : std::vector<CollisionCue>{};
    const bool any_moving = std::any_of(moving_sounds_.begin(), moving_sounds_.end(),
                                        [](const std::string &s) { return !s.empty(); });
    const std::vector<MovingState> states =
        any_moving ? moving_states(timeline, to) : std::vector<MovingState>{};
    const bool something =
        !cues.empty() ||
        std::any_of(states.begin(), states.end(), [](const MovingState &s) { return s.moving; });
    // The device opens when the first sound plays, not before.
    if (!stream_ && !something) return;
    if (!ensure_device()) return;

    // Read the sounds before taking the lock: the stream's thread must not wait on a file.
    std::vector<std::shared_ptr<const SoundData>> cue_sounds, loop_sounds(states.size());
    for (const CollisionCue &c : cues) cue_sounds.push_back(sound(c.sound));
    for (std::size_t m = 0; m < states.size() && m < moving_sounds_.size(); ++m)
        if (states[m].moving) loop_sounds[m] = sound(moving_sounds_[m]);

    std::lock_guard<std::mutex> lock(mutex_);
    for (std::size_t i = 0; i < cues.size(); ++i)
        if (cue_sounds[i]) engine_.play(cue_sounds[i], cues[i].volume, cues[i].pan);
    for (std::size_t m = 0; m < states.size() && m < moving_sounds_.size(); ++m) {
        if (moving_sounds_[m].empty()) continue;
        const int key = static_cast<int>(m);
        if (states[m].moving && loop_sounds[m])
            engine_.loop(key, loop_sounds[m], states[m].volume, states[m].pan);
        else
            engine_.stop_loop(key);
    }
}

void LivePlayer::fill(std::int16_t *out, std::size_t frames) {
    mix_.assign(2 * frames, 0.0f);
    {
        std::lock_guard<std::mutex> lock(mutex_);
        engine_.render(mix_.data(), frames);
    }
    for (std::size_t i = 0; i < 2 * frames; ++i)
        out[i] = static_cast<std::int16_t>(
            std::lround(static_cast<double>(std::clamp(mix_[i], -1.0f, 1.0f)) * 32767.0));
}

} // namespace animator::audio
