// Whether a body standing on some points is balanced there (issue 19, tipping): its centre of
// mass lies over the convex hull of the points that touch, seen along gravity. A cube on a face
// is; a cube on an edge is only when its centre is straight above that edge; one on a corner,
// only straight above it. A body that is not tips over about the hull's edge nearest below it.
#pragma once

#include <glm/vec3.hpp>

#include <vector>

namespace physics_custom {

// Whether the line through `centre` along `down` (need not be unit, nonzero) meets the convex
// hull of `feet` (world space; any number, in any order, coplanar or not), within `slack` (m)
// measured across `down`. No feet: false.
bool over_feet(const glm::dvec3 &centre, const std::vector<glm::dvec3> &feet,
               const glm::dvec3 &down, double slack);

} // namespace physics_custom
