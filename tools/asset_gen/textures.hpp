// Procedural 256 x 256 surface textures. All of them tile: every noise term repeats exactly once
// across the image, and every periodic term has an integer number of periods per side.
#pragma once

#include "image.hpp"

namespace animator::assetgen {

constexpr int kTextureSize = 256;

Image checker_texture(); // 8 x 8 squares, black and white, white at the top-left
Image wood_texture();
Image marble_texture();
Image brick_texture();

} // namespace animator::assetgen
