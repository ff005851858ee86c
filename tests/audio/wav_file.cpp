#include "wav_file.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <stdexcept>

namespace audio_test {

namespace {

std::uint32_t le32(const std::vector<unsigned char> &b, std::size_t at) {
    if (at + 4 > b.size()) throw std::runtime_error("WAV: truncated");
    return static_cast<std::uint32_t>(b[at]) | static_cast<std::uint32_t>(b[at + 1]) << 8 |
           static_cast<std::uint32_t>(b[at + 2]) << 16 |
           static_cast<std::uint32_t>(b[at + 3]) << 24;
}
std::uint16_t le16(const std::vector<unsigned char> &b, std::size_t at) {
    if (at + 2 > b.size()) throw std::runtime_error("WAV: truncated");
    return static_cast<std::uint16_t>(b[at] | b[at + 1] << 8);
}
bool tag(const std::vector<unsigned char> &b, std::size_t at, const char *t) {
    return at + 4 <= b.size() && std::equal(t, t + 4, b.begin() + static_cast<std::ptrdiff_t>(at));
}

} // namespace

Wav read_wav(const std::filesystem::path &path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error(path.string() + ": cannot be opened");
    const std::vector<unsigned char> b{std::istreambuf_iterator<char>(in), {}};
    if (!tag(b, 0, "RIFF") || !tag(b, 8, "WAVE"))
        throw std::runtime_error("WAV: no RIFF WAVE header");
    if (le32(b, 4) + 8 != b.size())
        throw std::runtime_error("WAV: the RIFF size disagrees with the file");
    Wav w;
    bool have_fmt = false, have_data = false;
    for (std::size_t at = 12; at + 8 <= b.size();) {
        const std::size_t size = le32(b, at + 4);
        if (at + 8 + size > b.size()) throw std::runtime_error("WAV: a chunk runs past the end");
        if (tag(b, at, "fmt ")) {
            w.format = le16(b, at + 8);
            w.channels = le16(b, at + 10);
            w.rate = static_cast<int>(le32(b, at + 12));
            const std::uint32_t byte_rate = le32(b, at + 16);
            const int align = le16(b, at + 20);
            w.bits = le16(b, at + 22);
            if (byte_rate != static_cast<std::uint32_t>(w.rate * w.channels * w.bits / 8) ||
                align != w.channels * w.bits / 8)
                throw std::runtime_error("WAV: byte rate or block align disagree with the format");
            have_fmt = true;
        } else if (tag(b, at, "data")) {
            if (!have_fmt || w.format != 1 || w.bits != 16)
                throw std::runtime_error("WAV: expected 16-bit PCM before the data");
            if (size % (2 * static_cast<std::size_t>(w.channels)) != 0)
                throw std::runtime_error("WAV: data is not a whole number of frames");
            for (std::size_t i = 0; i < size; i += 2)
                w.samples.push_back(static_cast<std::int16_t>(le16(b, at + 8 + i)));
            have_data = true;
        }
        at += 8 + size + (size & 1);
    }
    if (!have_fmt || !have_data) throw std::runtime_error("WAV: missing fmt or data chunk");
    return w;
}

void write_mono_wav(const std::filesystem::path &path, const std::vector<double> &samples,
                    int rate) {
    std::vector<unsigned char> b;
    auto put = [&](std::uint32_t v, int bytes) {
        for (int i = 0; i < bytes; ++i)
            b.push_back(static_cast<unsigned char>(v >> (8 * i) & 0xff));
    };
    auto text = [&](const char *t) { b.insert(b.end(), t, t + 4); };
    const auto data = static_cast<std::uint32_t>(2 * samples.size());
    text("RIFF");
    put(36 + data, 4);
    text("WAVE");
    text("fmt ");
    put(16, 4);
    put(1, 2);
    put(1, 2);
    put(static_cast<std::uint32_t>(rate), 4);
    put(static_cast<std::uint32_t>(2 * rate), 4);
    put(2, 2);
    put(16, 2);
    text("data");
    put(data, 4);
    for (double x : samples)
        put(static_cast<std::uint16_t>(static_cast<std::int16_t>(std::lround(x * 32767.0))), 2);
    std::ofstream(path, std::ios::binary)
        .write(reinterpret_cast<const char *>(b.data()), static_cast<std::streamsize>(b.size()));
}

std::vector<double> onsets(const Wav &wav, int channel, int threshold, std::size_t gap) {
    std::vector<double> out;
    std::size_t quiet = gap; // the start counts as after silence
    for (std::size_t f = 0; f < wav.frames(); ++f) {
        if (std::abs(static_cast<int>(wav.at(f, channel))) > threshold) {
            if (quiet >= gap) out.push_back(static_cast<double>(f) / wav.rate);
            quiet = 0;
        } else {
            ++quiet;
        }
    }
    return out;
}

int peak(const Wav &wav, int channel, std::size_t from, std::size_t to) {
    int p = 0;
    for (std::size_t f = from; f < to && f < wav.frames(); ++f)
        p = std::max(p, std::abs(static_cast<int>(wav.at(f, channel))));
    return p;
}

} // namespace audio_test
