// The time of impact of a body that turns: a mesh whose points move as x(t) = c(t) + R(t) p,
// c(t) = c0 + v t + a t^2 / 2 a parabola and R(t) a turn at constant angular velocity w
// (q(t) = exp(w t / 2) q0, a spherical top such as a cube). Polynomials no longer describe the
// gap, so the first contact is found by conservative advancement (Mirtich, "Impulse-based
// dynamic simulation of rigid body systems", thesis 1996, ch. 3; Zhang, Redon, Lee, Kim, "C2A",
// SIGGRAPH 2007): from a moment when the gap is g and it cannot close by more than D(dt) within
// dt, no contact happens before the dt that solves D(dt) = g; time advances by that much and the
// gap is measured again. The times returned are lower bounds of the true time: never past it.
// Against a plane, a vertex set's first root is then refined to rounding (turning_plane_root).
#pragma once

#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

namespace physics_custom {

// A mesh in model space about its centre of mass: vertices, triangles (3 indices each, any
// winding) and edges (each once; edges_of in mesh_distance.hpp; used to name the features that
// touch). A static world-space triangle soup (a floor, a room) is a TurningMesh whose vertices
// are in world space, with a default TurningPath (still).
struct TurningMesh {
    const glm::dvec3 *vertices = nullptr;
    std::size_t vertex_count = 0;
    const uint32_t *triangles = nullptr;
    std::size_t triangle_count = 0;
    const std::array<uint32_t, 2> *edges = nullptr;
    std::size_t edge_count = 0;
};

// The path of a mesh's centre of mass and its turn, t in seconds on the bake's clock:
// c(t) = c0 + v t + a t^2 / 2 and q(t) = exp(w t / 2) q0 (w in rad/s, world axes).
struct TurningPath {
    glm::dvec3 c0{0.0}, v{0.0}, a{0.0};
    glm::dquat q0{1.0, 0.0, 0.0, 0.0};
    glm::dvec3 w{0.0};

    // A turn whose angular velocity changes (a top that is not spherical, a spin-up): when
    // `turn` is set, the orientation is turn(t) and the angular velocity turn_rate(t) (q0 and w
    // are not used), and the steps rely only on the bounds |w(t)| <= w_bound and
    // |w'(t)| <= w_rate_bound, which the caller guarantees over the window.
    std::function<glm::dquat(double)> turn;
    std::function<glm::dvec3(double)> turn_rate;
    double w_bound = 0.0, w_rate_bound = 0.0;

    glm::dvec3 center(double t) const { return c0 + v * t + a * (0.5 * t * t); }
    glm::dvec3 velocity(double t) const { return v + a * t; }
    glm::dquat orientation(double t) const;
    glm::dvec3 angular_velocity(double t) const { return turn ? turn_rate(t) : w; }
    // Bounds over the window, seen along a unit direction n: of |n . (w x r)| / |r| (= |n x w|
    // at constant w), and of |n . (w' x r + w x (w x r))| / |r| (= |n x w| |w|).
    double turn_across(const glm::dvec3 &n) const;
    double turn_curving(const glm::dvec3 &n) const;
    glm::dvec3 place(const glm::dvec3 &p, double t) const; // c(t) + R(t) p
};

// A static plane n . x = d (n need not be unit), the side n points to is outside.
struct StaticPlane {
    glm::dvec3 n{0.0, 1.0, 0.0};
    double d = 0.0;
};

struct TurningContactSettings {
    // Advancement stops when the safe step falls below this: the time returned is a lower
    // bound of the true one, and with the second-order bound (whose step tends to the true
    // remaining time near a contact that closes at a nonzero speed) short of it by about this
    // much at most; the tests measure it at rounding.
    double time_tolerance = 1e-13;
    int max_steps = 10000;
    // turning_mesh_contact measures again, at each step, only the pairs of triangles whose last
    // bound has run out; with this set, every pair at every step (the plain advancement, kept
    // to compare the work against).
    bool measure_every_pair = false;
};

struct TurningContact {
    enum Kind {
        kNone,       // no contact within [t0, t1]
        kVertexFace, // a vertex of one on a face of the other (or on the plane)
        kEdgeEdge,   // two edges cross
        kUndecided,  // max_steps reached before the gap closed (for turning_mesh_contact,
                     // max_steps times its pairs of triangles measured): t is a lower bound still
        kInvalid     // an input is not finite (the window, a path, a vertex, the plane): the
                     // caller refuses it, naming the model
    } kind = kNone;
    double t = 0.0;
    glm::dvec3 point{0.0};          // where they touch (the middle of the nearest points)
    glm::dvec3 normal{0.0};         // unit, from the second body (or the plane) towards the first
    std::vector<glm::dvec3> points; // every vertex-face pair within `contact_slack` of touching
    double gap = 0.0;               // the gap left at t (>= 0)
    int steps = 0;                  // advancement steps taken
    std::size_t pair_tests = 0;     // pairs of triangles measured: the work done
    bool found() const { return kind == kVertexFace || kind == kEdgeEdge; }
};

// The earliest t in [t0, t1] at which the turning mesh touches the static plane. The mesh must
// be on the plane's outside at t0. `contact_slack` (m) gathers the vertices that touch together
// (a face landing flat) into `points`.
TurningContact turning_plane_contact(const TurningMesh &mesh, const TurningPath &path,
                                     const StaticPlane &plane, double t0, double t1,
                                     const TurningContactSettings &settings = {},
                                     double contact_slack = 1e-9);

// The earliest t in [t0, t1] at which the surfaces of mesh a (moving on path_a) and mesh b (on
// path_b; a default TurningPath, still, for a world-space triangle soup) touch. They must be
// apart at t0. Each may be convex or not: the bounds are taken on every pair of triangles (each
// convex), so they hold for any shape. The normal points from b towards a. Every pair is
// measured at t0; after that, a pair is measured again only when the safe step it gave has run
// out (each pair's bound holds from when it was taken), so a pair far apart is not measured at
// every step of one that closes (the steps are more, the work less: `pair_tests`). No broad
// phase: meant for the few small turning models of a scene.
TurningContact turning_mesh_contact(const TurningMesh &a, const TurningPath &path_a,
                                    const TurningMesh &b, const TurningPath &path_b, double t0,
                                    double t1, const TurningContactSettings &settings = {},
                                    double contact_slack = 1e-9);

// Of the face normals of a and b at t, the one along which the two are furthest apart, from b
// towards a (the separating axis of two convex meshes): where faces touch faces (a box standing
// on a box, their sides flush too), the touching features alone leave the normal undecided, and
// this is the face they stand on. `fallback` when no face normal has them apart within `slack`
// (edge on edge).
glm::dvec3 separating_face_normal(const TurningMesh &a, const TurningPath &path_a,
                                  const TurningMesh &b, const TurningPath &path_b, double t,
                                  double slack, const glm::dvec3 &fallback);

// Whether every number of the path is finite.
bool turning_path_is_finite(const TurningPath &path);

// The first root of h(t) = min over the mesh's vertices of n . x_i(t) - d in [t_lo, t1], where
// t_lo is a lower bound such as turning_plane_contact's time: bracketed from t_lo, then
// safeguarded Newton / bisection on the vertex that goes lowest, to rounding (the bracket is
// below 1e-13 s, or no representable time lies between its ends). Returns t1 + 1 if the mesh
// does not reach the plane by t1, NaN if an input is not finite; `vertex` receives the index of the
// vertex that touches.
double turning_plane_root(const TurningMesh &mesh, const TurningPath &path,
                          const StaticPlane &plane, double t_lo, double t1,
                          std::size_t *vertex = nullptr);

} // namespace physics_custom
