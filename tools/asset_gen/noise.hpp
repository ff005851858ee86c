// Deterministic hashing and noise. Everything here is a pure function of its arguments, so the
// generated assets come out byte-identical on every run (std:: random engines are avoided: their
// distributions are not specified bit-for-bit across standard libraries).
#pragma once

#include <cstdint>

namespace animator::assetgen {

// A well-mixed 32-bit hash (the "lowbias32" finaliser).
std::uint32_t hash_u32(std::uint32_t x);
// Hash of integer lattice coordinates and a seed, mapped to [0, 1).
double hash01(int x, int y, int z, std::uint32_t seed);

// Value noise on a 2D lattice that repeats every `period_x` cells in x and `period_y` in y, so a
// texture that samples exactly one period across each side tiles without a seam (separate
// periods allow grain stretched along one axis). Result in [0, 1].
double tiled_noise2(double x, double y, int period_x, int period_y, std::uint32_t seed);
// Sum of `octaves` octaves of tiled_noise2, each at twice the frequency and half the amplitude;
// still tiles because every octave's periods double with its frequency. Result in [0, 1].
double tiled_fbm2(double x, double y, int period_x, int period_y, int octaves, std::uint32_t seed);
// Like tiled_fbm2 but summing |2n - 1|: the creases make marble-like veins. Result in [0, 1].
double tiled_turbulence2(double x, double y, int period_x, int period_y, int octaves,
                         std::uint32_t seed);

// Value noise on an unbounded 3D lattice, for functions of a direction (skies). Result in [0, 1].
double noise3(double x, double y, double z, std::uint32_t seed);
double fbm3(double x, double y, double z, int octaves, std::uint32_t seed);

} // namespace animator::assetgen
