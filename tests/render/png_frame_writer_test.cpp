// Frames written as PNG on worker threads come back as they were drawn.
#include "render/png_frame_writer.hpp"
#include "render/render_error.hpp"

#include "assets/image.hpp"
#include "support.hpp"

#include <catch2/catch.hpp>

using namespace animator;

TEST_CASE("the PNG frame writer writes numbered frames that read back exactly") {
    const auto dir = test::fresh_dir("png_frame_writer");
    const int width = 33, height = 17, frames = 9;
    {
        PngFrameWriter writer(dir, width, height, 2, 9);
        for (int k = 0; k < frames; ++k) {
            std::vector<std::uint8_t> &pixels = writer.next_buffer();
            REQUIRE(pixels.size() == size_t(width * height * 3));
            for (size_t i = 0; i < pixels.size(); ++i)
                pixels[i] = static_cast<std::uint8_t>(i * 7 + size_t(k) * 31);
            writer.write(k);
        }
        writer.finish();
    }
    CHECK(PngFrameWriter::file_name(12) == "frame_00012.png");
    for (int k = 0; k < frames; ++k) {
        CAPTURE(k);
        const Image image = load_image(dir / PngFrameWriter::file_name(k));
        REQUIRE(image.width == width);
        REQUIRE(image.height == height);
        bool same = true;
        for (size_t i = 0; i < image.rgb.size(); ++i)
            same = same && image.rgb[i] == static_cast<std::uint8_t>(i * 7 + size_t(k) * 31);
        CHECK(same);
    }
    CHECK_FALSE(std::filesystem::exists(dir / PngFrameWriter::file_name(frames)));
}

TEST_CASE("a frame that cannot be written is reported with its file") {
    const auto dir = test::fresh_dir("png_frame_writer_missing") / "not_there";
    PngFrameWriter writer(dir, 4, 4, 1);
    writer.next_buffer();
    writer.write(3);
    CHECK_THROWS_WITH(writer.finish(), Catch::Contains("frame_00003.png: cannot be written"));
}
