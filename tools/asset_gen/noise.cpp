#include "noise.hpp"

#include <cmath>

namespace animator::assetgen {

namespace {

// Quintic fade: C2-continuous, so noise-derived colours have no visible lattice creases.
double fade(double t) {
    return t * t * t * (t * (t * 6.0 - 15.0) + 10.0);
}

double lerp(double a, double b, double t) {
    return a + (b - a) * t;
}

int wrap(int i, int period) {
    const int m = i % period;
    return m < 0 ? m + period : m;
}

} // namespace

std::uint32_t hash_u32(std::uint32_t x) {
    x ^= x >> 16;
    x *= 0x7feb352dU;
    x ^= x >> 15;
    x *= 0x846ca68bU;
    x ^= x >> 16;
    return x;
}

double hash01(int x, int y, int z, std::uint32_t seed) {
    // Odd multipliers spread neighbouring lattice points apart before the two mixing rounds;
    // unsigned arithmetic, so wrapping is defined.
    const std::uint32_t key = static_cast<std::uint32_t>(x) * 0x8da6b343U +
                              static_cast<std::uint32_t>(y) * 0xd8163841U +
                              static_cast<std::uint32_t>(z) * 0xcb1ab31fU;
    const std::uint32_t h = hash_u32(hash_u32(key) ^ (seed * 0x9e3779b9U));
    // 24 bits fit a double exactly, so the mapping itself cannot introduce rounding differences.
    return static_cast<double>(h >> 8) / 16777216.0;
}

double tiled_noise2(double x, double y, int period_x, int period_y, std::uint32_t seed) {
    const double fx = std::floor(x), fy = std::floor(y);
    const int ix = static_cast<int>(fx), iy = static_cast<int>(fy);
    const double tx = fade(x - fx), ty = fade(y - fy);
    const int x0 = wrap(ix, period_x), x1 = wrap(ix + 1, period_x);
    const int y0 = wrap(iy, period_y), y1 = wrap(iy + 1, period_y);
    const double a = lerp(hash01(x0, y0, 0, seed), hash01(x1, y0, 0, seed), tx);
    const double b = lerp(hash01(x0, y1, 0, seed), hash01(x1, y1, 0, seed), tx);
    return lerp(a, b, ty);
}

namespace {

// Octaves of tiled noise, each at twice the frequency (and period) and half the amplitude of the
// last, summed through `shape` and normalised by the total amplitude.
template <class Shape>
double tiled_octaves(double x, double y, int period_x, int period_y, int octaves, std::uint32_t seed,
                     Shape shape) {
    double sum = 0.0, amplitude = 1.0, total = 0.0;
    for (int o = 0; o < octaves; ++o) {
        sum += amplitude * shape(tiled_noise2(x, y, period_x, period_y, seed + static_cast<std::uint32_t>(o)));
        total += amplitude;
        x *= 2.0;
        y *= 2.0;
        period_x *= 2;
        period_y *= 2;
        amplitude *= 0.5;
    }
    return sum / total;
}

} // namespace

double tiled_fbm2(double x, double y, int period_x, int period_y, int octaves, std::uint32_t seed) {
    return tiled_octaves(x, y, period_x, period_y, octaves, seed, [](double n) { return n; });
}

double tiled_turbulence2(double x, double y, int period_x, int period_y, int octaves,
                         std::uint32_t seed) {
    return tiled_octaves(x, y, period_x, period_y, octaves, seed,
                         [](double n) { return std::fabs(2.0 * n - 1.0); });
}

double noise3(double x, double y, double z, std::uint32_t seed) {
    const double fx = std::floor(x), fy = std::floor(y), fz = std::floor(z);
    const int ix = static_cast<int>(fx), iy = static_cast<int>(fy), iz = static_cast<int>(fz);
    const double tx = fade(x - fx), ty = fade(y - fy), tz = fade(z - fz);
    double layer[2];
    for (int dz = 0; dz < 2; ++dz) {
        const double a = lerp(hash01(ix, iy, iz + dz, seed), hash01(ix + 1, iy, iz + dz, seed), tx);
        const double b =
            lerp(hash01(ix, iy + 1, iz + dz, seed), hash01(ix + 1, iy + 1, iz + dz, seed), tx);
        layer[dz] = lerp(a, b, ty);
    }
    return lerp(layer[0], layer[1], tz);
}

double fbm3(double x, double y, double z, int octaves, std::uint32_t seed) {
    double sum = 0.0, amplitude = 1.0, total = 0.0;
    for (int o = 0; o < octaves; ++o) {
        sum += amplitude * noise3(x, y, z, seed + static_cast<std::uint32_t>(o));
        total += amplitude;
        x *= 2.0;
        y *= 2.0;
        z *= 2.0;
        amplitude *= 0.5;
    }
    return sum / total;
}

} // namespace animator::assetgen
