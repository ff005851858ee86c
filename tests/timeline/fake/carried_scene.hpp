// The document the host's tests of carried segments bake with physics.test_carrier
// (carrier_backend.cpp): model 0, "platform", keyed from the origin at t = 0 to (4, 1, 0) turned
// 90 degrees about y at t = 2 s (linear keys: it moves at (2, 0.5, 0) m/s and turns at 45 deg/s);
// model 1, "box", which the backend says the platform carries at offset (1, 0.5, 0), turned 30
// degrees about x relative to it. By hand, at t:
//   the platform's turn Q = Ry(45 t degrees), its origin c = (2 t, 0.5 t, 0);
//   the box's origin c + Q (1, 0.5, 0), orientation Q Rx(30 degrees), velocity
//   (2, 0.5, 0) + (0, pi/4, 0) x Q (1, 0.5, 0), angular velocity (0, pi/4, 0).
#pragma once

#include "document/document.hpp"

#include <glm/gtc/quaternion.hpp>

#include <cmath>

namespace carried_test {

constexpr double kPi = 3.14159265358979323846;

inline animator::Document carried_document(int mode) {
    using namespace animator;
    Document doc;
    Model platform;
    platform.name = "platform";
    platform.mesh = "cube";
    doc.add_model(platform, ModelState{});
    Model box;
    box.name = "box";
    box.mesh = "cube";
    box.dynamics = true;
    ModelState start;
    start.center = glm::dvec3(1.0, 0.5, 0.0);
    doc.add_model(box, start);
    Keyframe k;
    k.time_ms = 2000;
    k.states.assign(doc.models().size(), std::nullopt);
    doc.insert_keyframe(k);
    ModelState end;
    end.center = glm::dvec3(4.0, 1.0, 0.0);
    end.angles = glm::dvec3(0.0, 90.0, 0.0);
    doc.set_state(2000, 0, end);
    Settings s = doc.settings();
    s.params["physics.test_carrier"]["mode"] = {static_cast<double>(mode), 0.0, 0.0, 0.0};
    doc.set_settings(s);
    return doc;
}

struct Expected {
    glm::dvec3 center, velocity, w;
    glm::dquat q;
};

inline Expected expected_box(double t) {
    const glm::dquat Q = glm::angleAxis(kPi / 4.0 * t, glm::dvec3(0, 1, 0));
    const glm::dvec3 arm = Q * glm::dvec3(1.0, 0.5, 0.0), w(0.0, kPi / 4.0, 0.0);
    Expected e;
    e.center = glm::dvec3(2.0 * t, 0.5 * t, 0.0) + arm;
    e.velocity = glm::dvec3(2.0, 0.5, 0.0) + glm::cross(w, arm);
    e.w = w;
    e.q = Q * glm::angleAxis(kPi / 6.0, glm::dvec3(1, 0, 0));
    return e;
}

} // namespace carried_test
