// The reference gas (gas_reference.hpp says what it is and which techniques it uses).
#include "gas_reference.hpp"

#include "calendar_queue.hpp" // physics.custom's, which its gas lane uses too

#include <algorithm>
#if defined(__x86_64__)
#include <immintrin.h>
#endif
#include <cmath>
#include <limits>

namespace animator::bench::reference {

namespace {

constexpr std::uint32_t kNone = 0xffffffffu;
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kPerBucket = 16.0; // events in a bucket of the queue, about

// What the event loop touches for every candidate: one cache line.
struct alignas(64) Sphere {
    double x[3]; // position at the local time t
    double v[3];
    double t;
    std::uint32_t count; // collisions so far: a pair event predicted at another count is stale
    std::uint32_t next;  // the next sphere in its cell, or kNone
};

// A sphere's next event: the earlier of its earliest pair collision and its next move (a cell
// crossing or a wall). The pair part outlives a cell crossing, after which it bounds the pairs
// already scanned from below.
struct Event {
    double pair_time = kInf;
    std::uint32_t partner = kNone, partner_count = 0;
    double move_time = kInf;
    int move = 0; // the axis; + 3 for a wall, where a crossing would leave the box
};

class Simulation {
  public:
    Simulation(const Gas &gas, std::vector<Collision> *log);
    // Runs the events up to time `until`.
    void run(double until);
    // Every sphere moved to time t.
    Gas state(double t) const;
    Result result;

  private:
    void advance(std::uint32_t i, double t);
    void collide(std::uint32_t i, std::uint32_t j);
    void scan(std::uint32_t i, std::int64_t cell, const std::int64_t *offsets, int count,
              std::uint32_t skip);
    void predict_pairs(std::uint32_t i, std::uint32_t skip); // the 27 cells around i
    void predict_move(std::uint32_t i);
    void schedule(std::uint32_t i); // its place in the queue by its event's time
    void cross(std::uint32_t i, int axis);

    std::vector<Collision> *log_;
    double r_, d2_;                  // radius, and (2r)^2
    std::array<double, 3> lo_, hi_;  // the walls
    double wall_lo_[3], wall_hi_[3]; // where the centres meet them: lo + r, hi - r
    ani::HugeVector<Sphere> s_;
    ani::HugeVector<Event> e_;
    ani::HugeVector<double> mass_;
    // The cell list: real cells 1 .. n_[a] per axis, a layer of empty cells around them.
    double cell_lo_[3], width_[3]; // where cell 1 starts (lo + r), cell widths
    int n_[3];
    std::int64_t stride_[3];
    ani::HugeVector<std::uint32_t> head_;
    ani::HugeVector<std::array<int, 3>> coord_; // each sphere's cell
    ani::HugeVector<std::uint32_t> prev_;       // the previous sphere in its cell, or kNone
    std::int64_t around_[27];               // the offsets of the 27 cells around a cell
    std::int64_t beyond_[6][9]; // after a crossing along axis a, way d: the 9 new, at 2a + d
    physics_custom::CalendarQueue queue_;
};

Simulation::Simulation(const Gas &gas, std::vector<Collision> *log)
    : log_(log), r_(gas.radius), d2_(4.0 * gas.radius * gas.radius), lo_(gas.lo), hi_(gas.hi) {
    const std::size_t n = gas.position.size();
    s_.resize(n);
    e_.resize(n);
    mass_.assign(gas.mass.begin(), gas.mass.end());
    coord_.resize(n);
    prev_.assign(n, kNone);
    // Cells at least 2r wide over the centres' range [lo + r, hi - r], and at most about 4 per
    // sphere (a sparse gas in a large box).
    double extent[3];
    for (int a = 0; a < 3; ++a) extent[a] = std::max(gas.hi[a] - gas.lo[a] - 2.0 * r_, 0.0);
    double w = 2.0 * r_ * (1.0 + 1e-9);
    const double most = 4.0 * static_cast<double>(std::max<std::size_t>(n, 8));
    const double volume = std::max(extent[0], w) * std::max(extent[1], w) * std::max(extent[2], w);
    if (w <= 0.0 || volume / (w * w * w) > most) w = std::cbrt(volume / most);
    std::int64_t cells = 1;
    for (int a = 0; a < 3; ++a) {
        n_[a] = w > 0.0 ? std::max(1, static_cast<int>(std::min(extent[a] / w, 1e6))) : 1;
        width_[a] = extent[a] / n_[a];
        wall_lo_[a] = cell_lo_[a] = gas.lo[a] + r_;
        wall_hi_[a] = gas.hi[a] - r_;
        stride_[a] = cells;
        cells *= n_[a] + 2;
    }
    head_.assign(static_cast<std::size_t>(cells), kNone);
    int q = 0;
    for (int z = -1; z <= 1; ++z)
        for (int y = -1; y <= 1; ++y)
            for (int x = -1; x <= 1; ++x)
                around_[q++] = x * stride_[0] + y * stride_[1] + z * stride_[2];
    for (int a = 0; a < 3; ++a)
        for (int d = 0; d < 2; ++d) {
            const std::int64_t s1 = stride_[(a + 1) % 3], s2 = stride_[(a + 2) % 3];
            q = 0;
            for (int d1 = -1; d1 <= 1; ++d1)
                for (int d2 = -1; d2 <= 1; ++d2)
                    beyond_[2 * a + d][q++] = (d ? 2 : -2) * stride_[a] + d1 * s1 + d2 * s2;
        }
    for (std::size_t i = 0; i < n; ++i) {
        Sphere &p = s_[i];
        std::int64_t cell = 0;
        for (int a = 0; a < 3; ++a) {
            p.x[a] = gas.position[i][a];
            p.v[a] = gas.velocity[i][a];
            const double f = width_[a] > 0.0 ? (p.x[a] - cell_lo_[a]) / width_[a] : 0.0;
            coord_[i][a] = std::clamp(static_cast<int>(std::floor(f)) + 1, 1, n_[a]);
            cell += coord_[i][a] * stride_[a];
        }
        p.t = 0.0;
        p.count = 0;
        p.next = head_[cell];
        if (p.next != kNone) prev_[p.next] = static_cast<std::uint32_t>(i);
        head_[cell] = static_cast<std::uint32_t>(i);
    }
    std::vector<double> times(n);
    for (std::uint32_t i = 0; i < n; ++i) {
        predict_pairs(i, kNone);
        predict_move(i);
        times[i] = std::min(e_[i].pair_time, e_[i].move_time);
    }
    queue_.init(times.data(), times.size(), 0.0, kPerBucket);
}

void Simulation::advance(std::uint32_t i, double t) {
    Sphere &p = s_[i];
    const double dt = t - p.t;
    for (int a = 0; a < 3; ++a) p.x[a] += p.v[a] * dt;
    p.t = t;
}

// The elastic response along the centre line: v_a' = v_a - 2 m_b / (m_a + m_b) (dv.n) n and
// v_b' = v_b + 2 m_a / (m_a + m_b) (dv.n) n, dv = v_a - v_b, n from a to b.
void Simulation::collide(std::uint32_t i, std::uint32_t j) {
    Sphere &a = s_[i], &b = s_[j];
    double dp[3], u = 0.0, dp2 = 0.0;
    for (int q = 0; q < 3; ++q) {
        dp[q] = b.x[q] - a.x[q];
        u += (a.v[q] - b.v[q]) * dp[q];
        dp2 += dp[q] * dp[q];
    }
    u /= dp2;
    const double ma = mass_[i], mb = mass_[j], fa = 2.0 * mb / (ma + mb) * u,
                 fb = 2.0 * ma / (ma + mb) * u;
    for (int q = 0; q < 3; ++q) {
        a.v[q] -= fa * dp[q];
        b.v[q] += fb * dp[q];
    }
    ++a.count;
    ++b.count;
}

// The earliest collision of i (moved to now) with the spheres of the cells at `offsets` from its
// cell `cell`, if earlier than the pair part of i's event: the stable root
// t = c / (-b + sqrt(b^2 - dv^2 c)), b = dp.dv < 0 (approaching: touching and separating pairs
// never meet), c = dp^2 - (2r)^2.
void Simulation::scan(std::uint32_t i, std::int64_t cell, const std::int64_t *offsets, int count,
                      std::uint32_t skip) {
    const Sphere &a = s_[i];
    const double x = a.x[0], y = a.x[1], z = a.x[2], vx = a.v[0], vy = a.v[1], vz = a.v[2];
    const double now = a.t;
    Event &e = e_[i];
    double horizon = e.pair_time - now;
    std::uint32_t partner = kNone, partner_count = 0;
    std::uint64_t tests = 0;
    // The cells' first spheres, listed without a branch (whether a cell is empty is a coin toss
    // at a gas's density) and not prefetched: the walk below loads them overlapped anyway, and
    // the two together made a 10,000-ball bake a sixth faster (docs/performance.md, the gas).
    std::uint32_t first[27];
    int m = 0;
    for (int q = 0; q < count; ++q) {
        const std::uint32_t k = head_[cell + offsets[q]];
        first[m] = k;
        m += k != kNone;
    }
    for (int q = 0; q < m; ++q)
        for (std::uint32_t k = first[q]; k != kNone; k = s_[k].next) {
            const Sphere &o = s_[k];
            if (k == i || k == skip) continue;
            ++tests;
            const double dt = now - o.t;
            const double dvx = o.v[0] - vx, dvy = o.v[1] - vy, dvz = o.v[2] - vz;
            const double dx = o.x[0] + o.v[0] * dt - x, dy = o.x[1] + o.v[1] * dt - y,
                         dz = o.x[2] + o.v[2] * dt - z;
            // Without branches (they would be mispredicted): every candidate's root is computed.
            const double b = dx * dvx + dy * dvy + dz * dvz;
            const double c = dx * dx + dy * dy + dz * dz - d2_;
            const double disc = b * b - (dvx * dvx + dvy * dvy + dvz * dvz) * c;
            const double root = std::sqrt(std::max(disc, 0.0));
            const double t = c > 0.0 ? c / (root - b) : 0.0; // overlapping by rounding: now
            const bool earlier = (b < 0.0) & (disc >= 0.0) & (t < horizon);
            horizon = earlier ? t : horizon;
            partner = earlier ? k : partner;
            partner_count = earlier ? o.count : partner_count;
        }
    result.predictions += tests;
    if (partner != kNone) {
        e.pair_time = now + horizon;
        e.partner = partner;
        e.partner_count = partner_count;
    }
}

void Simulation::predict_pairs(std::uint32_t i, std::uint32_t skip) {
    Event &e = e_[i];
    e.pair_time = kInf;
    e.partner = kNone;
    const std::array<int, 3> &c = coord_[i];
    scan(i, c[0] * stride_[0] + c[1] * stride_[1] + c[2] * stride_[2], around_, 27, skip);
}

// The first face of its cell the centre of i (moved to now) reaches, or the wall, if its cell
// is the last one that way.
void Simulation::predict_move(std::uint32_t i) {
    const Sphere &p = s_[i];
    Event &e = e_[i];
#if defined(__x86_64__)
    // Without branches, with SSE2's selects, as physics.custom's lane does (face_ahead in
    // gas_lane.cpp): which way a sphere moves along each axis, and which face it reaches first,
    // are coin tosses. The same numbers as the branches below.
    const __m128d zero = _mm_setzero_pd(), never = _mm_set_sd(kInf);
    const auto pick = [](__m128d mask, __m128d yes, __m128d no) {
        return _mm_or_pd(_mm_and_pd(mask, yes), _mm_andnot_pd(mask, no));
    };
    __m128d best = never;
    int move = 0;
    for (int a = 0; a < 3; ++a) {
        const double v = p.v[a];
        const int c = coord_[i][a], up = v > 0.0;
        const int wall = up ? c == n_[a] : c == 1; // (integers: a select, not a branch)
        const __m128d va = _mm_set_sd(v), is_up = _mm_cmpgt_sd(va, zero);
        const __m128d wall_plane = pick(is_up, _mm_set_sd(wall_hi_[a]), _mm_set_sd(wall_lo_[a]));
        const __m128d cell_plane = _mm_add_sd(
            _mm_set_sd(cell_lo_[a]),
            _mm_mul_sd(_mm_set_sd(static_cast<double>(c - 1 + up)), _mm_set_sd(width_[a])));
        const __m128d plane = pick(_mm_castsi128_pd(_mm_set1_epi64x(-static_cast<long long>(wall))),
                                   wall_plane, cell_plane);
        const __m128d q = _mm_div_sd(_mm_sub_sd(plane, _mm_set_sd(p.x[a])), va);
        const __m128d t =
            pick(_mm_cmpeq_sd(va, zero), never, pick(_mm_cmplt_sd(q, zero), zero, q)); // max(q, 0)
        const int first = -_mm_comilt_sd(t, best); // (all ones, or none)
        best = _mm_min_sd(t, best);
        move = ((wall ? a + 3 : a) & first) | (move & ~first);
    }
    if (_mm_comilt_sd(best, never)) e.move = move;
    e.move_time = p.t + _mm_cvtsd_f64(best);
#else
    double best = kInf;
    for (int a = 0; a < 3; ++a) {
        const double v = p.v[a];
        if (v == 0.0) continue;
        const int c = coord_[i][a];
        const bool wall = v > 0.0 ? c == n_[a] : c == 1;
        const double plane = wall ? (v > 0.0 ? wall_hi_[a] : wall_lo_[a])
                                  : cell_lo_[a] + (v > 0.0 ? c : c - 1) * width_[a];
        const double t = std::max((plane - p.x[a]) / v, 0.0);
        if (t < best) {
            best = t;
            e.move = wall ? a + 3 : a;
        }
    }
    e.move_time = p.t + best;
#endif
}

void Simulation::schedule(std::uint32_t i) {
    queue_.update(i, std::min(e_[i].pair_time, e_[i].move_time));
}

// i (moved to now) leaves its cell along `axis`: it moves to the next cell's list, and only the 9
// cells beyond that one are new to it (the pair part found before bounds the others).
void Simulation::cross(std::uint32_t i, int axis) {
    std::array<int, 3> &c = coord_[i];
    const std::int64_t old = c[0] * stride_[0] + c[1] * stride_[1] + c[2] * stride_[2];
    const int dir = s_[i].v[axis] > 0.0 ? 1 : -1;
    const std::int64_t cell = old + dir * stride_[axis];
    c[axis] += dir;
    Sphere &p = s_[i];
    if (prev_[i] != kNone)
        s_[prev_[i]].next = p.next;
    else
        head_[old] = p.next;
    if (p.next != kNone) prev_[p.next] = prev_[i];
    p.next = head_[cell];
    if (p.next != kNone) prev_[p.next] = i;
    prev_[i] = kNone;
    head_[cell] = i;
    scan(i, old, beyond_[2 * axis + (dir > 0)], 9, kNone);
}

void Simulation::run(double until) {
    Result &out = result;
    while (true) {
        const double t = queue_.top_time();
        if (t > until || t == kInf) break;
        const std::uint32_t i = queue_.top();
        Event &e = e_[i];
        advance(i, t);
        if (e.pair_time <= e.move_time) {
            const std::uint32_t j = e.partner;
            if (s_[j].count != e.partner_count) { // j changed course since: predict i anew
                ++out.stale_events;
                predict_pairs(i, kNone);
            } else {
                advance(j, t);
                collide(i, j);
                ++out.pair_collisions;
                if (log_) log_->push_back({t, std::min(i, j), std::max(i, j)});
                predict_pairs(i, j);
                predict_move(i);
                predict_pairs(j, i);
                predict_move(j);
                schedule(j);
            }
        } else if (e.move >= 3) { // a wall: reflect
            const int a = e.move - 3;
            s_[i].v[a] = -s_[i].v[a];
            ++s_[i].count;
            ++out.wall_collisions;
            if (log_) log_->push_back({t, i, kWall + static_cast<std::uint32_t>(a)});
            predict_pairs(i, kNone);
            predict_move(i);
        } else {
            ++out.cell_crossings;
            cross(i, e.move);
            predict_move(i);
        }
        schedule(i);
    }
}

Gas Simulation::state(double t) const {
    Gas g;
    g.radius = r_;
    g.lo = lo_;
    g.hi = hi_;
    g.mass.assign(mass_.begin(), mass_.end());
    g.position.resize(s_.size());
    g.velocity.resize(s_.size());
    for (std::size_t i = 0; i < s_.size(); ++i) {
        const Sphere &p = s_[i];
        for (int a = 0; a < 3; ++a) {
            g.position[i][a] = p.x[a] + p.v[a] * (t - p.t);
            g.velocity[i][a] = p.v[a];
        }
    }
    return g;
}

} // namespace

Result run(const Gas &gas, double T, std::vector<Collision> *log) {
    Simulation sim(gas, log);
    sim.run(T);
    sim.result.time = T;
    sim.result.final_state = sim.state(T);
    return std::move(sim.result);
}

} // namespace animator::bench::reference
