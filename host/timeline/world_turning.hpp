// Every model's WORLD orientation and angular velocity at a time (for `animator bake --trace`):
// from the backend's rotation segment when one turns the model then, else from the keys' Euler
// angles (X-Y-Z about the model's own axes, docs/ani-format.md) composed up the scene tree.
#pragma once

#include "timeline/timeline.hpp"

#include <glm/gtc/quaternion.hpp>

#include <vector>

namespace animator {

struct Turning {
    glm::dquat q{1.0, 0.0, 0.0, 0.0}; // unit, world orientation, w >= 0 (q and -q are one turn)
    glm::dvec3 w{0.0};                // angular velocity, radians per second, world axes
};

// `frame` is timeline.evaluate(t). A child's orientation is its parent's followed by its own
// keyed rotation (the parent's scale is left out: it does not turn the child), and its angular
// velocity its parent's plus its own turned into the world. A rotation segment is the world
// orientation itself (physics.h), whatever the model's parent.
std::vector<Turning> world_turnings(const Timeline &timeline, const Frame &frame, double t);

} // namespace animator
