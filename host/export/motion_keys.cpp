#include "export/motion_keys.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace animator::motion_keys {

namespace {

// The Hermite span from (a: va, da) to (b: vb, db) at s in [0, 1] of it.
glm::dvec3 hermite(const glm::dvec3 &va, const glm::dvec3 &da, const glm::dvec3 &vb,
                   const glm::dvec3 &db, double span, double s) {
    const double s2 = s * s, s3 = s2 * s;
    return (2.0 * s3 - 3.0 * s2 + 1.0) * va + (s3 - 2.0 * s2 + s) * span * da +
           (-2.0 * s3 + 3.0 * s2) * vb + (s3 - s2) * span * db;
}

// The derivatives at a and b of the cubic through the values at a, a + h/3, a + 2h/3 and b.
void cubic_ends(const std::function<glm::dvec3(double)> &f, double a, double b,
                const glm::dvec3 &ya, const glm::dvec3 &yb, glm::dvec3 &da, glm::dvec3 &db) {
    const double h = b - a;
    const glm::dvec3 y1 = f(a + h / 3.0), y2 = f(a + 2.0 * h / 3.0);
    const double step = h / 3.0;
    da = (-11.0 * ya + 18.0 * y1 - 9.0 * y2 + 2.0 * yb) / (6.0 * step);
    db = (-2.0 * ya + 9.0 * y1 - 18.0 * y2 + 11.0 * yb) / (6.0 * step);
}

void set_out(std::vector<VecKey> &keys, double t, const glm::dvec3 &value, const glm::dvec3 &rate) {
    if (keys.empty() || keys.back().t < t) {
        VecKey k;
        k.t = t;
        k.in = rate; // a first key: nothing arrives, so the curve is smooth through it
        k.value = value;
        keys.push_back(k);
    }
    keys.back().out = rate;
}

struct PieceSplitter {
    const Piece &piece;
    double tolerance, min_span;
    std::vector<VecKey> &keys;
    bool split = false;

    void span(double a, const glm::dvec3 &va, double b, const glm::dvec3 &vb, int depth) {
        glm::dvec3 da, db;
        if (piece.rate) {
            da = piece.rate(a);
            db = piece.rate(b);
        } else {
            cubic_ends(piece.value, a, b, va, vb, da, db);
        }
        const double h = b - a;
        double worst = 0.0;
        for (int k = 1; k < 8; ++k) {
            const double s = k / 8.0;
            worst = std::max(worst,
                             glm::length(hermite(va, da, vb, db, h, s) - piece.value(a + s * h)));
        }
        if (worst > tolerance && h > 2.0 * min_span && depth < 40) {
            split = true;
            const double m = a + 0.5 * h;
            const glm::dvec3 vm = piece.value(m);
            span(a, va, m, vm, depth + 1);
            span(m, vm, b, vb, depth + 1);
            return;
        }
        set_out(keys, a, va, da);
        VecKey k;
        k.t = b;
        k.in = db;
        k.value = vb;
        k.out = db;
        keys.push_back(k);
    }
};

glm::dquat nearest_sign(const glm::dquat &q, const glm::dquat &to) {
    return glm::dot(q, to) < 0.0 ? -q : q;
}

glm::dquat slerp(const glm::dquat &a, glm::dquat b, double s) {
    double c = glm::dot(a, b);
    if (c < 0.0) {
        b = -b;
        c = -c;
    }
    if (c > 1.0 - 1e-12) return glm::normalize(a * (1.0 - s) + b * s);
    const double angle = std::acos(std::min(1.0, c));
    const double sa = std::sin(angle);
    return glm::normalize(a * (std::sin((1.0 - s) * angle) / sa) + b * (std::sin(s * angle) / sa));
}

struct RotationSplitter {
    const std::function<glm::dquat(double)> &rotation;
    double tolerance, min_span;
    std::vector<QuatKey> &keys;
    bool split = false;

    void span(double a, const glm::dquat &qa, double b, glm::dquat qb, int depth) {
        qb = nearest_sign(qb, qa);
        const double h = b - a;
        bool fine = angle_between(qa, qb) <= kMaxKeyTurn;
        for (int k = 1; k < 8 && fine; ++k) {
            const double s = k / 8.0;
            fine = angle_between(slerp(qa, qb, s), rotation(a + s * h)) <= tolerance;
        }
        if (!fine && h > 2.0 * min_span && depth < 40) {
            split = true;
            const double m = a + 0.5 * h;
            const glm::dquat qm = nearest_sign(glm::normalize(rotation(m)), qa);
            span(a, qa, m, qm, depth + 1);
            span(m, qm, b, qb, depth + 1);
            return;
        }
        keys.push_back(
            QuatKey{b, nearest_sign(qb, keys.back().q)}); // nearest the key before it, as pushed
    }
};

} // namespace

void append_piece(std::vector<VecKey> &keys, double t0, double t1, const Piece &piece,
                  double tolerance, PieceStats *stats, double min_span) {
    const glm::dvec3 v0 = piece.value(t0);
    if (!(t1 > t0)) {
        if (keys.empty() || keys.back().t < t0) set_out(keys, t0, v0, glm::dvec3(0.0));
        return;
    }
    PieceSplitter splitter{piece, tolerance, min_span, keys};
    splitter.span(t0, v0, t1, piece.value(t1), 0);
    if (stats) ++(splitter.split ? stats->sampled : stats->exact);
}

bool is_linear(const std::vector<VecKey> &keys, double tolerance) {
    for (size_t k = 0; k + 1 < keys.size(); ++k) {
        const double dt = keys[k + 1].t - keys[k].t;
        const glm::dvec3 slope = (keys[k + 1].value - keys[k].value) / dt;
        // A Hermite span strays from its chord by at most (|out - slope| + |in - slope|) dt / 4.
        if ((glm::length(keys[k].out - slope) + glm::length(keys[k + 1].in - slope)) * dt / 4.0 >
            tolerance)
            return false;
    }
    return true;
}

glm::dvec3 hermite_at(const std::vector<VecKey> &keys, double t) {
    if (keys.empty()) return glm::dvec3(0.0);
    if (t <= keys.front().t) return keys.front().value;
    if (t >= keys.back().t) return keys.back().value;
    const auto it = std::upper_bound(keys.begin(), keys.end(), t,
                                     [](double x, const VecKey &k) { return x < k.t; });
    const VecKey &a = *(it - 1), &b = *it;
    const double h = b.t - a.t;
    return hermite(a.value, a.out, b.value, b.in, h, (t - a.t) / h);
}

void append_rotation(std::vector<QuatKey> &keys, double t0, double t1,
                     const std::function<glm::dquat(double)> &rotation, double tolerance,
                     PieceStats *stats, double min_span) {
    glm::dquat q0 = glm::normalize(rotation(t0));
    if (!keys.empty()) q0 = nearest_sign(q0, keys.back().q);
    if (keys.empty() || keys.back().t < t0) keys.push_back(QuatKey{t0, q0});
    if (!(t1 > t0)) return;
    RotationSplitter splitter{rotation, tolerance, min_span, keys};
    splitter.span(t0, keys.back().q, t1, glm::normalize(rotation(t1)), 0);
    if (stats) ++(splitter.split ? stats->sampled : stats->exact);
}

glm::dquat slerp_at(const std::vector<QuatKey> &keys, double t) {
    if (keys.empty()) return glm::dquat(1.0, 0.0, 0.0, 0.0);
    if (t <= keys.front().t) return keys.front().q;
    if (t >= keys.back().t) return keys.back().q;
    const auto it = std::upper_bound(keys.begin(), keys.end(), t,
                                     [](double x, const QuatKey &k) { return x < k.t; });
    const QuatKey &a = *(it - 1), &b = *it;
    return slerp(a.q, b.q, (t - a.t) / (b.t - a.t));
}

double angle_between(const glm::dquat &a, const glm::dquat &b) {
    const glm::dquat d = glm::conjugate(a) * b;
    return 2.0 * std::atan2(glm::length(glm::dvec3(d.x, d.y, d.z)), std::abs(d.w));
}

namespace {

template <typename Key, typename Merge>
std::size_t merge_times(std::vector<Key> &keys, double origin, std::vector<float> &times,
                        Merge merge) {
    std::vector<Key> kept;
    times.clear();
    std::size_t merged = 0;
    for (const Key &k : keys) {
        const float t = std::max(0.0f, static_cast<float>(k.t - origin));
        if (!times.empty() && t <= times.back()) {
            merge(kept.back(), k);
            ++merged;
            continue;
        }
        times.push_back(t);
        kept.push_back(k);
    }
    keys = std::move(kept);
    return merged;
}

} // namespace

std::size_t merge_float_times(std::vector<VecKey> &keys, double origin, std::vector<float> &times) {
    return merge_times(keys, origin, times,
                       [](VecKey &into, const VecKey &k) { into.out = k.out; });
}

std::size_t merge_float_times(std::vector<QuatKey> &keys, double origin,
                              std::vector<float> &times) {
    return merge_times(keys, origin, times, [](QuatKey &, const QuatKey &) {});
}

} // namespace animator::motion_keys
