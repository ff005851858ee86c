// The offline soundtrack: every collision and moving sound of a baked timeline mixed at its exact
// time (to the nearest output sample) into 16-bit stereo WAV, through the same voice engine,
// volumes and pans as live playback (voices.hpp, sound_cues.hpp), so that it can go under a
// rendered video. Also the sounds themselves: WAV files read once per id and shared.
#pragma once

#include "assets/asset_paths.hpp"
#include "audio/voices.hpp"
#include "timeline/timeline.hpp"

#include <cstdio>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace animator::audio {

// A sound that cannot be found or read; the message names the sound or the file and what was
// expected.
struct SoundError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// Reads a RIFF WAVE file of integer PCM (8, 16, 24 or 32 bits) or 32-bit float, mono or stereo.
// Throws SoundError naming the file and what was expected.
SoundData read_wav(const std::filesystem::path &path);

// Sounds by id, each read from its file once and then shared by every voice that plays it.
class SoundBank {
  public:
    explicit SoundBank(const AssetPaths &assets) : assets_(assets) {}
    // Sound `id` (found through AssetPaths: sounds/<id>.wav); throws SoundError when it cannot
    // be found ("sound 'x' not found: looked for ...") or read. A failure is remembered too.
    std::shared_ptr<const SoundData> get(const std::string &id);
    // How many files were read: once per id, however often it plays.
    std::size_t files_read() const { return files_read_; }

  private:
    const AssetPaths &assets_;
    std::map<std::string, std::shared_ptr<const SoundData>> sounds_;
    std::map<std::string, std::string> failures_;
    std::size_t files_read_ = 0;
};

// Loads every sound that the document names. Throws SoundError naming the model and the sound
// ("model 'ball': collision sound 'x' not found: ...").
void load_document_sounds(const Document &doc, SoundBank &bank);

struct MixOptions {
    int rate = 44100;   // output frames per second
    double from = 0.0;  // seconds: the soundtrack starts here (sounds started before go on)
    double until = 0.0; // seconds: and ends here (within what the timeline baked)
    std::size_t voices = kVoiceLimit;
};

struct MixStats {
    std::size_t collision_cues = 0;
    VoiceStats voices;
    std::size_t clipped = 0; // output samples beyond full scale (written at full scale)
};

// Mixes the soundtrack of `timeline` over [from, until] and gives it to `sink` in consecutive
// blocks of interleaved stereo frames (left, right), round((until - from) * rate) frames in all.
// `progress` gets [0, 1] and returns false to stop (throws BakeCancelled). Throws SoundError for
// a sound that cannot be read.
MixStats mix_soundtrack(const Timeline &timeline, SoundBank &bank, const MixOptions &options,
                        const std::function<void(const float *, std::size_t)> &sink,
                        const std::function<bool(double)> &progress = {});

// A 16-bit stereo PCM WAV file written atomically: the samples go to a temporary file beside
// `path`, which replaces `path` only on commit(), so a failed write leaves an old file intact.
// Samples beyond [-1, 1] are clipped. Throws std::runtime_error naming the file.
class WavWriter {
  public:
    WavWriter(std::filesystem::path path, int rate, std::size_t expected_frames = 0);
    ~WavWriter(); // without commit(), removes the temporary file
    WavWriter(const WavWriter &) = delete;
    WavWriter &operator=(const WavWriter &) = delete;

    void write(const float *interleaved, std::size_t frames);
    void commit();
    std::size_t clipped() const { return clipped_; }

    // The most frames a WAV file holds (its sizes are 32-bit).
    static std::size_t max_frames();

  private:
    void fail(const std::string &what);

    std::filesystem::path path_, temp_;
    int rate_;
    std::FILE *file_ = nullptr;
    std::size_t frames_ = 0, clipped_ = 0;
    std::vector<unsigned char> buffer_;
};

// mix_soundtrack into a WavWriter at `path`, committed at the end.
MixStats write_soundtrack(const Timeline &timeline, SoundBank &bank, const MixOptions &options,
                          const std::filesystem::path &path,
                          const std::function<bool(double)> &progress = {});

} // namespace animator::audio
