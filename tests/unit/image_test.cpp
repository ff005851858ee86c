// Hostile images: each is refused with a message naming the file, without decoding what it
// lies about. The files are built byte by byte here (PNG chunks, a deflate stream), so the
// tests do not depend on the decoder they check.
#include "assets/image.hpp"

#include "support.hpp"

#include <catch2/catch.hpp>

#include <cstdint>
#include <string>

using namespace animator;
namespace fs = std::filesystem;

namespace {

fs::path write(const std::string &dir, const std::string &name, const std::string &bytes) {
    const fs::path d = test::fresh_dir(dir);
    test::write_file(d / name, bytes);
    return d / name;
}

void put_u32_be(std::string &out, std::uint32_t v) {
    for (int shift = 24; shift >= 0; shift -= 8)
        out.push_back(static_cast<char>((v >> shift) & 0xff));
}

std::uint32_t crc32(const std::string &bytes) { // PNG's CRC (ISO 3309), bit by bit
    std::uint32_t crc = 0xffffffffu;
    for (unsigned char c : bytes) {
        crc ^= c;
        for (int k = 0; k < 8; ++k) crc = (crc >> 1) ^ (0xedb88320u & (0u - (crc & 1u)));
    }
    return crc ^ 0xffffffffu;
}

void put_chunk(std::string &png, const std::string &type, const std::string &data) {
    put_u32_be(png, static_cast<std::uint32_t>(data.size()));
    png += type + data;
    put_u32_be(png, crc32(type + data));
}

// An 8-bit RGB PNG of the given size whose image data is `zlib_stream`.
std::string rgb_png(std::uint32_t width, std::uint32_t height, const std::string &zlib_stream) {
    std::string png = "\x89PNG\r\n\x1a\n";
    std::string ihdr;
    put_u32_be(ihdr, width);
    put_u32_be(ihdr, height);
    ihdr +=
        std::string("\x08\x02\x00\x00\x00", 5); // depth 8, RGB, deflate, no filter, no interlace
    put_chunk(png, "IHDR", ihdr);
    put_chunk(png, "IDAT", zlib_stream);
    put_chunk(png, "IEND", "");
    return png;
}

// Writes deflate's bits: header fields least significant bit first, Huffman codes most
// significant bit first (RFC 1951, 3.1.1).
class BitWriter {
  public:
    void bits_lsb_first(std::uint32_t value, int count) {
        for (int i = 0; i < count; ++i) bit((value >> i) & 1u);
    }
    void code_msb_first(std::uint32_t code, int length) {
        for (int i = length - 1; i >= 0; --i) bit((code >> i) & 1u);
    }
    std::string finish() {
        if (used_) out_.push_back(static_cast<char>(current_));
        return out_;
    }

  private:
    void bit(std::uint32_t b) {
        current_ |= static_cast<unsigned>(b) << used_;
        if (++used_ == 8) {
            out_.push_back(static_cast<char>(current_));
            current_ = 0;
            used_ = 0;
        }
    }
    std::string out_;
    unsigned current_ = 0;
    int used_ = 0;
};

// A zlib stream that inflates to `n` zero bytes, about 13 bits per 258 bytes: one literal 0,
// then copies of length 258 at distance 1, in one block with the fixed Huffman codes (RFC 1951,
// 3.2.6: literal 0 is 00110000, length 258 is code 285 = 11000101, distance 1 is 00000, the
// end of the block is 0000000).
std::string zlib_zeros(std::uint64_t n) {
    BitWriter w;
    w.bits_lsb_first(1, 1); // the final block
    w.bits_lsb_first(1, 2); // fixed Huffman codes
    w.code_msb_first(0x30, 8);
    std::uint64_t left = n - 1;
    for (; left >= 258; left -= 258) {
        w.code_msb_first(0xc5, 8);
        w.code_msb_first(0, 5);
    }
    for (; left > 0; --left) w.code_msb_first(0x30, 8);
    w.code_msb_first(0, 7);
    std::string stream = "\x78\x01"; // deflate, 32 KiB window; 0x7801 is a multiple of 31
    stream += w.finish();
    put_u32_be(stream, static_cast<std::uint32_t>(n % 65521) << 16 | 1u); // Adler-32 of zeros
    return stream;
}

} // namespace

TEST_CASE("a hand-made PNG loads, so the hostile ones below fail for what they are") {
    // 1 x 1, filter byte 0 then the pixel (0, 0, 0): four zero bytes.
    const Image image =
        load_image(write("image_png_ok", "black.png", rgb_png(1, 1, zlib_zeros(4))));
    CHECK(image.width == 1);
    CHECK(image.height == 1);
    CHECK(image.rgb == std::vector<std::uint8_t>{0, 0, 0});
}

TEST_CASE("a file of another format named like a PNG is refused: only PNG and BMP are decoded") {
    // What the image fuzzer found: a 16-bit PNM (a 5 x 3 greymap with values up to 65535) that
    // stb's PNM decoder converted as 8-bit data, reading past its buffer.
    std::string pnm = "P5\n5 3\n65535\n";
    for (int i = 0; i < 15; ++i) pnm += "\x12{";
    const fs::path file = write("image_pnm", "grey.png", pnm);
    CHECK_THROWS_AS(load_image(file), AssetError);
    CHECK_THROWS_WITH(load_image(file),
                      Catch::StartsWith(file.string() + ": cannot be read as an image"));
}

TEST_CASE("an image whose header claims more pixels than a texture may have is refused from it") {
    // 8192 x 8192 RGB would need 192 MiB for its pixels and as much again for the inflated data
    // stb sizes from the header before finding that the stream holds four bytes.
    const fs::path file = write("image_huge", "huge.png", rgb_png(8192, 8192, zlib_zeros(4)));
    CHECK_THROWS_WITH(load_image(file),
                      Catch::StartsWith(file.string() + ": the image is 8192 x 8192 pixels"));
    const fs::path wide = write("image_wide", "wide.png", rgb_png(20000, 1, zlib_zeros(4)));
    CHECK_THROWS_WITH(load_image(wide),
                      Catch::StartsWith(wide.string() + ": the image is 20000 x 1 pixels"));
}

TEST_CASE("a PNG whose data inflates far past its size is refused, not inflated") {
    // A 1 x 1 image whose 1.8 MB stream inflates to 300 MB of zeros: stb would double its
    // buffer to 512 MiB to hold it all.
    const fs::path file = write("image_bomb", "bomb.png", rgb_png(1, 1, zlib_zeros(300'000'000)));
    CHECK_THROWS_WITH(
        load_image(file),
        Catch::StartsWith(
            file.string() +
            ": cannot be read as an image: decoding it would need more than 256 MiB"));
}
