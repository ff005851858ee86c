// What a body reports, built step by step (docs/physics-bullet.md, "Output").
//
// Bullet integrates with semi-implicit Euler: v' = v + a h, x' = x + v' h. With no contact, the
// positions at the step times lie exactly on one parabola, x_n = x_s + (v_s + a h / 2) n h +
// a (n h)^2 / 2, so a track reports one segment per stretch between contacts: it starts a stretch
// at a step, extends it while the next step's position and velocity match the stretch's
// extrapolation (relative 1e-12), and starts a new one otherwise. A step that does not match (a
// contact) is reported as a one-step segment through the positions at its two ends. Segments are
// continuous by construction: each starts where the previous one ended.
//
// Supported: under gravity, a body that Bullet keeps on a support (resting, or sliding or rolling
// along it) hops by about |a| dt^2 at each step, since restitution turns every resting contact
// into a tiny bounce. After a contact that leaves it moving along gravity slower than 2 |a| dt,
// the track reports it on the line x + u t (u: its velocity across gravity then; a rest when
// u = 0) for as long as Bullet's positions stay within 2 |a| dt^2 of that line and its velocity
// within 2 |a| dt of u: one segment instead of one per step, off Bullet's positions by at most
// that band.
//
// The same track also reports closed-form stretches (a kinematic fall, a rest, keyed spans) so a
// body's segments come out in time order whatever moves it.
#pragma once

#include <animator/physics.h>
#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>

#include <cstdint>
#include <functional>

namespace physics_bullet {

using SegmentSink = std::function<void(const ani_motion_segment &)>;
using RotationSink = std::function<void(const ani_rotation_segment &)>;

// Relative tolerance for "the step lies on the stretch's parabola".
constexpr double kMatchTolerance = 1e-12;

class Track {
  public:
    struct State {
        glm::dvec3 x{0.0}, v{0.0};
    };

    Track(uint32_t model, SegmentSink emit) : model_(model), emit_(std::move(emit)) {}

    // A stretch driven by Bullet's steps of nominal length dt, from Bullet's state (x, v) at t,
    // under the constant acceleration a.
    void start_stepping(double t, const glm::dvec3 &x, const glm::dvec3 &v, const glm::dvec3 &a,
                        double dt);
    // Bullet's state after a step of length h ending at t (`whole`: a step of exactly dt, which
    // can extend the stretch). Returns the state Bullet goes on from: the stretch's extrapolation
    // when the step matches it (so rounding never accumulates), else Bullet's own state, which
    // starts a new stretch.
    State step(double t, double h, bool whole, const glm::dvec3 &x, const glm::dvec3 &v);
    // Whether the open stretch is Bullet-driven and can be extended by whole steps in closed form
    // (not while resting).
    bool stepping() const { return mode_ == Mode::kStepping; }
    // Extends a stepping stretch by n whole steps ending at t, in closed form (nothing can touch
    // the body meanwhile). Returns the state at t.
    State coast(double t, int64_t n);
    // Where the open stretch starts.
    double stretch_start() const { return ts_; }
    // Acceleration of the open stretch.
    const glm::dvec3 &acceleration() const { return a_; }

    // A closed-form stretch from t: center(t') = p + u (t' - t) + a (t' - t)^2 / 2; `motion` is
    // ANI_MOTION_FREE or ANI_MOTION_REST.
    void start_closed(double t, const glm::dvec3 &p, const glm::dvec3 &u, const glm::dvec3 &a,
                      int motion);
    // Where the open stretch puts the body at t (closed form, or on the stepping stretch's
    // parabola up to its last step).
    glm::dvec3 position(double t) const;
    glm::dvec3 velocity(double t) const;

    // Reports the open stretch up to t and leaves nothing open.
    void close(double t);
    // Reports a keyed span (the host evaluates the keys).
    void keyed(double t0, double t1);

    bool open() const { return mode_ != Mode::kNone; }

  private:
    enum class Mode { kNone, kStepping, kSupported, kClosed };
    State at_steps(int64_t n) const;
    void emit(int motion, double t0, double t1, const glm::dvec3 &p0, const glm::dvec3 &u,
              const glm::dvec3 &a);

    uint32_t model_;
    SegmentSink emit_;
    Mode mode_ = Mode::kNone;
    // Stepping: Bullet's state (xs, vs) at ts, nominal step dt, n whole steps merged, the last
    // ending at t_last. Closed: p(t) = xs + vs (t - ts) + a (t - ts)^2 / 2. Supported:
    // p(t) = xs + vs (t - ts) up to t_last.
    double ts_ = 0.0, t_last_ = 0.0, dt_ = 0.0;
    int64_t n_ = 0;
    glm::dvec3 xs_{0.0}, vs_{0.0}, a_{0.0};
    int motion_ = ANI_MOTION_FREE;
};

// The same for a body's orientation when Bullet turns it (rotate on contact): with no contact
// the angular velocity is constant (no gyroscopic term) and each step turns the body by w h.
class RotationTrack {
  public:
    struct State {
        glm::dquat q{1.0, 0.0, 0.0, 0.0};
        glm::dvec3 w{0.0};
    };

    // `reach`: the body's size, to turn the position band of a body on a support into an angle.
    RotationTrack(uint32_t model, RotationSink emit, double reach)
        : model_(model), emit_(std::move(emit)), reach_(reach) {}
    // The acceleration the body is under (its supported rest needs gravity).
    void set_gravity(double g) { g_ = g; }

    void start(double t, const glm::dquat &q, const glm::dvec3 &w, double dt);
    State step(double t, double h, bool whole, const glm::dquat &q, const glm::dvec3 &w);
    State coast(double t, int64_t n);
    void close(double t);
    bool open() const { return open_; }

  private:
    glm::dquat at(double tau) const;
    void emit(double t0, double t1, const glm::dquat &q0, const glm::dvec3 &w);

    uint32_t model_;
    RotationSink emit_;
    double reach_ = 1.0, g_ = 0.0;
    bool open_ = false;
    bool still_ = false; // rocking on a support: reported at rest
    double ts_ = 0.0, t_last_ = 0.0, dt_ = 0.0;
    int64_t n_ = 0;
    glm::dquat qs_{1.0, 0.0, 0.0, 0.0};
    glm::dvec3 ws_{0.0};
};

// The rotation that turns q0 into q1 as an angular velocity over h (world frame).
glm::dvec3 angular_velocity(const glm::dquat &q0, const glm::dquat &q1, double h);
// q turned by w for tau seconds (world frame).
glm::dquat turned(const glm::dquat &q, const glm::dvec3 &w, double tau);

} // namespace physics_bullet
