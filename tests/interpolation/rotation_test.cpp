// The camera's rotation: unit quaternions (w, x, y, z), slerp along the shorter arc, and the
// angular velocity in rad/s (world frame) as the rate.
#include "interp_support.hpp"

#include "rotation.hpp"

#include <cmath>
#include <random>

using namespace interp_test;

namespace {

const double kPi = std::acos(-1.0);

// A rotation by `degrees` about the unit axis (ax, ay, az): (cos(a/2), sin(a/2) axis).
std::array<double, 4> about(double degrees, double ax, double ay, double az) {
    const double half = degrees * kPi / 360.0;
    return {std::cos(half), std::sin(half) * ax, std::sin(half) * ay, std::sin(half) * az};
}

interp::Quat quat(const std::array<double, 4> &q) { return {q[0], q[1], q[2], q[3]}; }

interp::Quat random_unit(std::mt19937 &rng) {
    std::normal_distribution<double> n(0.0, 1.0);
    return interp::normalized({n(rng), n(rng), n(rng), n(rng)});
}

// max |R^T R - I| and det R.
struct MatrixCheck {
    double orthogonality_error;
    double determinant;
};

MatrixCheck check_matrix(const interp::Quat &q) {
    const auto r = interp::to_matrix(q);
    double worst = 0.0;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            double rtr = 0.0;
            for (int k = 0; k < 3; ++k) rtr += r[static_cast<size_t>(3 * k + i)] * r[static_cast<size_t>(3 * k + j)];
            worst = std::max(worst, std::fabs(rtr - (i == j ? 1.0 : 0.0)));
        }
    const double det = r[0] * (r[4] * r[8] - r[5] * r[7]) - r[1] * (r[3] * r[8] - r[5] * r[6]) +
                       r[2] * (r[3] * r[7] - r[4] * r[6]);
    return {worst, det};
}

// |q| and whether it is +-expected (q and -q are one orientation).
double orientation_distance(const interp::Quat &q, const std::array<double, 4> &expected) {
    return 1.0 - std::fabs(interp::dot(q, quat(expected)));
}

interp::Quat value_quat(const Evaluation &e, size_t i) {
    return {e.value(i, 0), e.value(i, 1), e.value(i, 2), e.value(i, 3)};
}

} // namespace

TEST_CASE("the Slerp class turns at a steady rate about one axis") {
    const interp::Slerp s(quat({1, 0, 0, 0}), quat(about(90, 0, 1, 0)));
    CHECK(s.angle() == close(kPi / 2));
    const interp::Vec3 w = s.rotation_vector(); // pi/2 about world Y
    CHECK(w.x == close(0.0));
    CHECK(w.y == close(kPi / 2));
    CHECK(w.z == close(0.0));
    const interp::Quat half = s.at(0.5); // 45 degrees about Y
    const auto expected = about(45, 0, 1, 0);
    CHECK(half.w == close(expected[0]));
    CHECK(half.x == close(0.0));
    CHECK(half.y == close(expected[2]));
    CHECK(half.z == close(0.0));
    CHECK(orientation_distance(s.at(1.0), about(90, 0, 1, 0)) == close(0.0));
    CHECK(orientation_distance(s.at(0.0), {1, 0, 0, 0}) == close(0.0));
}

TEST_CASE("camera slerp halfway from identity to 90 degrees about Y is 45 degrees about Y") {
    Interpolator linear("interpolation.linear");
    const std::vector<ani_key> keys = {key(0.0, {1, 0, 0, 0}), key(2.0, about(90, 0, 1, 0))};
    const Evaluation e = linear.evaluate(channel(ANI_CHANNEL_CAMERA_ROTATION, keys), {0.5, 1.0, 5.0});
    REQUIRE(e.code == ANI_OK);
    // t = 1 of 2: 45 degrees about Y = (cos 22.5, 0, sin 22.5, 0); t = 0.5: 22.5 degrees.
    const auto at45 = about(45, 0, 1, 0), at22 = about(22.5, 0, 1, 0);
    for (int c = 0; c < 4; ++c) {
        CHECK(e.value(1, c) == close(at45[static_cast<size_t>(c)]));
        CHECK(e.value(0, c) == close(at22[static_cast<size_t>(c)]));
    }
    // The angular velocity: (pi/2) / 2 s about +Y, also after the last key.
    for (size_t i = 0; i < 3; ++i) {
        CHECK(e.rate(i, 0) == close(0.0));
        CHECK(e.rate(i, 1) == close(kPi / 4));
        CHECK(e.rate(i, 2) == close(0.0));
        CHECK(e.rate(i, 3) == 0.0);
    }
    for (int c = 0; c < 4; ++c) CHECK(e.value(2, c) == keys[1].value[c]);
}

TEST_CASE("camera slerp takes the shorter arc when the quaternions' dot product is negative") {
    Interpolator linear("interpolation.linear");
    // -(90 degrees about Y) is the same orientation; the long arc would pass 135 degrees at
    // halfway, the short one passes 45.
    auto minus90 = about(90, 0, 1, 0);
    for (double &c : minus90) c = -c;
    const std::vector<ani_key> keys = {key(0.0, {1, 0, 0, 0}), key(1.0, minus90)};
    const Evaluation e = linear.evaluate(channel(ANI_CHANNEL_CAMERA_ROTATION, keys), {0.5, 1.0});
    REQUIRE(e.code == ANI_OK);
    CHECK(orientation_distance(value_quat(e, 0), about(45, 0, 1, 0)) == close(0.0));
    CHECK(std::hypot(e.rate(0, 0), e.rate(0, 1), e.rate(0, 2)) == close(kPi / 2)); // (pi/2) / 1 s
    CHECK(e.rate(0, 1) == close(kPi / 2));
    for (int c = 0; c < 4; ++c) CHECK(e.value(1, c) == minus90[static_cast<size_t>(c)]);
}

TEST_CASE("every interpolated camera rotation gives an orthonormal matrix") {
    std::mt19937 rng(99);
    double worst = 0.0, worst_det = 0.0;
    for (int pair = 0; pair < 2000; ++pair) {
        const interp::Slerp s(random_unit(rng), random_unit(rng));
        for (int i = 0; i <= 20; ++i) {
            const MatrixCheck m = check_matrix(s.at(i / 20.0));
            worst = std::max(worst, m.orthogonality_error);
            worst_det = std::max(worst_det, std::fabs(m.determinant - 1.0));
        }
    }
    CHECK(worst < 1e-12);
    CHECK(worst_det < 1e-12);

    // Through the plugin, linear and smooth with ease, over many keys.
    Interpolator linear("interpolation.linear");
    Interpolator smooth("interpolation.smooth");
    smooth.set_param("ease", 1.0);
    std::vector<ani_key> keys;
    for (int k = 0; k < 50; ++k) {
        const interp::Quat q = random_unit(rng);
        keys.push_back(key(0.3 * k, {q.w, q.x, q.y, q.z}));
    }
    const ani_channel ch = channel(ANI_CHANNEL_CAMERA_ROTATION, keys);
    const std::vector<double> times = linspace(-1.0, 16.0, 10000);
    for (const Interpolator *plugin : {&linear, &smooth}) {
        const Evaluation e = plugin->evaluate(ch, times);
        REQUIRE(e.code == ANI_OK);
        for (size_t i = 0; i < times.size(); ++i) {
            const MatrixCheck m = check_matrix(value_quat(e, i));
            CAPTURE(i);
            CHECK(m.orthogonality_error < 1e-12);
            CHECK(m.determinant == close(1.0));
        }
    }
}

TEST_CASE("camera angular velocity has magnitude angle over dt and matches the motion") {
    Interpolator linear("interpolation.linear");
    std::mt19937 rng(5);
    for (int trial = 0; trial < 100; ++trial) {
        const interp::Quat a = random_unit(rng), b = random_unit(rng);
        const double dt = 0.5 + trial * 0.01;
        const std::vector<ani_key> keys = {key(1.0, {a.w, a.x, a.y, a.z}), key(1.0 + dt, {b.w, b.x, b.y, b.z})};
        // The angle between two orientations: 2 acos |a . b|.
        const double angle = 2.0 * std::acos(std::min(1.0, std::fabs(interp::dot(a, b))));
        const double t = 1.0 + 0.3 * dt, h = 1e-6;
        const Evaluation e = linear.evaluate(channel(ANI_CHANNEL_CAMERA_ROTATION, keys), {t, t + h});
        REQUIRE(e.code == ANI_OK);
        CAPTURE(trial);
        CHECK(std::hypot(e.rate(0, 0), e.rate(0, 1), e.rate(0, 2)) == close(angle / dt, 1e-9));
        // World-frame angular velocity w: q(t + h) q(t)* = (cos(|w|h/2), sin(|w|h/2) w/|w|),
        // whose vector part is w h / 2 to first order.
        const interp::Quat step =
            interp::multiply(value_quat(e, 1), interp::conjugate(value_quat(e, 0)));
        const double sign = step.w < 0 ? -1.0 : 1.0;
        CHECK(sign * step.x * 2 / h == close(e.rate(0, 0), 1e-6));
        CHECK(sign * step.y * 2 / h == close(e.rate(0, 1), 1e-6));
        CHECK(sign * step.z * 2 / h == close(e.rate(0, 2), 1e-6));
    }
}

TEST_CASE("camera slerp between nearly identical or identical quaternions stays finite") {
    Interpolator linear("interpolation.linear");
    const interp::Quat tilt = interp::normalized({1.0, 1e-15, -2e-15, 0.0});
    const std::vector<ani_key> near_keys = {key(0.0, {1, 0, 0, 0}), key(1.0, {tilt.w, tilt.x, tilt.y, tilt.z})};
    const std::vector<ani_key> same_keys = {key(0.0, about(30, 1, 0, 0)), key(1.0, about(30, 1, 0, 0))};
    for (const auto *keys : {&near_keys, &same_keys}) {
        const Evaluation e = linear.evaluate(channel(ANI_CHANNEL_CAMERA_ROTATION, *keys), {0.25, 0.5, 2.0});
        REQUIRE(e.code == ANI_OK);
        for (size_t i = 0; i < 3; ++i) {
            CHECK(orientation_distance(value_quat(e, i), {(*keys)[0].value[0], (*keys)[0].value[1],
                                                          (*keys)[0].value[2], (*keys)[0].value[3]}) ==
                  close(0.0));
            // At most the angle 2 * |(1e-15, -2e-15, 0)| per second.
            for (int c = 0; c < 3; ++c) CHECK(std::fabs(e.rate(i, c)) < 1e-14);
        }
    }
    // The small-angle limit in the class itself.
    const interp::Slerp s(quat({1, 0, 0, 0}), tilt);
    CHECK(s.rotation_vector().x == close(2e-15, 1e-20)); // the angle 2 asin(|v|) ~ 2 |v|
    CHECK(s.rotation_vector().y == close(-4e-15, 1e-20));
}
