#include "audio/mixer.hpp"

#include "audio/sound_cues.hpp"

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fcntl.h>
#include <fstream>
#include <iterator>
#include <limits>
#include <unistd.h>

namespace animator::audio {

namespace fs = std::filesystem;

namespace {

std::uint32_t u32(const unsigned char *p) {
    return static_cast<std::uint32_t>(p[0]) | static_cast<std::uint32_t>(p[1]) << 8 |
           static_cast<std::uint32_t>(p[2]) << 16 | static_cast<std::uint32_t>(p[3]) << 24;
}
std::uint16_t u16(const unsigned char *p) {
    return static_cast<std::uint16_t>(p[0] | p[1] << 8);
}

void put16(std::vector<unsigned char> &out, std::uint32_t v) {
    out.push_back(static_cast<unsigned char>(v & 0xff));
    out.push_back(static_cast<unsigned char>(v >> 8 & 0xff));
}
void put32(std::vector<unsigned char> &out, std::uint32_t v) {
    put16(out, v & 0xffff);
    put16(out, v >> 16);
}

// One sample of `bits` bits in `format` (1 integer PCM, 3 float) at p, as a double in [-1, 1].
double sample_at(const unsigned char *p, int bits, int format) {
    if (format == 3) {
        float f;
        const std::uint32_t raw = u32(p);
        std::memcpy(&f, &raw, sizeof f);
        return std::isfinite(f) ? std::clamp(static_cast<double>(f), -1.0, 1.0) : 0.0;
    }
    switch (bits) {
    case 8:
        return (static_cast<double>(p[0]) - 128.0) / 128.0; // 8-bit WAV is unsigned
    case 16:
        return static_cast<double>(static_cast<std::int16_t>(u16(p))) / 32768.0;
    case 24: {
        std::int32_t v = static_cast<std::int32_t>(p[0] | p[1] << 8 | p[2] << 16);
        if (v & 0x800000) v -= 0x1000000;
        return static_cast<double>(v) / 8388608.0;
    }
    default:
        return static_cast<double>(static_cast<std::int32_t>(u32(p))) / 2147483648.0;
    }
}

} // namespace

SoundData read_wav(const fs::path &path) {
    const std::string name = path.string();
    auto bad = [&](const std::string &what) { return SoundError(name + ": " + what); };
    std::ifstream in(path, std::ios::binary);
    if (!in) throw bad("cannot be opened");
    const std::vector<unsigned char> bytes{std::istreambuf_iterator<char>(in),
                                           std::istreambuf_iterator<char>()};
    if (bytes.size() < 12 || std::memcmp(bytes.data(), "RIFF", 4) != 0 ||
        std::memcmp(bytes.data() + 8, "WAVE", 4) != 0)
        throw bad("is not a WAV file (expected a RIFF WAVE header)");

    int format = 0, channels = 0, bits = 0;
    std::uint32_t rate = 0;
    const unsigned char *data = nullptr;
    std::size_t data_size = 0;
    std::size_t at = 12;
    while (at + 8 <= bytes.size()) {
        const unsigned char *chunk = bytes.data() + at;
        const std::size_t size = u32(chunk + 4);
        const std::size_t body = at + 8;
        const std::size_t available = std::min(size, bytes.size() - body);
        if (std::memcmp(chunk, "fmt ", 4) == 0) {
            if (available < 16) throw bad("has a truncated fmt chunk");
            const unsigned char *f = chunk + 8;
            format = u16(f);
            channels = u16(f + 2);
            rate = u32(f + 4);
            bits = u16(f + 14);
            // WAVE_FORMAT_EXTENSIBLE: the real format is the sub-format GUID's first two bytes.
            if (format == 0xFFFE && available >= 26) format = u16(f + 24);
        } else if (std::memcmp(chunk, "data", 4) == 0) {
            data = chunk + 8;
            data_size = available;
        }
        at = body + size + (size & 1); // chunks are padded to an even size
    }
    if (format == 0) throw bad("has no fmt chunk (expected a WAV file's format description)");
    const bool pcm = format == 1 && (bits == 8 || bits == 16 || bits == 24 || bits == 32);
    const bool float32 = format == 3 && bits == 32;
    if (!pcm && !float32)
        throw bad("has an unsupported encoding (format " + std::to_string(format) + ", " +
                  std::to_string(bits) +
                  " bits; expected integer PCM of 8, 16, 24 or 32 bits, or 32-bit float)");
    if (channels != 1 && channels != 2)
        throw bad("has " + std::to_string(channels) + " channels (expected 1 or 2)");
    if (rate < 1000 || rate > 384000)
        throw bad("has a sample rate of " + std::to_string(rate) + " Hz (expected 1000 to 384000)");
    if (!data) throw bad("has no data chunk (expected the samples)");

    SoundData sound;
    sound.file = path;
    sound.rate = static_cast<int>(rate);
    const std::size_t width = static_cast<std::size_t>(bits / 8);
    const std::size_t frame = width * static_cast<std::size_t>(channels);
    const std::size_t frames = data_size / frame;
    if (frames == 0) throw bad("has no samples");
    sound.samples.resize(frames);
    for (std::size_t i = 0; i < frames; ++i) {
        double sum = 0.0;
        for (std::size_t c = 0; c < static_cast<std::size_t>(channels); ++c)
            sum += sample_at(data + i * frame + c * width, bits, format);
        sound.samples[i] = static_cast<float>(sum / channels);
    }
    return sound;
}

std::shared_ptr<const SoundData> SoundBank::get(const std::string &id) {
    if (const auto s = sounds_.find(id); s != sounds_.end()) return s->second;
    if (const auto f = failures_.find(id); f != failures_.end()) throw SoundError(f->second);
    try {
        const std::optional<fs::path> file = assets_.resolve(ANI_ASSET_SOUND, id);
        if (!file)
            throw SoundError("sound '" + id +
                             "' not found: " + assets_.searched(ANI_ASSET_SOUND, id));
        ++files_read_;
        auto sound = std::make_shared<SoundData>(read_wav(*file));
        sound->id = id;
        sounds_[id] = sound;
        return sound;
    } catch (const SoundError &e) {
        failures_[id] = e.what();
        throw;
    }
}

void load_document_sounds(const Document &doc, SoundBank &bank) {
    for (const Model &m : doc.models()) {
        for (const auto &[what, id] :
             {std::pair<const char *, const std::string &>{"collision", m.collision_sound},
              {"moving", m.moving_sound}}) {
            if (id.empty()) continue;
            try {
                bank.get(id);
            } catch (const SoundError &e) {
                // "model 'ball': collision sound 'x' not found: ...", or for a file that cannot
                // be read, "model 'ball': collision sound 'x': FILE: what was expected".
                const std::string said = e.what();
                const bool missing = said.rfind("sound '", 0) == 0;
                throw SoundError("model '" + m.name + "': " + what + " " +
                                 (missing ? said : "sound '" + id + "': " + said));
            }
        }
    }
}

MixStats mix_soundtrack(const Timeline &timeline, SoundBank &bank, const MixOptions &o,
                        const std::function<void(const float *, std::size_t)> &sink,
                        const std::function<bool(double)> &progress) {
    const auto &models = timeline.document().models();
    const double rate = o.rate;
    auto frame_of = [&](double t) { return static_cast<long long>(std::llround(t * rate)); };
    const long long first = frame_of(o.from), end = frame_of(o.until);

    MixStats stats;
    const std::vector<CollisionCue> cues =
        collision_cues(timeline, -std::numeric_limits<double>::infinity(), o.until);
    stats.collision_cues = cues.size();
    const bool any_moving = std::any_of(models.begin(), models.end(),
                                        [](const Model &m) { return !m.moving_sound.empty(); });
    // Moving sounds follow the model every kMovingSampleStep seconds, up to `until`.
    const auto moving_steps =
        any_moving ? static_cast<long long>(std::floor(o.until / kMovingSampleStep + 1e-9)) + 1 : 0;

    VoiceEngine engine(o.rate, o.voices);
    constexpr std::size_t kBlock = 4096;
    std::vector<float> block(2 * kBlock);
    long long frame = 0;
    std::size_t cue = 0;
    long long step = 0;
    while (frame < end) {
        long long next = end;
        if (cue < cues.size()) next = std::min(next, frame_of(cues[cue].time));
        if (step < moving_steps)
            next = std::min(next, frame_of(static_cast<double>(step) * kMovingSampleStep));
        while (frame < next) {
            const auto n = static_cast<std::size_t>(std::min<long long>(next - frame, kBlock));
            std::fill(block.begin(), block.begin() + static_cast<std::ptrdiff_t>(2 * n), 0.0f);
            engine.render(block.data(), n);
            // Frames before `from` are mixed (a sound started before goes on) but not given out.
            if (frame + static_cast<long long>(n) > first) {
                const auto skip = static_cast<std::size_t>(std::max<long long>(0, first - frame));
                sink(block.data() + 2 * skip, n - skip);
            }
            frame += static_cast<long long>(n);
            if (progress && !progress(static_cast<double>(frame) / static_cast<double>(end)))
                throw BakeCancelled();
        }
        if (frame >= end) break;
        // Moving sounds first, then the collisions at this frame.
        while (step < moving_steps &&
               frame_of(static_cast<double>(step) * kMovingSampleStep) <= frame) {
            const std::vector<MovingState> states =
                moving_states(timeline, static_cast<double>(step) * kMovingSampleStep);
            for (std::size_t m = 0; m < models.size(); ++m) {
                if (models[m].moving_sound.empty()) continue;
                const int key = static_cast<int>(m);
                if (states[m].moving)
                    engine.loop(key, bank.get(models[m].moving_sound), states[m].volume,
                                states[m].pan);
                else
                    engine.stop_loop(key);
            }
            ++step;
        }
        for (; cue < cues.size() && frame_of(cues[cue].time) <= frame; ++cue)
            engine.play(bank.get(cues[cue].sound), cues[cue].volume, cues[cue].pan);
    }
    stats.voices = engine.stats();
    return stats;
}

std::size_t WavWriter::max_frames() {
    // The RIFF size (data + 36 bytes of header) must fit in 32 bits.
    return (std::numeric_limits<std::uint32_t>::max() - 36) / 4;
}

WavWriter::WavWriter(fs::path path, int rate, std::size_t expected_frames)
    : path_(std::move(path)), rate_(rate) {
    if (expected_frames > max_frames())
        throw std::runtime_error(path_.string() + ": " + std::to_string(expected_frames) +
                                 " frames do not fit in a WAV file (at most " +
                                 std::to_string(max_frames()) + ")");
    const fs::path dir = path_.has_parent_path() ? path_.parent_path() : fs::path(".");
    // Beside the target, so the rename stays within one file system; open() rather than
    // mkstemp() so that the file gets the usual permissions (0666 less the umask).
    static std::atomic<unsigned> counter{0};
    const fs::path name =
        dir / ("." + path_.filename().string() + "." + std::to_string(::getpid()) + "." +
               std::to_string(counter++) + ".tmp");
    const int fd = ::open(name.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd < 0) fail("cannot be written (" + std::string(std::strerror(errno)) + ")");
    temp_ = name;
    file_ = fdopen(fd, "wb");
    if (!file_) {
        ::close(fd);
        fail("cannot be written (" + std::string(std::strerror(errno)) + ")");
    }
    const unsigned char header[44] = {}; // filled in by commit()
    if (std::fwrite(header, 1, sizeof header, file_) != sizeof header) fail("writing failed");
}

WavWriter::~WavWriter() {
    if (file_) std::fclose(file_);
    if (!temp_.empty()) {
        std::error_code ignored;
        fs::remove(temp_, ignored);
    }
}

void WavWriter::fail(const std::string &what) {
    throw std::runtime_error(path_.string() + ": " + what);
}

void WavWriter::write(const float *samples, std::size_t frames) {
    if (!file_) fail("written after it was finished");
    if (frames > max_frames() - frames_) fail("too long for a WAV file");
    buffer_.clear();
    buffer_.reserve(4 * frames);
    for (std::size_t i = 0; i < 2 * frames; ++i) {
        float x = samples[i];
        if (!(std::abs(x) <= 1.0f)) {
            ++clipped_;
            x = std::isnan(x) ? 0.0f : std::clamp(x, -1.0f, 1.0f);
        }
        const auto v = static_cast<std::int16_t>(std::lround(static_cast<double>(x) * 32767.0));
        put16(buffer_, static_cast<std::uint16_t>(v));
    }
    if (std::fwrite(buffer_.data(), 1, buffer_.size(), file_) != buffer_.size())
        fail("writing failed (" + std::string(std::strerror(errno)) + ")");
    frames_ += frames;
}

void WavWriter::commit() {
    if (!file_) fail("written after it was finished");
    const auto data = static_cast<std::uint32_t>(4 * frames_);
    std::vector<unsigned char> h;
    h.insert(h.end(), {'R', 'I', 'F', 'F'});
    put32(h, 36 + data);
    h.insert(h.end(), {'W', 'A', 'V', 'E', 'f', 'm', 't', ' '});
    put32(h, 16);                                    // fmt chunk size
    put16(h, 1);                                     // integer PCM
    put16(h, 2);                                     // stereo
    put32(h, static_cast<std::uint32_t>(rate_));     // frames per second
    put32(h, static_cast<std::uint32_t>(rate_) * 4); // bytes per second
    put16(h, 4);                                     // bytes per frame
    put16(h, 16);                                    // bits per sample
    h.insert(h.end(), {'d', 'a', 't', 'a'});
    put32(h, data);
    const bool ok = std::fseek(file_, 0, SEEK_SET) == 0 &&
                    std::fwrite(h.data(), 1, h.size(), file_) == h.size() &&
                    std::fflush(file_) == 0 && ::fsync(fileno(file_)) == 0;
    const int closed = std::fclose(file_);
    file_ = nullptr;
    if (!ok || closed != 0) fail("writing failed (" + std::string(std::strerror(errno)) + ")");
    std::error_code ec;
    fs::rename(temp_, path_, ec);
    if (ec) fail("cannot be written (" + ec.message() + ")");
    temp_.clear();
}

MixStats write_soundtrack(const Timeline &timeline, SoundBank &bank, const MixOptions &options,
                          const fs::path &path, const std::function<bool(double)> &progress) {
    const auto frames =
        static_cast<std::size_t>(std::max(0LL, std::llround(options.until * options.rate) -
                                                   std::llround(options.from * options.rate)));
    WavWriter writer(path, options.rate, frames);
    MixStats stats = mix_soundtrack(
        timeline, bank, options, [&](const float *s, std::size_t n) { writer.write(s, n); },
        progress);
    writer.commit();
    stats.clipped = writer.clipped();
    return stats;
}

} // namespace animator::audio
