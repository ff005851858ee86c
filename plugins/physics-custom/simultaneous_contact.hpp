// Several points touching at once along one normal (a cube landing flat on four corners, a box
// rocking onto its other edge), issue 18. The compression first: the impulses lambda_k >= 0 that
// stop every approaching point together, a small linear complementarity problem
//
//   u'_k = u_k + sum_l A_kl lambda_l >= 0,   lambda_k >= 0,   lambda_k u'_k = 0
//
// (u_k the normal relative velocity of the touching points, A_kl the normal velocity change at k
// per unit normal impulse at l: the Delassus matrix of the two bodies). Then restitution by
// Poisson's hypothesis at every point: e times each compression impulse again, (1 + e) lambda_k
// in all. The points that pushed leave at -e times their speed, as Newton's law says for one
// point; and the kinetic energy changes by -(1 - e^2)/2 lambda.A.lambda <= 0, so several points
// at once never create energy (Newton's law applied to all points together can: Stronge,
// "Impact Mechanics", 7.2), and keep it exactly for e = 1. A point that did not push may leave
// still approaching; the bake then meets it at once as a contact of its own.
//
// With one normal, A has rank 3 at most (a point's row depends on 1 and on its position across
// n), so a solution pushes at three points or fewer: the sets of one, two and three points are
// tried in turn and solved exactly (Cramer's rule), the first that satisfies every point wins.
// For a positive semi-definite A the velocities after are the same for all solutions (Cottle,
// Pang, Stone, "The Linear Complementarity Problem", 3.1), so the choice does not matter.
//
// Impulses along one normal at points x_k add up to one impulse of their sum at their centre of
// pressure P = sum lambda_k x_k / sum lambda_k (the torques add linearly in x). So the result is
// returned as P and the sum, for impulse.hpp's contact_impulse_of to apply, with friction:
// Coulomb's law then acts at the centre of pressure with the whole normal impulse. A cube
// landing flat without spin gets P under its centre of mass (two diagonal corners with equal
// impulses), so no spin.
#pragma once

#include "impulse.hpp"

#include <optional>
#include <vector>

namespace physics_custom {

struct SimultaneousImpulse {
    glm::dvec3 centre{0.0}; // the centre of pressure (world space)
    double normal = 0.0;    // the sum of the normal impulses (> 0), along n on a
};

// a and b as contact_impulse takes them (their `r` is not used), com_a and com_b their centres
// of mass, `points` where they touch (world space), n the unit normal from b towards a. None
// when no point approaches (nothing to do) or when no set of three points or fewer solves it
// (a degenerate Delassus matrix: the caller falls back to one point).
std::optional<SimultaneousImpulse>
simultaneous_impulse(const ImpulseBody &a, const glm::dvec3 &com_a, const ImpulseBody &b,
                     const glm::dvec3 &com_b, const std::vector<glm::dvec3> &points,
                     const glm::dvec3 &n, double e);

} // namespace physics_custom
