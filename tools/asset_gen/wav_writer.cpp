#include "wav_writer.hpp"

#include "file_io.hpp"

namespace animator::assetgen {

namespace {

// WAV is little-endian whatever the host is, so bytes are written one at a time.
void put_u32(std::string &out, std::uint32_t v) {
    for (int shift = 0; shift < 32; shift += 8)
        out.push_back(static_cast<char>((v >> shift) & 0xff));
}
void put_u16(std::string &out, std::uint16_t v) {
    out.push_back(static_cast<char>(v & 0xff));
    out.push_back(static_cast<char>(v >> 8));
}

} // namespace

std::string to_wav(const std::vector<std::int16_t> &samples, int sample_rate) {
    constexpr std::uint16_t kChannels = 1, kBitsPerSample = 16;
    constexpr std::uint16_t kBlockAlign = kChannels * kBitsPerSample / 8;
    const auto data_size = static_cast<std::uint32_t>(samples.size() * kBlockAlign);
    std::string out;
    out.reserve(44 + data_size);
    out += "RIFF";
    put_u32(out, 36 + data_size); // everything after this field
    out += "WAVE";
    out += "fmt ";
    put_u32(out, 16);
    put_u16(out, 1); // PCM
    put_u16(out, kChannels);
    put_u32(out, static_cast<std::uint32_t>(sample_rate));
    put_u32(out, static_cast<std::uint32_t>(sample_rate) * kBlockAlign);
    put_u16(out, kBlockAlign);
    put_u16(out, kBitsPerSample);
    out += "data";
    put_u32(out, data_size);
    for (const std::int16_t s : samples) put_u16(out, static_cast<std::uint16_t>(s));
    return out;
}

void write_wav(const std::filesystem::path &path, const std::vector<std::int16_t> &samples,
               int sample_rate) {
    write_bytes(path, to_wav(samples, sample_rate));
}

} // namespace animator::assetgen
