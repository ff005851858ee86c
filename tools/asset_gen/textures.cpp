#include "textures.hpp"

#include "noise.hpp"

#include <glm/common.hpp>
#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>

namespace animator::assetgen {

namespace {

constexpr double kTwoPi = 2.0 * glm::pi<double>();

// Calls colour(s, t) with s, t in [0, 1) at pixel corners (not centres): a lattice of period p
// sampled at s * p then lines up exactly with the pixel grid on both sides of the wrap.
template <typename F> Image render(F colour) {
    Image image(kTextureSize, kTextureSize);
    for (int y = 0; y < kTextureSize; ++y)
        for (int x = 0; x < kTextureSize; ++x)
            image.set(x, y,
                      colour(static_cast<double>(x) / kTextureSize,
                             static_cast<double>(y) / kTextureSize, x, y));
    return image;
}

double smoothstep(double e0, double e1, double x) {
    const double t = glm::clamp((x - e0) / (e1 - e0), 0.0, 1.0);
    return t * t * (3.0 - 2.0 * t);
}

} // namespace

Image checker_texture() {
    constexpr int kSquare = kTextureSize / 8;
    return render([](double, double, int x, int y) {
        return ((x / kSquare + y / kSquare) % 2 == 0) ? glm::dvec3(1.0) : glm::dvec3(0.0);
    });
}

// A plank cut along the trunk: growth rings are wavy stripes running down the image (v), with
// fine fibres stretched along them.
Image wood_texture() {
    return render([](double s, double t, int, int) {
        const double wobble = tiled_fbm2(s * 3.0, t * 2.0, 3, 2, 4, 11);
        const double rings = 7.0 * s + 1.6 * wobble; // 7 rings per tile, so it tiles in s
        const double phase = rings - std::floor(rings);
        // Late wood: a narrow dark band with a soft leading edge and a sharp trailing one.
        const double late = smoothstep(0.55, 0.85, phase) * (1.0 - smoothstep(0.9, 1.0, phase));
        const double fibre = tiled_fbm2(s * 64.0, t * 4.0, 64, 4, 3, 12);
        const glm::dvec3 light(0.78, 0.56, 0.33), dark(0.42, 0.24, 0.11);
        const double darkness = glm::clamp(0.75 * late + 0.45 * (fibre - 0.5), 0.0, 1.0);
        return glm::mix(light, dark, darkness);
    });
}

// Classic turbulence marble: a sine ramp running diagonally across the tile, warped by
// turbulence; near the sine's zeros, grey veins, with fainter secondary veins at a finer scale.
Image marble_texture() {
    return render([](double s, double t, int, int) {
        const double turbulence = tiled_turbulence2(s * 3.0, t * 3.0, 3, 3, 6, 21);
        const double wave = std::sin(kTwoPi * (1.0 * s + 2.0 * t + 1.1 * turbulence));
        const double vein = std::pow(1.0 - std::fabs(wave), 5.0);
        const double fine_turbulence = tiled_turbulence2(s * 8.0, t * 8.0, 8, 8, 4, 23);
        const double fine = std::pow(
            1.0 - std::fabs(std::sin(kTwoPi * (3.0 * s - 1.0 * t + 0.8 * fine_turbulence))), 12.0);
        const double cloud = tiled_fbm2(s * 6.0, t * 6.0, 6, 6, 4, 22);
        const glm::dvec3 white(0.95, 0.95, 0.93), grey(0.40, 0.41, 0.45);
        const double amount = glm::clamp(0.85 * vein + 0.35 * fine, 0.0, 1.0);
        return glm::mix(white * (0.88 + 0.12 * cloud), grey, amount);
    });
}

// Running bond: 4 bricks of 64 x 32 pixels per row, alternate rows shifted by half a brick,
// 4-pixel mortar joints on each brick's left and top sides.
Image brick_texture() {
    constexpr int kBrickW = 64, kBrickH = 32, kMortar = 4;
    return render([](double s, double t, int x, int y) {
        const int row = y / kBrickH;
        const int shifted = x + (row % 2) * (kBrickW / 2);
        const int column = (shifted / kBrickW) % (kTextureSize / kBrickW);
        const int lx = shifted % kBrickW, ly = y % kBrickH;
        const double grit = hash01(x, y, 0, 31) - 0.5;
        if (lx < kMortar || ly < kMortar) {
            return glm::dvec3(0.72, 0.70, 0.66) * (1.0 + 0.12 * grit);
        }
        const double tone = hash01(column, row, 0, 32);
        const double mottle = tiled_fbm2(s * 16.0, t * 16.0, 16, 16, 3, 33);
        const glm::dvec3 base =
            glm::mix(glm::dvec3(0.58, 0.22, 0.15), glm::dvec3(0.70, 0.34, 0.22), tone);
        // Edges a little darker, as if the arrises were worn and shadowed.
        const int edge = std::min({lx - kMortar, kBrickW - 1 - lx, ly - kMortar, kBrickH - 1 - ly});
        const double bevel = edge < 2 ? 0.85 : 1.0;
        return base * (0.85 + 0.3 * mottle) * (1.0 + 0.1 * grit) * bevel;
    });
}

} // namespace animator::assetgen
