// The generated cube-map skyboxes: format, seamless edges, and what each sky shows.
#include "asset_readers.hpp"

#include <catch2/catch.hpp>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <set>
#include <string>
#include <utility>
#include <vector>

using namespace animator::test::assets;

namespace {

constexpr int kSize = 256;
// OpenGL's face order: +X, -X, +Y, -Y, +Z, -Z.
const char *const kFaces[6] = {"right", "left", "top", "bottom", "front", "back"};
const char *const kSkies[3] = {"day", "sunset", "night"};

using Cube = std::array<Image, 6>;

Cube load(const std::string &sky) {
    Cube cube;
    for (int f = 0; f < 6; ++f)
        cube[static_cast<std::size_t>(f)] =
            read_image(generated_dir() / "skyboxes" / sky / (std::string(kFaces[f]) + ".png"));
    return cube;
}

// The direction through face coordinates (sc, tc), sc along a row and tc down the rows.
glm::dvec3 direction(int face, double sc, double tc) {
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
glm::dvec3 texel_direction(int face, int column, int row) {
    return direction(face, 2.0 * (column + 0.5) / kSize - 1.0, 2.0 * (row + 0.5) / kSize - 1.0);
}

struct Texel {
    int face, column, row;
};
// The OpenGL specification's face selection (the major axis) and its (sc, tc) table, written
// independently of `direction` above.
Texel texel_at(const glm::dvec3 &d) {
    const double ax = std::fabs(d.x), ay = std::fabs(d.y), az = std::fabs(d.z);
    int face;
    double sc, tc, ma;
    if (ax >= ay && ax >= az) {
        face = d.x > 0 ? 0 : 1;
        sc = d.x > 0 ? -d.z : d.z;
        tc = -d.y;
        ma = ax;
    } else if (ay >= az) {
        face = d.y > 0 ? 2 : 3;
        sc = d.x;
        tc = d.y > 0 ? d.z : -d.z;
        ma = ay;
    } else {
        face = d.z > 0 ? 4 : 5;
        sc = d.z > 0 ? d.x : -d.x;
        tc = -d.y;
        ma = az;
    }
    auto index = [](double c) {
        return std::clamp(static_cast<int>(std::floor((c + 1.0) / 2.0 * kSize)), 0, kSize - 1);
    };
    return {face, index(sc / ma), index(tc / ma)};
}

int channel(const Cube &cube, const Texel &t, int c) {
    return cube[static_cast<std::size_t>(t.face)].at(t.column, t.row, c);
}

struct SeamStats {
    int max_difference = 0; // per channel, 0..255
    double mean_difference = 0.0;
    // How far the step across the seam exceeds the largest step from either texel to one of its
    // eight neighbours on its own face: a sharp feature (a star) may legitimately change as fast
    // across the seam as it does inside a face, but no faster.
    int max_excess = 0;
    std::set<std::pair<int, int>> edges; // face pairs met
    // Where the largest difference and the largest excess are, for the failure message.
    Texel max_a{0, 0, 0}, max_b{0, 0, 0}, worst_a{0, 0, 0}, worst_b{0, 0, 0};
};

int largest_local_step(const Cube &cube, const Texel &t, int c) {
    int step = 0;
    for (int dr = -1; dr <= 1; ++dr) {
        for (int dc = -1; dc <= 1; ++dc) {
            const Texel n{t.face, t.column + dc, t.row + dr};
            if (n.column < 0 || n.column >= kSize || n.row < 0 || n.row >= kSize) continue;
            step = std::max(step, std::abs(channel(cube, t, c) - channel(cube, n, c)));
        }
    }
    return step;
}

// For every border texel of every face, steps one texel outward across the cube edge and finds
// the texel there on the neighbouring face, and compares the two.
SeamStats seams(const Cube &cube) {
    SeamStats stats;
    double sum = 0.0;
    int count = 0;
    for (int face = 0; face < 6; ++face) {
        for (int row = 0; row < kSize; ++row) {
            for (int column = 0; column < kSize; ++column) {
                std::vector<std::pair<int, int>> outward;
                if (column == 0) outward.push_back({-1, 0});
                if (column == kSize - 1) outward.push_back({1, 0});
                if (row == 0) outward.push_back({0, -1});
                if (row == kSize - 1) outward.push_back({0, 1});
                for (const auto &[dc, dr] : outward) {
                    const Texel a{face, column, row};
                    const Texel b = texel_at(texel_direction(face, column + dc, row + dr));
                    REQUIRE(b.face != face);
                    stats.edges.insert(std::minmax(face, b.face));
                    for (int c = 0; c < 3; ++c) {
                        const int across = std::abs(channel(cube, a, c) - channel(cube, b, c));
                        const int local = std::max(largest_local_step(cube, a, c),
                                                   largest_local_step(cube, b, c));
                        if (across > stats.max_difference) {
                            stats.max_difference = across;
                            stats.max_a = a;
                            stats.max_b = b;
                        }
                        if (across - local > stats.max_excess) {
                            stats.max_excess = across - local;
                            stats.worst_a = a;
                            stats.worst_b = b;
                        }
                        sum += across;
                        ++count;
                    }
                }
            }
        }
    }
    stats.mean_difference = sum / count;
    return stats;
}

std::string describe(const Texel &t) {
    return std::string(kFaces[t.face]) + " (" + std::to_string(t.column) + ", " +
           std::to_string(t.row) + ")";
}

double mean_luminance(const Cube &cube) {
    double sum = 0.0;
    for (const auto &im : cube)
        for (int y = 0; y < im.height; ++y)
            for (int x = 0; x < im.width; ++x) sum += im.luminance(x, y);
    return sum / (6.0 * kSize * kSize);
}

Texel brightest(const Cube &cube) {
    Texel best{0, 0, 0};
    double best_l = -1.0;
    for (int f = 0; f < 6; ++f) {
        const auto &im = cube[static_cast<std::size_t>(f)];
        for (int y = 0; y < kSize; ++y) {
            for (int x = 0; x < kSize; ++x) {
                const double l = im.at(x, y, 0) + im.at(x, y, 1) + im.at(x, y, 2);
                if (l > best_l) {
                    best_l = l;
                    best = {f, x, y};
                }
            }
        }
    }
    return best;
}

double elevation_degrees(const Texel &t) {
    const glm::dvec3 d = glm::normalize(texel_direction(t.face, t.column, t.row));
    return glm::degrees(std::asin(d.y));
}

} // namespace

TEST_CASE("skybox faces load as 256 x 256 RGB images") {
    for (const char *sky : kSkies) {
        for (const auto &im : load(sky)) {
            INFO(sky);
            CHECK(im.width == kSize);
            CHECK(im.height == kSize);
            CHECK(im.channels == 3);
        }
    }
}

TEST_CASE("the face table and the OpenGL face selection agree on every texel") {
    int mismatched = 0;
    for (int face = 0; face < 6; ++face) {
        for (int row = 0; row < kSize; ++row) {
            for (int column = 0; column < kSize; ++column) {
                const Texel t = texel_at(texel_direction(face, column, row));
                if (t.face != face || t.column != column || t.row != row) ++mismatched;
            }
        }
    }
    CHECK(mismatched == 0);
}

TEST_CASE("skybox faces meet seamlessly along all 12 cube edges") {
    for (const char *sky : kSkies) {
        INFO(sky);
        const SeamStats s = seams(load(sky));
        INFO("max " << s.max_difference << " between " << describe(s.max_a) << " and "
                    << describe(s.max_b) << "; mean " << s.mean_difference << "; max excess "
                    << s.max_excess << " between " << describe(s.worst_a) << " and "
                    << describe(s.worst_b));
        CHECK(s.edges.size() == 12);
        CHECK(s.mean_difference <= 3.0);
        // Stars are point-like, so across a seam they change as fast as between any two
        // neighbouring texels; the night sky is held to "no sharper than inside the faces".
        if (std::string(sky) != "night") CHECK(s.max_difference <= 12);
        CHECK(s.max_excess <= 12);
    }
}

TEST_CASE("the night sky is darker than the sunset sky, which is darker than the day sky") {
    const double day = mean_luminance(load("day")), sunset = mean_luminance(load("sunset")),
                 night = mean_luminance(load("night"));
    INFO("day " << day << ", sunset " << sunset << ", night " << night);
    CHECK(night < sunset);
    CHECK(sunset < day);
}

TEST_CASE("the sky is brighter than the ground below the horizon") {
    for (const char *sky : kSkies) {
        INFO(sky);
        const Cube cube = load(sky);
        double top = 0.0, bottom = 0.0;
        for (int y = 0; y < kSize; ++y) {
            for (int x = 0; x < kSize; ++x) {
                top += cube[2].luminance(x, y);
                bottom += cube[3].luminance(x, y);
            }
        }
        CHECK(top > bottom);
    }
}

TEST_CASE("the day sun is white and high, the sunset sun orange and near the horizon") {
    const Cube day = load("day");
    const Texel day_sun = brightest(day);
    INFO("day sun on face " << day_sun.face << " at elevation " << elevation_degrees(day_sun));
    CHECK(day_sun.face == 2);
    CHECK(elevation_degrees(day_sun) > 45.0);
    for (int c = 0; c < 3; ++c) CHECK(channel(day, day_sun, c) >= 240);

    const Cube sunset = load("sunset");
    const Texel sunset_sun = brightest(sunset);
    const double elevation = elevation_degrees(sunset_sun);
    INFO("sunset sun on face " << sunset_sun.face << " at elevation " << elevation);
    CHECK(elevation > 0.0);
    CHECK(elevation < 20.0);
    CHECK(channel(sunset, sunset_sun, 0) >= 240);
    CHECK(channel(sunset, sunset_sun, 0) > channel(sunset, sunset_sun, 1) + 40);
    CHECK(channel(sunset, sunset_sun, 1) > channel(sunset, sunset_sun, 2) + 40);
}

TEST_CASE("the night sky has stars: many small bright points above the horizon") {
    const Cube night = load("night");
    int stars = 0;
    for (int f = 0; f < 6; ++f) {
        const Image &im = night[static_cast<std::size_t>(f)];
        for (int y = 1; y + 1 < kSize; ++y) {
            for (int x = 1; x + 1 < kSize; ++x) {
                const double l = im.luminance(x, y);
                if (l < 60.0) continue;
                // A local maximum standing well above the texels two away: a point, not a disc.
                bool peak = true;
                for (int dy = -1; dy <= 1; ++dy)
                    for (int dx = -1; dx <= 1; ++dx)
                        if (im.luminance(x + dx, y + dy) > l) peak = false;
                const double ring = (x >= 2 && y >= 2 && x + 2 < kSize && y + 2 < kSize)
                                        ? std::max({im.luminance(x - 2, y), im.luminance(x + 2, y),
                                                    im.luminance(x, y - 2), im.luminance(x, y + 2)})
                                        : l;
                if (peak && ring < 0.6 * l && texel_direction(f, x, y).y > 0.0) ++stars;
            }
        }
    }
    INFO(stars << " stars");
    CHECK(stars >= 200);
}
