#include "track.hpp"

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>

namespace physics_bullet {

namespace {

ani_vec3 ani(const glm::dvec3 &v) {
    return {v.x, v.y, v.z};
}

bool near(const glm::dvec3 &x, const glm::dvec3 &y, double scale) {
    return glm::length(x - y) <= kMatchTolerance * scale;
}

} // namespace

void Track::start_stepping(double t, const glm::dvec3 &x, const glm::dvec3 &v, const glm::dvec3 &a,
                           double dt) {
    mode_ = Mode::kStepping;
    ts_ = t_last_ = t;
    xs_ = x;
    vs_ = v;
    a_ = a;
    dt_ = dt;
    n_ = 0;
}

Track::State Track::at_steps(int64_t n) const {
    const double tau = static_cast<double>(n) * dt_;
    return {xs_ + (vs_ + 0.5 * dt_ * a_) * tau + 0.5 * tau * tau * a_, vs_ + tau * a_};
}

Track::State Track::step(double t, double h, bool whole, const glm::dvec3 &x, const glm::dvec3 &v) {
    const double g = glm::length(a_);
    const double band = 2.0 * g * dt_ * dt_, slow = 2.0 * g * dt_;
    if (mode_ == Mode::kSupported) {
        const glm::dvec3 p = xs_ + vs_ * (t - ts_);
        if (glm::length(x - p) <= band && glm::length(v - vs_) <= slow) {
            t_last_ = t;
            return {x, v};
        }
        const glm::dvec3 end = xs_ + vs_ * (t_last_ - ts_);
        emit(ANI_MOTION_FREE, ts_, t_last_, xs_, vs_, glm::dvec3(0.0));
        const double span = t - t_last_;
        if (span > 0.0)
            emit(ANI_MOTION_FREE, t_last_, t, end, (x - end) / span - 0.5 * span * a_, a_);
        const glm::dvec3 a = a_;
        const double dt = dt_;
        start_stepping(t, x, v, a, dt);
        return {x, v};
    }
    if (mode_ != Mode::kStepping) {
        start_stepping(t, x, v, a_, h);
        return {x, v};
    }
    if (whole) {
        const State p = at_steps(n_ + 1);
        const double tau = static_cast<double>(n_ + 1) * dt_;
        const double x_scale = glm::length(xs_) + glm::length(vs_ + 0.5 * dt_ * a_) * tau +
                               0.5 * glm::length(a_) * tau * tau;
        const double v_scale = glm::length(vs_) + glm::length(a_) * tau;
        if (near(x, p.x, x_scale) && near(v, p.v, v_scale)) {
            ++n_;
            t_last_ = t;
            return p;
        }
    }
    // A contact (or a step of another length): report the stretch so far, then this step as a
    // segment through its two ends, and start again from Bullet's state.
    const State end = at_steps(n_);
    if (n_ > 0) emit(ANI_MOTION_FREE, ts_, t_last_, xs_, vs_ + 0.5 * dt_ * a_, a_);
    const double span = t - t_last_;
    if (span > 0.0) {
        // Through end.x at t_last and x at t, with the stretch's acceleration.
        const glm::dvec3 u = (x - end.x) / span - 0.5 * span * a_;
        emit(ANI_MOTION_FREE, t_last_, t, end.x, u, a_);
    }
    const glm::dvec3 a = a_;
    const double dt = dt_;
    start_stepping(t, x, v, a, dt);
    if (g > 0.0) {
        const glm::dvec3 down = a / g;
        if (std::abs(glm::dot(v, down)) <= slow) { // held by a support
            mode_ = Mode::kSupported;
            vs_ = v - glm::dot(v, down) * down;
        }
    }
    return {x, v};
}

Track::State Track::coast(double t, int64_t n) {
    n_ += n;
    t_last_ = t;
    return at_steps(n_);
}

void Track::start_closed(double t, const glm::dvec3 &p, const glm::dvec3 &u, const glm::dvec3 &a,
                         int motion) {
    mode_ = Mode::kClosed;
    ts_ = t_last_ = t;
    xs_ = p;
    vs_ = u;
    a_ = a;
    n_ = 0;
    motion_ = motion;
}

glm::dvec3 Track::position(double t) const {
    if (mode_ == Mode::kSupported) return xs_ + vs_ * (t - ts_);
    if (mode_ == Mode::kStepping) {
        if (n_ == 0) return xs_;
        const double tau = t - ts_;
        return xs_ + (vs_ + 0.5 * dt_ * a_) * tau + 0.5 * tau * tau * a_;
    }
    const double tau = t - ts_;
    return xs_ + vs_ * tau + 0.5 * tau * tau * a_;
}

glm::dvec3 Track::velocity(double t) const {
    if (mode_ == Mode::kSupported) return vs_;
    const double tau = t - ts_;
    if (mode_ == Mode::kStepping) return vs_ + 0.5 * dt_ * a_ + tau * a_;
    return vs_ + tau * a_;
}

void Track::close(double t) {
    if (mode_ == Mode::kStepping) {
        if (n_ > 0) emit(ANI_MOTION_FREE, ts_, t_last_, xs_, vs_ + 0.5 * dt_ * a_, a_);
        if (t > t_last_) { // nothing was stepped since (a bake that ends mid-step): the parabola
            const State end = at_steps(n_);
            emit(ANI_MOTION_FREE, t_last_, t, end.x, end.v + 0.5 * dt_ * a_, a_);
        }
    } else if (mode_ == Mode::kSupported && t > ts_) {
        emit(ANI_MOTION_FREE, ts_, t, xs_, vs_, glm::dvec3(0.0));
    } else if (mode_ == Mode::kClosed && t > ts_) {
        emit(motion_, ts_, t, xs_, vs_, a_);
    }
    mode_ = Mode::kNone;
}

void Track::keyed(double t0, double t1) {
    if (!(t1 > t0)) return;
    ani_motion_segment s{};
    s.model = model_;
    s.motion = ANI_MOTION_KEYED;
    s.t0 = t0;
    s.t1 = t1;
    emit_(s);
}

void Track::emit(int motion, double t0, double t1, const glm::dvec3 &p0, const glm::dvec3 &u,
                 const glm::dvec3 &a) {
    if (!(t1 > t0)) return;
    ani_motion_segment s{};
    s.model = model_;
    const bool still = u == glm::dvec3(0.0) && a == glm::dvec3(0.0);
    s.motion = still ? ANI_MOTION_REST : motion;
    s.t0 = t0;
    s.t1 = t1;
    s.p0 = ani(p0);
    s.v0 = ani(u);
    s.a = ani(a);
    emit_(s);
}

// ---- rotation ------------------------------------------------------------------------------

glm::dquat turned(const glm::dquat &q, const glm::dvec3 &w, double tau) {
    const double speed = glm::length(w);
    if (!(speed > 0.0)) return q;
    return glm::normalize(glm::angleAxis(speed * tau, w / speed) * q);
}

glm::dvec3 angular_velocity(const glm::dquat &q0, const glm::dquat &q1, double h) {
    glm::dquat d = q1 * glm::conjugate(q0);
    if (d.w < 0.0) d = -d; // the short way
    const glm::dvec3 axis(d.x, d.y, d.z);
    const double s = glm::length(axis);
    if (!(s > 0.0) || !(h > 0.0)) return glm::dvec3(0.0);
    const double angle = 2.0 * std::atan2(s, d.w);
    return axis / s * (angle / h);
}

void RotationTrack::start(double t, const glm::dquat &q, const glm::dvec3 &w, double dt) {
    open_ = true;
    still_ = false;
    ts_ = t_last_ = t;
    qs_ = q;
    ws_ = w;
    dt_ = dt;
    n_ = 0;
}

glm::dquat RotationTrack::at(double tau) const {
    return still_ ? qs_ : turned(qs_, ws_, tau);
}

RotationTrack::State RotationTrack::step(double t, double h, bool whole, const glm::dquat &q,
                                         const glm::dvec3 &w) {
    if (!open_) {
        start(t, q, w, h);
        return {q, w};
    }
    // On a support a body rocks by about the position band over its size.
    const double angle_band = 2.0 * g_ * dt_ * dt_ / reach_, slow = 2.0 * g_ * dt_ / reach_;
    auto distance = [](const glm::dquat &x, const glm::dquat &y) {
        return std::min(glm::length(glm::dvec4(x.x - y.x, x.y - y.y, x.z - y.z, x.w - y.w)),
                        glm::length(glm::dvec4(x.x + y.x, x.y + y.y, x.z + y.z, x.w + y.w)));
    };
    if (still_) {
        if (2.0 * distance(q, qs_) <= angle_band && glm::length(w) <= slow) {
            t_last_ = t;
            return {q, w};
        }
        emit(ts_, t_last_, qs_, glm::dvec3(0.0));
        if (t > t_last_) emit(t_last_, t, qs_, angular_velocity(qs_, q, t - t_last_));
        const double dt = dt_;
        start(t, q, w, dt);
        return {q, w};
    }
    if (whole) {
        const glm::dquat p = at(static_cast<double>(n_ + 1) * dt_);
        // Orientations are unit quaternions: an absolute tolerance, a little looser than for
        // positions because each step renormalizes.
        if (distance(q, p) <= 1e-10 &&
            glm::length(w - ws_) <= kMatchTolerance * (glm::length(ws_) + 1e-300)) {
            ++n_;
            t_last_ = t;
            return {p, ws_};
        }
    }
    const glm::dquat end = at(static_cast<double>(n_) * dt_);
    if (n_ > 0) emit(ts_, t_last_, qs_, ws_);
    if (t > t_last_) emit(t_last_, t, end, angular_velocity(end, q, t - t_last_));
    const double dt = dt_;
    start(t, q, w, dt);
    if (g_ > 0.0 && glm::length(w) <= slow) still_ = true;
    return {q, w};
}

RotationTrack::State RotationTrack::coast(double t, int64_t n) {
    n_ += n;
    t_last_ = t;
    return {at(static_cast<double>(n_) * dt_), ws_};
}

void RotationTrack::close(double t) {
    if (!open_) return;
    if (still_) {
        emit(ts_, t, qs_, glm::dvec3(0.0));
        open_ = false;
        return;
    }
    if (n_ > 0) emit(ts_, t_last_, qs_, ws_);
    if (t > t_last_) emit(t_last_, t, at(static_cast<double>(n_) * dt_), ws_);
    open_ = false;
}

void RotationTrack::emit(double t0, double t1, const glm::dquat &q0, const glm::dvec3 &w) {
    if (!(t1 > t0) || !emit_) return;
    ani_rotation_segment s{};
    s.model = model_;
    s.t0 = t0;
    s.t1 = t1;
    s.q0 = ani_quat{q0.w, q0.x, q0.y, q0.z};
    s.w = ani(w);
    emit_(s);
}

} // namespace physics_bullet
