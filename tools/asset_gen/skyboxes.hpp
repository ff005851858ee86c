// Cube-map skyboxes. Each texel's colour is a pure function of its view direction, so the six
// faces meet seamlessly at the cube's edges by construction.
#pragma once

#include "image.hpp"

#include <glm/vec3.hpp>

#include <array>

namespace animator::assetgen {

constexpr int kSkyFaceSize = 256;

enum class Sky { Day, Sunset, Night };

// File names in OpenGL's face order: +X, -X, +Y, -Y, +Z, -Z.
const std::array<const char *, 6> &cube_face_files();

// The OpenGL cube-map table: the direction through face coordinates sc, tc in [-1, 1], where sc
// runs along a row (left to right) and tc down the rows (row 0 first). Not normalised.
glm::dvec3 cube_direction(int face, double sc, double tc);

glm::dvec3 sky_colour(Sky sky, const glm::dvec3 &unit_direction);
Image sky_face(Sky sky, int face);

} // namespace animator::assetgen
