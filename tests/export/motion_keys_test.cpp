// The keys of motion_keys.hpp against the functions they hold: exact where the motion is a cubic
// or a turn at a constant rate about one axis, within the bound where it is sampled.
#include "export/motion_keys.hpp"

#include <catch2/catch.hpp>

#include <glm/geometric.hpp>

#include <cmath>

using namespace animator;
using namespace animator::motion_keys;

namespace {

double worst_gap(const std::vector<VecKey> &keys, const std::function<glm::dvec3(double)> &f,
                 double t0, double t1) {
    double worst = 0.0;
    for (int k = 0; k <= 1000; ++k) {
        const double t = t0 + (t1 - t0) * k / 1000.0;
        worst = std::max(worst, glm::length(hermite_at(keys, t) - f(t)));
    }
    return worst;
}

} // namespace

TEST_CASE("a parabola with its velocity is one Hermite span, exact to rounding") {
    const glm::dvec3 p0(1.0, 5.0, -2.0), v0(3.0, 4.0, 0.5), a(0.0, -9.81, 0.0);
    Piece piece;
    piece.value = [&](double t) {
        return p0 + v0 * (t - 0.25) + 0.5 * a * (t - 0.25) * (t - 0.25);
    };
    piece.rate = [&](double t) { return v0 + a * (t - 0.25); };
    std::vector<VecKey> keys;
    PieceStats stats;
    append_piece(keys, 0.25, 1.75, piece, 1e-9, &stats);
    REQUIRE(keys.size() == 2);
    CHECK(stats.exact == 1);
    CHECK(stats.sampled == 0);
    CHECK(worst_gap(keys, piece.value, 0.25, 1.75) < 1e-14 * 10.0);
    CHECK_FALSE(is_linear(keys, 1e-9));
}

TEST_CASE(
    "a cubic known only by its values is one span: the ends' derivatives come from its own cubic") {
    auto f = [](double t) {
        return glm::dvec3(2.0 * t * t * t - t * t + 3.0, -t * t * t, 0.5 * t);
    };
    std::vector<VecKey> keys;
    PieceStats stats;
    append_piece(keys, -1.0, 2.0, Piece{f, {}}, 1e-10, &stats);
    CHECK(keys.size() == 2);
    CHECK(stats.exact == 1);
    CHECK(worst_gap(keys, f, -1.0, 2.0) < 1e-12);
    // The fitted derivatives are the true ones: 6t^2 - 2t, -3t^2, 0.5.
    CHECK(keys[0].out.x == Approx(6.0 + 2.0).epsilon(1e-12));
    CHECK(keys[1].in.y == Approx(-12.0).epsilon(1e-12));
}

TEST_CASE("pieces in a row share their key: the in-tangent of the one before, the out-tangent of "
          "the next") {
    // A bounce at t = 1: falling at -9.81 m/s before, rising at +9.81 after.
    Piece fall{[](double t) { return glm::dvec3(0.0, 1.0 + 4.905 * (1.0 - t * t), 0.0); },
               [](double t) { return glm::dvec3(0.0, -9.81 * t, 0.0); }};
    Piece rise{[](double t) {
                   return glm::dvec3(0.0, 1.0 + 9.81 * (t - 1.0) - 4.905 * (t - 1.0) * (t - 1.0),
                                     0.0);
               },
               [](double t) { return glm::dvec3(0.0, 9.81 - 9.81 * (t - 1.0), 0.0); }};
    std::vector<VecKey> keys;
    append_piece(keys, 0.0, 1.0, fall, 1e-9);
    append_piece(keys, 1.0, 2.0, rise, 1e-9);
    REQUIRE(keys.size() == 3);
    CHECK(keys[1].t == 1.0);
    CHECK(keys[1].in.y == Approx(-9.81));
    CHECK(keys[1].out.y == Approx(9.81));
    CHECK(std::abs(hermite_at(keys, 1.5).y - rise.value(1.5).y) < 1e-14);
    CHECK(std::abs(hermite_at(keys, 0.5).y - fall.value(0.5).y) < 1e-14);
}

TEST_CASE("a motion that is no cubic is split until it strays less than the tolerance") {
    auto f = [](double t) { return glm::dvec3(std::sin(3.0 * t), std::cos(2.0 * t), 0.0); };
    auto rate = [](double t) {
        return glm::dvec3(3.0 * std::cos(3.0 * t), -2.0 * std::sin(2.0 * t), 0.0);
    };
    std::vector<VecKey> keys;
    PieceStats stats;
    append_piece(keys, 0.0, 4.0, Piece{f, rate}, 1e-7, &stats);
    CHECK(stats.sampled == 1);
    CHECK(keys.size() > 10);
    CHECK(worst_gap(keys, f, 0.0, 4.0) <
          2e-7); // checked at 7 points a span; between them a little more
}

TEST_CASE("straight keys are told from curved ones") {
    std::vector<VecKey> keys;
    append_piece(keys, 0.0, 1.0, Piece{[](double t) { return glm::dvec3(2.0 * t, 1.0, -t); }, {}},
                 1e-9);
    append_piece(keys, 1.0, 3.0,
                 Piece{[](double t) { return glm::dvec3(2.0 - (t - 1.0), 1.0, -1.0); }, {}}, 1e-9);
    CHECK(is_linear(keys, 1e-9));
    keys.back().in.x += 1e-3;
    CHECK_FALSE(is_linear(keys, 1e-9));
}

TEST_CASE("a turn at a constant rate about one axis is exact, with keys at most 90 degrees apart") {
    const glm::dvec3 axis = glm::normalize(glm::dvec3(1.0, 2.0, -0.5));
    const glm::dquat q0 = glm::angleAxis(0.3, glm::normalize(glm::dvec3(0.0, 1.0, 1.0)));
    const double rate = 3.0 * 2.0 * M_PI; // three turns a second
    auto f = [&](double t) { return glm::angleAxis(rate * t, axis) * q0; };
    std::vector<QuatKey> keys;
    PieceStats stats;
    append_rotation(keys, 0.0, 1.0, f, 1e-6, &stats);
    CHECK(stats.sampled == 1); // split for the 90 degree rule only
    CHECK(keys.size() >= 13);  // 1080 degrees in spans of at most 90
    double worst = 0.0;
    for (size_t k = 1; k < keys.size(); ++k) {
        CHECK(angle_between(keys[k - 1].q, keys[k].q) <= kMaxKeyTurn + 1e-12);
        CHECK(glm::dot(keys[k - 1].q, keys[k].q) >= 0.0); // signs chosen nearest
    }
    for (int k = 0; k <= 1000; ++k)
        worst = std::max(worst, angle_between(slerp_at(keys, k / 1000.0), f(k / 1000.0)));
    CHECK(worst < 1e-12);
}

TEST_CASE("a turn about a moving axis is sampled within the bound") {
    // Keyed Euler angles turning about X and Z at once: not a slerp.
    auto f = [](double t) {
        return glm::angleAxis(2.0 * t, glm::dvec3(1, 0, 0)) *
               glm::angleAxis(0.0, glm::dvec3(0, 1, 0)) *
               glm::angleAxis(-3.0 * t, glm::dvec3(0, 0, 1));
    };
    std::vector<QuatKey> keys;
    PieceStats stats;
    const double bound = 1e-5;
    append_rotation(keys, 0.0, 2.0, f, bound, &stats);
    CHECK(stats.sampled == 1);
    double worst = 0.0;
    for (int k = 0; k <= 4000; ++k)
        worst = std::max(worst, angle_between(slerp_at(keys, k / 2000.0), f(k / 2000.0)));
    CHECK(worst < 1.5 * bound);
}

TEST_CASE("keys float32 cannot tell apart are merged, leaving times strictly increasing") {
    std::vector<VecKey> keys{{0.0, glm::dvec3(0), glm::dvec3(0.0), glm::dvec3(1.0)},
                             {10.0, glm::dvec3(-1), glm::dvec3(5.0), glm::dvec3(2.0)},
                             {10.0 + 1e-9, glm::dvec3(2), glm::dvec3(5.0), glm::dvec3(3.0)},
                             {11.0, glm::dvec3(3), glm::dvec3(6.0), glm::dvec3(0.0)}};
    std::vector<float> times;
    CHECK(merge_float_times(keys, 0.0, times) == 1);
    REQUIRE(times.size() == 3);
    CHECK(keys.size() == 3);
    CHECK(times[0] < times[1]);
    CHECK(times[1] < times[2]);
    CHECK(keys[1].in == glm::dvec3(-1));   // arriving as the first said
    CHECK(keys[1].out == glm::dvec3(3.0)); // leaving as the last said

    std::vector<QuatKey> turns{{1.0, glm::dquat(1, 0, 0, 0)},
                               {1.0 + 1e-9, glm::dquat(0, 1, 0, 0)},
                               {2.0, glm::dquat(0, 0, 1, 0)}};
    CHECK(merge_float_times(turns, 0.5, times) == 1);
    CHECK(times == std::vector<float>{0.5f, 1.5f});
    CHECK(turns[0].q == glm::dquat(1, 0, 0, 0));
}
