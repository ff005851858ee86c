// The generated surface textures: format, content and tiling.
#include "asset_readers.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <string>

using namespace animator::test::assets;

namespace {

const char *const kTextures[] = {"checker.png", "checker.bmp", "wood.png", "marble.png",
                                 "brick.png"};

Image load(const std::string &name) {
    return read_image(generated_dir() / "textures" / name);
}

// Mean absolute difference, over all channels, between column a and column b (or rows).
double column_step(const Image &im, int a, int b) {
    double sum = 0.0;
    for (int y = 0; y < im.height; ++y)
        for (int c = 0; c < im.channels; ++c) sum += std::abs(im.at(a, y, c) - im.at(b, y, c));
    return sum / (im.height * im.channels);
}
double row_step(const Image &im, int a, int b) {
    double sum = 0.0;
    for (int x = 0; x < im.width; ++x)
        for (int c = 0; c < im.channels; ++c) sum += std::abs(im.at(x, a, c) - im.at(x, b, c));
    return sum / (im.width * im.channels);
}

} // namespace

TEST_CASE("textures load as 256 x 256 RGB images") {
    for (const char *name : kTextures) {
        INFO(name);
        const Image im = load(name);
        CHECK(im.width == 256);
        CHECK(im.height == 256);
        CHECK(im.channels == 3);
    }
}

TEST_CASE("checker.bmp holds exactly the pixels of checker.png") {
    const Image png = load("checker.png"), bmp = load("checker.bmp");
    REQUIRE(png.channels == bmp.channels);
    CHECK(png.pixels == bmp.pixels);
}

TEST_CASE("checker.png is an 8 x 8 black and white checkerboard, white at the top left") {
    const Image im = load("checker.png");
    int wrong = 0;
    for (int y = 0; y < im.height; ++y)
        for (int x = 0; x < im.width; ++x)
            for (int c = 0; c < 3; ++c)
                if (im.at(x, y, c) != (((x / 32 + y / 32) % 2 == 0) ? 255 : 0)) ++wrong;
    CHECK(wrong == 0);
}

TEST_CASE("textures are not flat") {
    for (const char *name : kTextures) {
        INFO(name);
        const Image im = load(name);
        double sum = 0.0, sum2 = 0.0;
        for (int y = 0; y < im.height; ++y) {
            for (int x = 0; x < im.width; ++x) {
                const double l = im.luminance(x, y);
                sum += l;
                sum2 += l * l;
            }
        }
        const double n = im.width * im.height, mean = sum / n;
        const double deviation = std::sqrt(std::max(0.0, sum2 / n - mean * mean));
        INFO("luminance standard deviation " << deviation);
        CHECK(deviation > 8.0);
    }
}

TEST_CASE("textures tile: the wrap-around seam is no sharper than the sharpest step inside") {
    for (const char *name : kTextures) {
        INFO(name);
        const Image im = load(name);
        double worst_column = 0.0, worst_row = 0.0;
        for (int i = 0; i + 1 < im.width; ++i)
            worst_column = std::max(worst_column, column_step(im, i, i + 1));
        for (int i = 0; i + 1 < im.height; ++i)
            worst_row = std::max(worst_row, row_step(im, i, i + 1));
        const double seam_x = column_step(im, im.width - 1, 0);
        const double seam_y = row_step(im, im.height - 1, 0);
        INFO("seams " << seam_x << ", " << seam_y << "; inside at most " << worst_column << ", "
                      << worst_row);
        CHECK(seam_x <= worst_column + 1.0);
        CHECK(seam_y <= worst_row + 1.0);
    }
}

TEST_CASE("wood and brick are warm, marble is light and nearly grey") {
    auto mean = [](const Image &im) {
        double rgb[3] = {0, 0, 0};
        for (int y = 0; y < im.height; ++y)
            for (int x = 0; x < im.width; ++x)
                for (int c = 0; c < 3; ++c) rgb[c] += im.at(x, y, c);
        for (double &v : rgb) v /= im.width * im.height;
        return std::array<double, 3>{rgb[0], rgb[1], rgb[2]};
    };
    for (const char *name : {"wood.png", "brick.png"}) {
        INFO(name);
        const auto m = mean(load(name));
        CHECK(m[0] > m[1] + 20.0);
        CHECK(m[1] > m[2]);
    }
    const auto marble = mean(load("marble.png"));
    CHECK(marble[0] > 180.0);
    CHECK(std::max({marble[0], marble[1], marble[2]}) -
              std::min({marble[0], marble[1], marble[2]}) <
          15.0);
}
