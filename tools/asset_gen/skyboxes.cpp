#include "skyboxes.hpp"

#include "noise.hpp"

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <cmath>

namespace animator::assetgen {

namespace {

double smoothstep(double e0, double e1, double x) {
    const double t = glm::clamp((x - e0) / (e1 - e0), 0.0, 1.0);
    return t * t * (3.0 - 2.0 * t);
}

// Direction from elevation above the horizon and azimuth (0 = -Z, growing towards +X), radians.
glm::dvec3 from_angles(double elevation, double azimuth) {
    return {std::cos(elevation) * std::sin(azimuth), std::sin(elevation),
            -std::cos(elevation) * std::cos(azimuth)};
}

// Coverage of a disc of angular radius `radius`; the rim is softened over 16% of the radius so
// its edge is not a jagged staircase of texels.
double disc(const glm::dvec3 &d, const glm::dvec3 &centre, double radius) {
    const double angle = std::acos(glm::clamp(glm::dot(d, centre), -1.0, 1.0));
    return 1.0 - smoothstep(radius * 0.92, radius * 1.08, angle);
}
// Light scattered around a bright disc, falling off exponentially with the angle.
double glow(const glm::dvec3 &d, const glm::dvec3 &centre, double width) {
    const double angle = std::acos(glm::clamp(glm::dot(d, centre), -1.0, 1.0));
    return std::exp(-angle / width);
}

// Soft cumulus: noise on a flat cloud layer overhead, found by projecting the direction onto
// it (a plane, not the sphere: noise of the raw direction would vary with elevation alone near
// the zenith and draw rings there). The projection is tamed near the horizon, and the octaves are
// few, so the finest detail stays a few texels wide and neighbouring texels (also across a cube
// edge) differ only a little. Faded out towards and below the horizon.
double clouds(const glm::dvec3 &d, std::uint32_t seed) {
    if (d.y <= 0.0) return 0.0;
    const double scale = 2.2 / (d.y + 0.35);
    const double n = fbm3(d.x * scale + 7.0, 1.7, d.z * scale - 3.0, 4, seed);
    return smoothstep(0.46, 0.82, n) * smoothstep(0.0, 0.15, d.y);
}

// Stars: space is cut into cubic cells, kCells per unit length; a hash decides
// whether a cell holds a star and where in the cell. Only star points within half a cell of the
// sphere count, and each star's glow is cut off smoothly within 0.4 cell, so every star that can
// light a direction lies in that direction's cell or a neighbour: searching the 3 x 3 x 3 cells
// around it finds them all and the result is continuous. Each star is a Gaussian about a texel
// wide.
double stars(const glm::dvec3 &d) {
    constexpr double kCells = 40.0;
    constexpr double kSigma = 0.0035;       // radians
    constexpr double kReach = 0.4 / kCells; // radians; the glow is zero beyond
    const glm::dvec3 p = d * kCells;
    const int cx = static_cast<int>(std::floor(p.x)), cy = static_cast<int>(std::floor(p.y)),
              cz = static_cast<int>(std::floor(p.z));
    double light = 0.0;
    for (int dz = -1; dz <= 1; ++dz) {
        for (int dy = -1; dy <= 1; ++dy) {
            for (int dx = -1; dx <= 1; ++dx) {
                const int x = cx + dx, y = cy + dy, z = cz + dz;
                if (hash01(x, y, z, 41) > 0.08) continue;
                const glm::dvec3 point =
                    glm::dvec3(x, y, z) +
                    glm::dvec3(hash01(x, y, z, 42), hash01(x, y, z, 43), hash01(x, y, z, 44));
                if (std::fabs(glm::length(point) - kCells) > 0.5) continue;
                const double angle = glm::length(d - glm::normalize(point)); // chord ~ angle
                if (angle >= kReach) continue;
                const double window = 1.0 - (angle / kReach) * (angle / kReach);
                const double brightness = 0.3 + 0.7 * std::pow(hash01(x, y, z, 45), 2.0);
                light += brightness * window * window *
                         std::exp(-0.5 * (angle * angle) / (kSigma * kSigma));
            }
        }
    }
    return light;
}

glm::dvec3 day(const glm::dvec3 &d) {
    // High up, well inside top.png, so the small disc never straddles a cube edge.
    const glm::dvec3 sun = from_angles(glm::radians(62.0), glm::radians(30.0));
    const double up = glm::clamp(d.y, 0.0, 1.0);
    glm::dvec3 sky =
        glm::mix(glm::dvec3(0.72, 0.84, 0.96), glm::dvec3(0.18, 0.42, 0.84), std::pow(up, 0.6));
    const glm::dvec3 ground = glm::mix(glm::dvec3(0.42, 0.45, 0.38), glm::dvec3(0.24, 0.28, 0.20),
                                       std::pow(glm::clamp(-d.y, 0.0, 1.0), 0.5));
    const double cloud = clouds(d, 51);
    sky = glm::mix(sky, glm::dvec3(0.97, 0.97, 0.98), 0.85 * cloud);
    sky += glm::dvec3(1.0, 0.95, 0.85) * (0.35 * glow(d, sun, 0.12));
    sky = glm::mix(sky, glm::dvec3(1.0, 1.0, 0.98), disc(d, sun, 0.035));
    return glm::mix(ground, sky, smoothstep(-0.03, 0.01, d.y));
}

glm::dvec3 sunset(const glm::dvec3 &d) {
    // Just above the horizon towards -Z, in the middle of back.png.
    const glm::dvec3 sun = from_angles(glm::radians(8.0), 0.0);
    const double up = glm::clamp(d.y, 0.0, 1.0);
    glm::dvec3 sky = glm::mix(glm::dvec3(1.0, 0.52, 0.22), glm::dvec3(0.72, 0.32, 0.45),
                              smoothstep(0.0, 0.35, up));
    sky = glm::mix(sky, glm::dvec3(0.20, 0.12, 0.36), smoothstep(0.25, 1.0, up));
    // Warmer towards the sun's side of the sky.
    const double towards_sun = 0.5 - 0.5 * d.z;
    sky *= 0.8 + 0.2 * towards_sun;
    const glm::dvec3 cloud_colour =
        glm::dvec3(0.55, 0.30, 0.42) + 0.35 * towards_sun * glm::dvec3(0.9, 0.45, 0.2);
    sky = glm::mix(sky, cloud_colour, 0.7 * clouds(d, 61));
    // The glow blends rather than adds, so nothing near the sun outshines the disc itself.
    sky = glm::mix(sky, glm::dvec3(1.0, 0.6, 0.25), 0.8 * glow(d, sun, 0.2));
    sky = glm::mix(sky, glm::dvec3(1.0, 0.78, 0.4), disc(d, sun, 0.12));
    const glm::dvec3 ground = glm::mix(glm::dvec3(0.20, 0.12, 0.16), glm::dvec3(0.08, 0.05, 0.08),
                                       std::pow(glm::clamp(-d.y, 0.0, 1.0), 0.5));
    return glm::mix(ground, sky, smoothstep(-0.03, 0.01, d.y));
}

glm::dvec3 night(const glm::dvec3 &d) {
    // Towards +X, inside right.png.
    const glm::dvec3 moon = from_angles(glm::radians(35.0), glm::radians(90.0));
    const double up = glm::clamp(d.y, 0.0, 1.0);
    glm::dvec3 sky =
        glm::mix(glm::dvec3(0.05, 0.07, 0.15), glm::dvec3(0.0, 0.01, 0.04), std::pow(up, 0.5));
    // Stars fade towards the horizon, where the air is thicker.
    sky += glm::dvec3(0.95, 0.95, 1.0) * (stars(d) * smoothstep(0.0, 0.25, d.y));
    sky += glm::dvec3(0.6, 0.65, 0.8) * (0.12 * glow(d, moon, 0.08));
    const double on_moon = disc(d, moon, 0.045);
    if (on_moon > 0.0) {
        // Maria: a few darker patches on the disc.
        const double maria = fbm3(d.x * 40.0, d.y * 40.0, d.z * 40.0, 3, 71);
        sky = glm::mix(sky, glm::dvec3(0.92, 0.92, 0.86) * (0.8 + 0.25 * maria), on_moon);
    }
    const glm::dvec3 ground(0.01, 0.012, 0.02);
    return glm::mix(ground, sky, smoothstep(-0.03, 0.01, d.y));
}

} // namespace

const std::array<const char *, 6> &cube_face_files() {
    static const std::array<const char *, 6> files = {"right.png",  "left.png",  "top.png",
                                                      "bottom.png", "front.png", "back.png"};
    return files;
}

glm::dvec3 cube_direction(int face, double sc, double tc) {
    switch (face) {
    case 0:
        return {1.0, -tc, -sc};
    case 1:
        return {-1.0, -tc, sc};
    case 2:
        return {sc, 1.0, tc};
    case 3:
        return {sc, -1.0, -tc};
    case 4:
        return {sc, -tc, 1.0};
    default:
        return {-sc, -tc, -1.0};
    }
}

glm::dvec3 sky_colour(Sky sky, const glm::dvec3 &unit_direction) {
    switch (sky) {
    case Sky::Day:
        return day(unit_direction);
    case Sky::Sunset:
        return sunset(unit_direction);
    default:
        return night(unit_direction);
    }
}

Image sky_face(Sky sky, int face) {
    Image image(kSkyFaceSize, kSkyFaceSize);
    for (int row = 0; row < kSkyFaceSize; ++row) {
        for (int column = 0; column < kSkyFaceSize; ++column) {
            // Texel centres, so the faces' outermost texels sit half a texel from each edge.
            const double sc = 2.0 * (column + 0.5) / kSkyFaceSize - 1.0;
            const double tc = 2.0 * (row + 0.5) / kSkyFaceSize - 1.0;
            image.set(column, row, sky_colour(sky, glm::normalize(cube_direction(face, sc, tc))));
        }
    }
    return image;
}

} // namespace animator::assetgen
