// The gas lane (gas_lane.hpp says what it takes and how it is fast). Every time and response is
// the general engine's function: sphere_sphere's stable root, first_exit's cell crossings,
// sphere_triangle, elastic_exchange and reflect, on the paths moved to the event's time as the
// general engine moves them.
#include "gas_lane.hpp"

#include "grid.hpp"
#include "response.hpp"

#include <animator/plugin_cpp.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#if defined(__x86_64__)
#include <immintrin.h>
#endif
#include <cmath>
#include <optional>
#include <string>

namespace physics_custom {

namespace {
glm::dvec3 vec(const double *x) {
    return {x[0], x[1], x[2]};
}
void put(double *x, const glm::dvec3 &v) {
    x[0] = v.x;
    x[1] = v.y;
    x[2] = v.z;
}
ani_vec3 ani(const glm::dvec3 &v) {
    return {v.x, v.y, v.z};
}

// The face of its cell (`cell`, in a grid of cells of `side` from `origin`) that a path from c
// at velocity v (no acceleration) reaches first (the general grid's first_exit, written out for
// such a path): per axis, the face it moves towards, at (face - c) / v, or at once (t = 0) when
// it is on that face or beyond it by rounding; none along an axis it does not move along (t
// infinite if along none); ties go to the lower axis.
struct FaceAhead {
    double t;
    int axis, direction;
};
constexpr double kNever = std::numeric_limits<double>::infinity();
#if defined(__x86_64__)
// With SSE2's selects (every x86-64 has them), without branches: which way a sphere moves along
// each axis, and which face it reaches first, are coin tosses, and the branches on them were
// mispredicted (the 10,000-ball bench's lane 6% faster). The same numbers as the branches below.
inline FaceAhead face_ahead(const glm::dvec3 &c, const glm::dvec3 &v,
                            const std::array<int32_t, 3> &cell, const glm::dvec3 &origin,
                            double side) {
    const __m128d zero = _mm_setzero_pd(), one = _mm_set_sd(1.0), never = _mm_set_sd(kNever);
    const auto pick = [](__m128d mask, __m128d yes, __m128d no) {
        return _mm_or_pd(_mm_and_pd(mask, yes), _mm_andnot_pd(mask, no));
    };
    __m128d soonest = never;
    int axis = 0, direction = 0;
    for (int a = 0; a < 3; ++a) {
        const __m128d va = _mm_set_sd(v[a]), ca = _mm_set_sd(c[a]);
        const __m128d up = _mm_cmpgt_sd(va, zero);
        const __m128d face = _mm_add_sd(
            _mm_set_sd(origin[a]),
            _mm_mul_sd(_mm_add_sd(_mm_set_sd(static_cast<double>(cell[a])), _mm_and_pd(up, one)),
                       _mm_set_sd(side)));
        const __m128d beyond = pick(up, _mm_cmpge_sd(ca, face), _mm_cmple_sd(ca, face));
        const __m128d t = pick(_mm_cmpeq_sd(va, zero), never,
                               _mm_andnot_pd(beyond, _mm_div_sd(_mm_sub_sd(face, ca), va)));
        const int first = -_mm_comilt_sd(t, soonest); // (all ones, or none)
        soonest = _mm_min_sd(t, soonest);
        axis = (a & first) | (axis & ~first);
        direction = ((2 * _mm_comigt_sd(va, zero) - 1) & first) | (direction & ~first);
    }
    return {_mm_cvtsd_f64(soonest), axis, direction};
}
#else
inline FaceAhead face_ahead(const glm::dvec3 &c, const glm::dvec3 &v,
                            const std::array<int32_t, 3> &cell, const glm::dvec3 &origin,
                            double side) {
    FaceAhead ahead{kNever, 0, 0};
    for (int a = 0; a < 3; ++a) {
        if (v[a] == 0.0) continue;
        const double face =
            origin[a] + (static_cast<double>(cell[a]) + (v[a] > 0.0 ? 1.0 : 0.0)) * side;
        const double t = (v[a] > 0.0 ? c[a] >= face : c[a] <= face) ? 0.0 : (face - c[a]) / v[a];
        if (t < ahead.t) ahead = {t, a, v[a] > 0.0 ? 1 : -1};
    }
    return ahead;
}
#endif

// A centre at c moving at v against a triangle's plane: on which side of it (1: the normal's,
// -1: the other), how far from it, and how fast it comes closer (the triangle tests' numbers).
struct Approach {
    double side, away, closing;
};
inline Approach approach(const GasLane::Triangle &tri, const glm::dvec3 &c, const glm::dvec3 &v) {
    const double d0 = glm::dot(tri.normal, c) - tri.offset, vn = glm::dot(tri.normal, v);
    const double side = d0 > 0.0 ? 1.0 : -1.0;
    return {side, side * d0, -side * vn};
}

} // namespace

// The box the static models close, when they do: the box of all their corners, each of its six
// faces two triangles of one model lying in the face's plane (their normal along its axis alone,
// every corner's coordinate along it the face's) with the face's four corners between them and
// its diagonal shared, so that the two make the whole face. Its faces by index (2 a: the lower
// along axis a, 2 a + 1: the upper), each its two triangles in the general engine's order.
struct GasLane::BoxFaces {
    Box box;
    std::array<std::array<uint32_t, 2>, 6> triangles{};
};
std::optional<GasLane::BoxFaces> GasLane::find_box(const std::vector<Triangle> &triangles) {
    if (triangles.size() < 12) return std::nullopt;
    BoxFaces found;
    found.box = {triangles[0].a, triangles[0].a};
    for (const Triangle &t : triangles)
        for (const glm::dvec3 &p : {t.a, t.b, t.c}) {
            found.box.lo = glm::min(found.box.lo, p);
            found.box.hi = glm::max(found.box.hi, p);
        }
    for (int f = 0; f < 6; ++f) {
        const int a = f / 2, b = (a + 1) % 3, c = (a + 2) % 3;
        const double plane = f % 2 ? found.box.hi[a] : found.box.lo[a];
        // A triangle of the face: the face's corners it has, a bit each (corner 0 to 3: bit 0 of
        // the corner's number upper along b, bit 1 upper along c), or 0 when it is not one.
        const auto corners = [&](const Triangle &t) {
            if (t.normal[a] == 0.0 || t.normal[b] != 0.0 || t.normal[c] != 0.0) return 0;
            int out = 0;
            for (const glm::dvec3 *q : {&t.a, &t.b, &t.c}) {
                const bool lo_b = (*q)[b] == found.box.lo[b], hi_b = (*q)[b] == found.box.hi[b];
                const bool lo_c = (*q)[c] == found.box.lo[c], hi_c = (*q)[c] == found.box.hi[c];
                if ((*q)[a] != plane || !(lo_b || hi_b) || !(lo_c || hi_c)) return 0;
                out |= 1 << ((hi_b ? 1 : 0) | (hi_c ? 2 : 0));
            }
            return __builtin_popcount(static_cast<unsigned>(out)) == 3 ? out : 0; // 3 distinct
        };
        std::vector<std::pair<uint32_t, int>> in_face; // (triangle, its corners)
        for (uint32_t k = 0; k < triangles.size(); ++k)
            if (const int cs = corners(triangles[k])) in_face.emplace_back(k, cs);
        bool whole = false;
        for (std::size_t x = 0; x < in_face.size() && !whole; ++x)
            for (std::size_t y = x + 1; y < in_face.size() && !whole; ++y) {
                const int shared = in_face[x].second & in_face[y].second;
                // Two corners shared, and they are a diagonal's (0 and 3, or 1 and 2).
                whole = triangles[in_face[x].first].model == triangles[in_face[y].first].model &&
                        (shared == 0b1001 || shared == 0b0110);
                if (whole)
                    found.triangles[static_cast<std::size_t>(f)] = {in_face[x].first,
                                                                    in_face[y].first};
            }
        if (!whole) return std::nullopt;
    }
    return found;
}

GasLane::GasLane(double radius, const glm::dvec3 &acceleration, const Grid &grid,
                 std::vector<Triangle> triangles, const ani::HugeVector<Start> &spheres, double now,
                 bool check)
    : r_(radius), reach2_((radius + radius) * (radius + radius)), a_(acceleration),
      falls_(acceleration != glm::dvec3(0.0)), grid_(grid), triangles_(std::move(triangles)) {
    const std::size_t n = spheres.size();
    s_.resize(n); // (each of these written below, sphere by sphere)
    e_.resize(n);
    as_reported_.resize(n);
    contact_.resize(n); // (read only for an event with a triangle, which writes it)
    prev_.resize(n);
    // The box around the spheres, if the static models close one and nothing falls (a parabola
    // meets a face where first_exit and sphere_triangle say). If a sphere is not inside it after
    // all, everything is laid out again without it.
    const std::optional<BoxFaces> box = falls_ ? std::nullopt : find_box(triangles_);
    // (Per sphere, in two halves at once for many spheres; listed by layer for the halves of
    // linking and of the first predictions: with 4 layers of cells or more.)
    const bool two = n >= ani::kWorthTwoHalves, by_layers = two && grid_.counts[2] >= 4;
    Layers layers;
    bool clear = true;
    if (!lay_out(spheres, now, check, box ? &*box : nullptr, two, by_layers, layers, clear))
        lay_out(spheres, now, check, nullptr, two, by_layers, layers, clear);
    if (!clear) {
        admissible_ = false;
        return;
    }
    link_all(by_layers ? &layers : nullptr);
    if (!predict_all_pairs(now, check, by_layers ? &layers : nullptr)) {
        admissible_ = false;
        return;
    }
    ani::UnwrittenVector<double> times(n); // (each written below)
    std::size_t tests[2] = {0, 0};
    ani::in_halves(two, n, [&](std::size_t from, std::size_t to) {
        std::size_t done = 0; // (its own: the two counts share a cache line)
        for (std::size_t i = from; i < to; ++i) {
            predict_move(static_cast<uint32_t>(i), now, done);
            times[i] = std::min(e_[i].pair_time, e_[i].move_time);
        }
        tests[from != 0] = done;
    });
    counts_.done += tests[0] + tests[1];
    queue_.init(times.data(), n, now);
}

// The cells, each cell's triangles, and every sphere's records, placed in its cell (and listed
// by the layer of cells it is in, for the halves of linking and of the first predictions);
// `clear`: whether every sphere is (with `check`). With `box`, its faces are known as such (not
// listed: the spheres moving towards them test them): false, and nothing to be trusted, if a
// sphere is not inside it.
bool GasLane::lay_out(const ani::HugeVector<Start> &spheres, double now, bool check,
                      const BoxFaces *box, bool two, bool by_layers, Layers &layers, bool &clear) {
    const std::size_t n = spheres.size();
    boxed_ = box != nullptr;
    facing_ = 0;
    int64_t cells = 1;
    for (int a = 0; a < 3; ++a) {
        stride_[a] = cells;
        cells *= grid_.counts[a] + 2;
    }
    head_.assign(static_cast<std::size_t>(cells), kNone);
    // (The general grid's order: x fastest, then y, then z.)
    int q = 0;
    for (int z = -1; z <= 1; ++z)
        for (int y = -1; y <= 1; ++y)
            for (int x = -1; x <= 1; ++x)
                around_[q++] = x * stride_[0] + y * stride_[1] + z * stride_[2];
    for (int a = 0; a < 3; ++a)
        for (int d = 0; d < 2; ++d) {
            const int64_t s1 = stride_[(a + 1) % 3], s2 = stride_[(a + 2) % 3];
            q = 0;
            for (int d1 = -1; d1 <= 1; ++d1)
                for (int d2 = -1; d2 <= 1; ++d2)
                    beyond_[2 * a + d][q++] = (d ? 1 : -1) * stride_[a] + d1 * s1 + d2 * s2;
        }
    // The box's faces, and the cells beside each.
    if (box) {
        const double pad = r_ * (1.0 + 1e-6); // (as list_triangles widens the cells)
        for (int f = 0; f < 6; ++f) {
            const int a = f / 2;
            const double plane = f % 2 ? box->box.hi[a] : box->box.lo[a];
            Face &face = faces_[static_cast<std::size_t>(f)];
            face.first = box->triangles[static_cast<std::size_t>(f)][0];
            face.second = box->triangles[static_cast<std::size_t>(f)][1];
            face.from = static_cast<int32_t>(coordinate(plane - pad, a));
            face.to = static_cast<int32_t>(coordinate(plane + pad, a));
            face_order_[static_cast<std::size_t>(f)] = f;
            // (Its plane's front the box's inside, for either triangle: a centre inside can be r
            // in front of it. Behind the plane, never: left_touching.)
            const double inward = f % 2 ? -1.0 : 1.0;
            if (triangles_[face.first].normal[a] * inward > 0.0 ||
                triangles_[face.second].normal[a] * inward > 0.0)
                facing_ |= 1 << f;
        }
        std::sort(face_order_.begin(), face_order_.end(), [&](int x, int y) {
            return faces_[static_cast<std::size_t>(x)].first <
                   faces_[static_cast<std::size_t>(y)].first;
        });
    }
    list_triangles();
    // (What is done per sphere, each sphere's alone: its records, its cell, whether it is clear
    // and inside the box, and the layer of cells it is in, listed.)
    Layers halves[2];
    const int64_t middle = grid_.counts[2] / 2;
    bool clear_in[2] = {true, true}, inside_in[2] = {true, true};
    ani::in_halves(two, n, [&](std::size_t from, std::size_t to) {
        const int half = from != 0;
        Layers &mine = halves[half];
        // (Its own until the end: the other half's share their cache line.)
        bool apart = true, inside = true;
        for (std::size_t i = from; i < to; ++i) {
            const Start &st = spheres[i];
            Sphere &p = s_[i];
            put(p.x, st.p);
            put(p.v, st.v);
            p.t0 = st.t0;
            p.count = 0;
            e_[i] = Event{};
            e_[i].mass = st.mass;
            as_reported_[i] = {st.model, st.motion};
            const glm::dvec3 c = at(p, now);
            const std::array<int64_t, 3> cell{coordinate(c.x, 0), coordinate(c.y, 1),
                                              coordinate(c.z, 2)};
            place(static_cast<uint32_t>(i), cell);
            if (check) apart = apart && clear_of(static_cast<uint32_t>(i), c);
            if (box)
                inside = inside && glm::all(glm::greaterThan(c, box->box.lo)) &&
                         glm::all(glm::lessThan(c, box->box.hi));
            if (by_layers)
                (cell[2] < middle - 1 ? mine.below
                 : cell[2] < middle   ? mine.between
                                      : mine.above)
                    .push_back(static_cast<uint32_t>(i));
        }
        clear_in[half] = apart;
        inside_in[half] = inside;
    });
    clear = clear_in[0] && clear_in[1];
    if (by_layers) { // (the halves' lists one after the other: each in the order of the spheres)
        layers = std::move(halves[0]);
        const auto append = [](std::vector<uint32_t> &to, const std::vector<uint32_t> &from) {
            to.insert(to.end(), from.begin(), from.end());
        };
        append(layers.below, halves[1].below);
        append(layers.between, halves[1].between);
        append(layers.above, halves[1].above);
    }
    return inside_in[0] && inside_in[1];
}

// Each cell's triangles: those whose box reaches the cell's widened by the radius (and a little
// more, for rounding), in the general engine's order; counted, then listed. (With boxed_, the
// box's faces are not: the spheres moving towards them test them.)
void GasLane::list_triangles() {
    const double pad = r_ * (1.0 + 1e-6);
    const auto each_cell = [&](const Box &box, auto &&f) {
        std::array<int64_t, 3> lo{}, hi{};
        for (int a = 0; a < 3; ++a) {
            lo[a] = coordinate(box.lo[a] - pad, a);
            hi[a] = coordinate(box.hi[a] + pad, a);
        }
        for (int64_t z = lo[2]; z <= hi[2]; ++z)
            for (int64_t y = lo[1]; y <= hi[1]; ++y)
                for (int64_t x = lo[0]; x <= hi[0]; ++x)
                    f(static_cast<std::size_t>(cell_index({x, y, z})));
    };
    std::vector<bool> listed(triangles_.size(), true);
    if (boxed_)
        for (const Face &face : faces_) listed[face.first] = listed[face.second] = false;
    const std::size_t cells = head_.size();
    near_from_.assign(cells + 1, 0);
    for (uint32_t k = 0; k < triangles_.size(); ++k)
        if (listed[k]) each_cell(triangles_[k].box, [&](std::size_t c) { ++near_from_[c + 1]; });
    for (std::size_t c = 0; c < cells; ++c) near_from_[c + 1] += near_from_[c];
    near_.resize(near_from_.back());
    // (Each cell's start used as its cursor, leaving it at the next cell's start: moved back up
    // one cell after. No copy of the starts: at 100,000 balls 800 KB in fresh pages a bake.)
    for (uint32_t k = 0; k < triangles_.size(); ++k)
        if (listed[k])
            each_cell(triangles_[k].box, [&](std::size_t c) { near_[near_from_[c]++] = k; });
    std::copy_backward(near_from_.begin(), near_from_.end() - 1, near_from_.end());
    near_from_[0] = 0;
}

// Calls f(k) for each triangle k near e's cell: those of the box's faces in `faces` (a bit each),
// in the lists' order, then those its cell lists; stops at the first for which f is true (and
// says so).
template <class F> inline bool GasLane::any_near(const Event &e, int faces, F &&f) const {
    for (int k = 0; faces != 0 && k < 6; ++k) {
        const Face &face = faces_[static_cast<std::size_t>(face_order_[k])];
        if ((faces >> face_order_[k] & 1) && (f(face.first) || f(face.second))) return true;
    }
    for (uint32_t k = e.near_from; k < e.near_to; ++k)
        if (f(near_[k])) return true;
    return false;
}

// Whether sphere i (placed, its centre at c) is inside the grid's cells and not within r (and the
// general engine's touching allowance, 1e-6 r: EventBake::overlaps_body) of a triangle: one
// touching a face, which the general engine may put on it, is left to the general engine too.
// (That no two overlap is checked by predict_all_pairs, which reads every pair anyway.)
bool GasLane::clear_of(uint32_t i, const glm::dvec3 &c) const {
    const Event &e = e_[i];
    if (!in_grid(e)) return false;
    const double beside = r_ * (1.0 + 1e-6);
    const auto apart = [&](uint32_t k) {
        const Triangle &tri = triangles_[k];
        return !(glm::length(c - closest_point_on_triangle(c, tri.a, tri.b, tri.c)) < beside);
    };
    return !any_near(e, e.faces, [&](uint32_t k) { return !apart(k); });
}

// Every sphere linked into its cell's list, in the order of the spheres (each list then starts
// with its last), as one pass over them would link them. With `layers`, in two halves at once:
// the layers of cells below the middle one and those from it up (a cell's spheres all in one
// half, each half in the spheres' order).
void GasLane::link_all(const Layers *layers) {
    if (!layers) {
        for (uint32_t i = 0; i < s_.size(); ++i) link(i);
        return;
    }
    ani::side_by_side(
        [&] { // below and between, merged in the spheres' order
            const std::vector<uint32_t> &a = layers->below, &b = layers->between;
            std::size_t j = 0, k = 0;
            while (j < a.size() || k < b.size())
                link(k == b.size() || (j < a.size() && a[j] < b[k]) ? a[j++] : b[k++]);
        },
        [&] {
            for (uint32_t i : layers->above) link(i);
        });
}

// Where a sphere is at t, and how fast it moves: Path::at and Path::velocity, the same operations
// in the same order (without acceleration, the term that would add 0 is left out).
inline glm::dvec3 GasLane::at(const Sphere &p, double t) const {
    const double dt = t - p.t0;
    if (falls_) return Path{vec(p.x), vec(p.v), a_}.at(dt);
    return {p.x[0] + p.v[0] * dt, p.x[1] + p.v[1] * dt, p.x[2] + p.v[2] * dt};
}

inline glm::dvec3 GasLane::velocity(const Sphere &p, double t) const {
    if (falls_) return Path{vec(p.x), vec(p.v), a_}.velocity(t - p.t0);
    return vec(p.v);
}

// The cell along axis a of coordinate x (grid.hpp's cell_of): clamped to the layer of empty cells
// around the grid's.
int64_t GasLane::coordinate(double x, int a) const {
    return static_cast<int64_t>(std::clamp(std::floor((x - grid_.origin[a]) / grid_.cell), -1.0,
                                           static_cast<double>(grid_.counts[a])));
}

int64_t GasLane::cell_index(const std::array<int64_t, 3> &c) const {
    return (c[0] + 1) * stride_[0] + (c[1] + 1) * stride_[1] + (c[2] + 1) * stride_[2];
}

void GasLane::place(uint32_t i, const std::array<int64_t, 3> &c) {
    Event &e = e_[i];
    for (int a = 0; a < 3; ++a) e.cell[a] = static_cast<int32_t>(c[a]);
    e.index = static_cast<uint32_t>(cell_index(c));
    e.near_from = near_from_[e.index];
    e.near_to = near_from_[e.index + 1];
    e.faces = 0;
    for (int f = 0; boxed_ && f < 6; ++f) {
        const Face &face = faces_[static_cast<std::size_t>(f)];
        e.faces |= static_cast<uint8_t>((c[f / 2] >= face.from && c[f / 2] <= face.to) << f);
    }
}

void GasLane::link(uint32_t i) {
    const std::size_t cell = e_[i].index;
    Sphere &p = s_[i];
    p.next = head_[cell];
    if (p.next != kNone) prev_[p.next] = i;
    prev_[i] = kNone;
    head_[cell] = i;
}

void GasLane::unlink(uint32_t i) {
    Sphere &p = s_[i];
    if (prev_[i] != kNone)
        s_[prev_[i]].next = p.next;
    else
        head_[e_[i].index] = p.next;
    if (p.next != kNone) prev_[p.next] = prev_[i];
}

namespace {

// The candidates of one scan, gathered (structure of arrays, so that their roots are computed
// several at a time), and what the roots are computed from.
struct Batch {
    static constexpr int kSize = 64;
    alignas(32) double x[kSize], y[kSize], z[kSize], vx[kSize], vy[kSize], vz[kSize], t0[kSize];
    alignas(32) double t[kSize]; // out: the time from now of each one's contact, or infinity
    uint32_t sphere[kSize], count[kSize];
    int n = 0;
    // Candidate k: centre p and velocity v at t0.
    void set(int k, const glm::dvec3 &p, const glm::dvec3 &v, double at) {
        x[k] = p.x;
        y[k] = p.y;
        z[k] = p.z;
        vx[k] = v.x;
        vy[k] = v.y;
        vz[k] = v.z;
        t0[k] = at;
    }
};
struct Scanner {
    double now, x, y, z, vx, vy, vz, reach2, horizon;
};

// d = here - candidate k moved to now, as every root of a scan has it (the start's overlap check
// reads the same numbers).
inline void offset(const Batch &b, const Scanner &s, int k, double &dx, double &dy, double &dz) {
    const double dt = s.now - b.t0[k];
    dx = s.x - (b.x[k] + b.vx[k] * dt);
    dy = s.y - (b.y[k] + b.vy[k] * dt);
    dz = s.z - (b.z[k] + b.vz[k] * dt);
}

// sphere_sphere's stable root for every candidate of the batch, as sphere_sphere(here, r, there, r)
// computes it (d = here - there, e = v - v_o; the same operations in the same order, so the same
// numbers): infinity for one that is not approaching, does not meet, or meets no earlier than
// the horizon. Several at a time where the processor can (the same operations on each).
inline void roots_scalar(Batch &b, const Scanner &s, int from) {
    for (int k = from; k < b.n; ++k) {
        double dx, dy, dz;
        offset(b, s, k, dx, dy, dz);
        const double ex = s.vx - b.vx[k], ey = s.vy - b.vy[k], ez = s.vz - b.vz[k];
        const double qa = ex * ex + ey * ey + ez * ez, qb = dx * ex + dy * ey + dz * ez,
                     qc = dx * dx + dy * dy + dz * dz - s.reach2;
        const double disc = qb * qb - qa * qc;
        const double root = qc / (-qb + std::sqrt(std::max(disc, 0.0)));
        const double t = qc <= 0.0 ? 0.0 : root; // touching (or overlapping) and approaching
        const bool earlier = (qb < 0.0) & (qc <= 0.0 || disc >= 0.0) & (t < s.horizon);
        b.t[k] = earlier ? t : std::numeric_limits<double>::infinity();
    }
}

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
__attribute__((target("avx2"))) void roots_avx2(Batch &b, const Scanner &s) {
    const __m256d now = _mm256_set1_pd(s.now), x = _mm256_set1_pd(s.x), y = _mm256_set1_pd(s.y),
                  z = _mm256_set1_pd(s.z), vx = _mm256_set1_pd(s.vx), vy = _mm256_set1_pd(s.vy),
                  vz = _mm256_set1_pd(s.vz), reach2 = _mm256_set1_pd(s.reach2),
                  horizon = _mm256_set1_pd(s.horizon), zero = _mm256_setzero_pd(),
                  inf = _mm256_set1_pd(std::numeric_limits<double>::infinity());
    int k = 0;
    for (; k + 4 <= b.n; k += 4) {
        const __m256d dt = _mm256_sub_pd(now, _mm256_load_pd(b.t0 + k));
        const __m256d ovx = _mm256_load_pd(b.vx + k), ovy = _mm256_load_pd(b.vy + k),
                      ovz = _mm256_load_pd(b.vz + k);
        const __m256d dx = _mm256_sub_pd(
                          x, _mm256_add_pd(_mm256_load_pd(b.x + k), _mm256_mul_pd(ovx, dt))),
                      dy = _mm256_sub_pd(
                          y, _mm256_add_pd(_mm256_load_pd(b.y + k), _mm256_mul_pd(ovy, dt))),
                      dz = _mm256_sub_pd(
                          z, _mm256_add_pd(_mm256_load_pd(b.z + k), _mm256_mul_pd(ovz, dt)));
        const __m256d ex = _mm256_sub_pd(vx, ovx), ey = _mm256_sub_pd(vy, ovy),
                      ez = _mm256_sub_pd(vz, ovz);
        const __m256d qa = _mm256_add_pd(
            _mm256_add_pd(_mm256_mul_pd(ex, ex), _mm256_mul_pd(ey, ey)), _mm256_mul_pd(ez, ez));
        const __m256d qb = _mm256_add_pd(
            _mm256_add_pd(_mm256_mul_pd(dx, ex), _mm256_mul_pd(dy, ey)), _mm256_mul_pd(dz, ez));
        const __m256d qc =
            _mm256_sub_pd(_mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(dx, dx), _mm256_mul_pd(dy, dy)),
                                        _mm256_mul_pd(dz, dz)),
                          reach2);
        const __m256d disc = _mm256_sub_pd(_mm256_mul_pd(qb, qb), _mm256_mul_pd(qa, qc));
        const __m256d root = _mm256_div_pd(
            qc, _mm256_add_pd(_mm256_sub_pd(zero, qb), _mm256_sqrt_pd(_mm256_max_pd(disc, zero))));
        const __m256d touching = _mm256_cmp_pd(qc, zero, _CMP_LE_OQ);
        const __m256d t = _mm256_blendv_pd(root, zero, touching);
        const __m256d earlier = _mm256_and_pd(
            _mm256_and_pd(_mm256_cmp_pd(qb, zero, _CMP_LT_OQ),
                          _mm256_or_pd(touching, _mm256_cmp_pd(disc, zero, _CMP_GE_OQ))),
            _mm256_cmp_pd(t, horizon, _CMP_LT_OQ));
        _mm256_store_pd(b.t + k, _mm256_blendv_pd(inf, t, earlier));
    }
    roots_scalar(b, s, k);
}
// (__builtin_cpu_init first: this runs among the library's static initialisers.)
const bool kAvx2 = [] {
    __builtin_cpu_init();
    return __builtin_cpu_supports("avx2") != 0;
}();
#endif

void roots(Batch &b, const Scanner &s) {
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
    if (kAvx2) return roots_avx2(b, s);
#endif
    roots_scalar(b, s, 0);
}

// The roots of a scan's batch, filled to a whole number of fours with the scanning sphere
// itself (not approaching, never earlier); its count of candidates is kept.
inline void solve(Batch &b, const Scanner &s) {
    for (int n = b.n; n % 4 != 0; ++n) b.set(n, {s.x, s.y, s.z}, {s.vx, s.vy, s.vz}, s.now);
    const int found = b.n;
    b.n = (b.n + 3) / 4 * 4;
    roots(b, s);
    b.n = found;
}

} // namespace

// Sphere k as a candidate of a scan at `now` (moved to now when paths fall: the roots then move
// it by 0 s); true when the batch is full. (Inlined: a call for each candidate made the scans of
// a 10,000-ball gas 4% slower.)
template <class B>
[[gnu::always_inline]] inline bool GasLane::gather(B &batch, uint32_t k, double now) const {
    const Sphere &o = s_[k];
    const int n = batch.n++;
    if (falls_)
        batch.set(n, at(o, now), velocity(o, now), now);
    else
        batch.set(n, vec(o.x), vec(o.v), o.t0);
    batch.sphere[n] = k;
    batch.count[n] = o.count;
    return batch.n == B::kSize;
}

// The earliest collision of i with the spheres of the cells at `offsets` from its cell, if
// earlier than the pair part of its event (`all`: that part starts afresh). The candidates are
// gathered in batches and their roots computed together (roots: without branches, which would
// be mispredicted, and several at a time); the earliest is taken in the order they were found.
void GasLane::scan(uint32_t i, double now, const int64_t *offsets, int count, bool all) {
    const Sphere &a = s_[i];
    Event &e = e_[i];
    if (all) {
        e.pair_time = kInf;
        e.partner = kNone;
    }
    const glm::dvec3 here = at(a, now), v = velocity(a, now);
    Scanner s{now, here.x, here.y, here.z, v.x, v.y, v.z, reach2_, e.pair_time - now};
    uint32_t partner = kNone, partner_count = 0;
    std::size_t tests = 0;
    Batch batch;
    const auto take = [&] {
        solve(batch, s);
        for (int k = 0; k < batch.n; ++k)
            if (batch.t[k] < s.horizon) {
                s.horizon = batch.t[k];
                partner = batch.sphere[k];
                partner_count = batch.count[k];
            }
        tests += static_cast<std::size_t>(batch.n);
        batch.n = 0;
    };
    // The cells' first spheres, listed without a branch (whether a cell is empty is a coin toss
    // at a gas's density) and not prefetched: the walk below loads them overlapped anyway, and
    // the two together made a 10,000-ball bake a sixth faster (docs/performance.md, the gas).
    const int64_t cell = e.index;
    uint32_t first[27];
    int m = 0;
    for (int q = 0; q < count; ++q) {
        const uint32_t k = head_[static_cast<std::size_t>(cell + offsets[q])];
        first[m] = k;
        m += k != kNone;
    }
    for (int q = 0; q < m; ++q)
        for (uint32_t k = first[q]; k != kNone; k = s_[k].next)
            if (k != i && gather(batch, k, now)) take();
    take();
    ++counts_.predictions;
    counts_.done += tests;
    if (all) counts_.skipped += s_.size() - 1 - tests;
    if (partner != kNone) {
        e.pair_time = now + s.horizon;
        e.partner = partner;
        e.partner_count = partner_count;
    }
}

void GasLane::predict_pairs(uint32_t i, double now) {
    scan(i, now, around_, 27, true);
}

// Every sphere's earliest collision at the start, each pair's root computed
// once (a scan per sphere computed each twice): each sphere scans its own cell's later spheres and
// the 13 cells after its own (around_[14..26], the others' mirror images), and offers the root to
// both. The root is the same number from either side (d and e change sign, their products do
// not), so every sphere gets the times its own scan would have found. With `check`, false (and
// the predictions unfinished) when two spheres are closer than 2r less the general engine's
// touching allowance (1e-6 r each: EventBake::overlaps_body): the squared distance of each pair
// from the batch its root was computed from. With `layers` (4 layers of cells or more), in two
// halves at once (below).
bool GasLane::predict_all_pairs(double now, bool check, const Layers *layers) {
    const std::size_t n = s_.size();
    std::size_t tests = 0;
    if (!layers) {
        if (!all_pairs_of(now, check, tests, nullptr, n)) return false;
    } else {
        // In two halves at once: the spheres below the middle layer of cells but one, and those
        // from it up. A sphere's pairs reach its own layer and the next, so the halves write
        // apart (and each reads only its own spheres' events: listed first); the layer between
        // them after. (Each sphere is offered the same roots; only the order of two offers from
        // either side of that layer changes, which decides between exactly equal times alone.)
        const std::vector<uint32_t> &below = layers->below, &above = layers->above,
                                    &between = layers->between;
        std::size_t tests_above = 0;
        bool apart_below = true, apart_above = true;
        ani::side_by_side(
            [&] { apart_below = all_pairs_of(now, check, tests, below.data(), below.size()); },
            [&] {
                apart_above = all_pairs_of(now, check, tests_above, above.data(), above.size());
            });
        tests += tests_above;
        if (!(apart_below && apart_above &&
              all_pairs_of(now, check, tests, between.data(), between.size())))
            return false;
    }
    counts_.predictions += n;
    counts_.done += tests;
    counts_.skipped += n * (n - 1) / 2 - tests;
    return true;
}

// predict_all_pairs for the spheres listed (ids[0, listed), or 0 to listed - 1 without a list),
// its pair tests added to `tests_out`.
bool GasLane::all_pairs_of(double now, bool check, std::size_t &tests_out, const uint32_t *ids,
                           std::size_t listed) {
    std::size_t tests = 0; // (added at the end: the other half's count may share its cache line)
    const double closest = (r_ + r_) * (1.0 - 1e-6), closest2 = closest * closest;
    const auto offer = [](Event &ev, double at, uint32_t who, uint32_t count) {
        if (at < ev.pair_time) { // (ties: the one offered first stays)
            ev.pair_time = at;
            ev.partner = who;
            ev.partner_count = count;
        }
    };
    Batch batch;
    for (std::size_t l = 0; l < listed; ++l) {
        const uint32_t i = ids ? ids[l] : static_cast<uint32_t>(l);
        const Sphere &a = s_[i];
        const glm::dvec3 here = at(a, now), v = velocity(a, now);
        const Scanner s{now, here.x, here.y, here.z, v.x, v.y, v.z, reach2_, kInf};
        bool overlap = false;
        const auto take = [&] {
            solve(batch, s);
            for (int k = 0; check && k < batch.n; ++k) {
                double dx, dy, dz;
                offset(batch, s, k, dx, dy, dz);
                overlap |= dx * dx + dy * dy + dz * dz < closest2;
            }
            for (int k = 0; k < batch.n; ++k) {
                const double t = batch.t[k];
                if (!(t < kInf)) continue;
                offer(e_[i], now + t, batch.sphere[k], batch.count[k]);
                offer(e_[batch.sphere[k]], now + t, i, a.count);
            }
            tests += static_cast<std::size_t>(batch.n);
            batch.n = 0;
        };
        const int64_t cell = e_[i].index;
        for (uint32_t k = head_[static_cast<std::size_t>(cell)]; k != kNone; k = s_[k].next)
            if (k > i && gather(batch, k, now)) take();
        for (int q = 14; q < 27; ++q)
            for (uint32_t k = head_[static_cast<std::size_t>(cell + around_[q])]; k != kNone;
                 k = s_[k].next)
                if (gather(batch, k, now)) take();
        take();
        if (overlap) return false;
    }
    tests_out += tests;
    return true;
}

// Its next move from now: out of its cell, or into a static model's triangle listed for its cell
// before that (sphere_triangle, as the general engine's obstacles). The crossing is first_exit's
// for a path without acceleration, written out (face_ahead).
void GasLane::predict_move(uint32_t i, double now, std::size_t &done) {
    const Sphere &p = s_[i];
    Event &e = e_[i];
    e.move_time = kInf;
    e.triangle = kNone;
    const glm::dvec3 c = at(p, now), v = velocity(p, now);
    if (falls_) return predict_fall(i, now, Path{c, v, a_}, done);
    if (v == glm::dvec3(0.0)) return; // still: it moves nowhere (the movers meet it)
    const FaceAhead ahead = face_ahead(c, v, e.cell, grid_.origin, grid_.cell);
    double limit = ahead.t;
    if (limit < kInf) {
        e.axis = static_cast<int8_t>(ahead.axis);
        e.direction = static_cast<int8_t>(ahead.direction);
    }
    e.move_time = now + limit;
    const uint32_t from = e.near_from, to = e.near_to;
    // The box's faces beside its cell that it moves towards (tested as if listed: in the lists'
    // order, before the cell's other triangles).
    int faces = 0;
    if (e.faces != 0)
        for (int a = 0; a < 3; ++a) faces |= (v[a] != 0.0) << (2 * a + (v[a] > 0.0));
    faces &= e.faces;
    if (from == to && faces == 0) return;
    const Path here{c, v, glm::dvec3(0.0)};
    const auto offer = [&](uint32_t k, const Contact &hit) {
        limit = hit.t;
        e.move_time = now + hit.t;
        e.triangle = k;
        Contact &kept = contact_[i]; // (field by field: a copy whole was a `rep movs`)
        kept.t = hit.t;
        kept.normal = hit.normal;
        kept.point = hit.point;
    };
    // A face of the box, its centre inside it: met where it meets the face's plane (r away), the
    // contact inside the face; the common case of the test below, with its numbers, written out.
    // (Touching it already, by rounding: the test below.)
    int general = 0;
    for (int f : face_order_) {
        if (!(faces >> f & 1)) continue;
        const Triangle &tri = triangles_[faces_[f].first];
        const glm::dvec3 &n = tri.normal;
        const auto [side, away, closing] = approach(tri, c, v);
        if (!(away > r_ && closing > 0.0)) {
            general |= 1 << f;
            continue;
        }
        ++done;
        const double t = (away - r_) / closing;
        if (t <= limit) {
            const glm::dvec3 normal = side * n;
            offer(faces_[f].first, Contact{t, normal, here.at(t) - normal * r_});
        }
    }
    if (from == to && general == 0) return;
    Box reach = swept_box(here, limit);
    reach.lo -= glm::dvec3(r_);
    reach.hi += glm::dvec3(r_);
    // Within r of a triangle's plane is where any contact with it starts (its edges and corners
    // lie in the plane): a path that stays farther over [0, limit] (with a margin for rounding),
    // or that leaves the plane from r away or more (to rounding: it has just bounced off it), meets
    // none. Once a face is met, the triangles of the same plane (the other half of a box's side)
    // are met no earlier. A path that meets the plane outside the triangle meets its edges or
    // corners no earlier than the plane: tested last, and only when that is soon enough.
    const double far = r_ * (1.0 + 1e-9) + 1e-12, off = r_ * (1.0 - 1e-9);
    const Triangle *met = nullptr;
    uint32_t later[16];
    double plane_at[16];
    int deferred = 0;
    const auto test = [&](uint32_t k) {
        const Triangle &tri = triangles_[k];
        if (!reach.overlaps(tri.box)) return;
        const glm::dvec3 &n = tri.normal;
        if (n == glm::dvec3(0.0)) {
            ++done;
            if (auto hit = sphere_triangle(here, r_, tri.a, tri.b, tri.c, limit)) offer(k, *hit);
            return;
        }
        const auto [side, away, closing] = approach(tri, c, v);
        if (away + std::min(-closing * limit, 0.0) > far || (closing <= 0.0 && away >= off)) return;
        if (met && n == met->normal && tri.offset == met->offset) return;
        ++done;
        if (away > r_ && closing > 0.0) {
            // sphere_triangle's common case written out: the plane at (away - r) / closing, met
            // inside the triangle (sphere_triangle's test).
            const double t = (away - r_) / closing;
            if (!(t <= limit)) return;
            const glm::dvec3 normal = side * n, q = here.at(t) - r_ * normal;
            // (The corners named, not copied: a copy of the three was a `rep movs`, slow to
            // start, at every face met.)
            const glm::dvec3 *const corners[3] = {&tri.a, &tri.b, &tri.c};
            bool inside = true;
            for (int j = 0; j < 3 && inside; ++j) {
                const glm::dvec3 &a = *corners[j], &b = *corners[(j + 1) % 3];
                inside = glm::dot(n, glm::cross(b - a, q - a)) >= 0.0;
            }
            if (inside) {
                offer(k, Contact{t, normal, here.at(t) - normal * r_});
                met = &tri;
                return;
            }
            if (deferred < 16) {
                later[deferred] = k;
                plane_at[deferred++] = t;
                return;
            }
        }
        if (auto hit = sphere_triangle(here, r_, tri.a, tri.b, tri.c, limit)) {
            offer(k, *hit);
            met = nullptr;
        }
    };
    any_near(e, general, [&](uint32_t k) {
        test(k);
        return false;
    });
    for (int k = 0; k < deferred; ++k) {
        if (plane_at[k] >= limit) continue; // (a tie at most: met as early already)
        const Triangle &tri = triangles_[later[k]];
        if (auto hit = sphere_triangle(here, r_, tri.a, tri.b, tri.c, limit)) offer(later[k], *hit);
    }
}

// predict_move for a sphere under gravity: its cell's walls by first_exit, and the triangles of
// its cell by sphere_triangle, on its parabola (`here`, from now).
void GasLane::predict_fall(uint32_t i, double now, const Path &here, std::size_t &done) {
    Event &e = e_[i];
    Box bounds;
    for (int a = 0; a < 3; ++a) {
        bounds.lo[a] = grid_.origin[a] + static_cast<double>(e.cell[a]) * grid_.cell;
        bounds.hi[a] = grid_.origin[a] + static_cast<double>(e.cell[a] + 1) * grid_.cell;
    }
    // (A parabola leaves every box: there is an exit.)
    const std::optional<Exit> exit = first_exit(here, bounds, kInf);
    if (!exit) return;
    double limit = exit->t;
    e.move_time = now + limit;
    e.axis = static_cast<int8_t>(exit->axis);
    e.direction = static_cast<int8_t>(exit->direction);
    if (e.near_from == e.near_to) return;
    Box reach = swept_box(here, limit);
    reach.lo -= glm::dvec3(r_);
    reach.hi += glm::dvec3(r_);
    for (uint32_t k = e.near_from; k < e.near_to; ++k) {
        const Triangle &tri = triangles_[near_[k]];
        if (!reach.overlaps(tri.box)) continue;
        ++done;
        if (auto hit = sphere_triangle(here, r_, tri.a, tri.b, tri.c, limit)) {
            limit = hit->t;
            e.move_time = now + hit->t;
            e.triangle = near_[k];
            contact_[i] = *hit;
        }
    }
}

void GasLane::schedule(uint32_t i) {
    queue_.update(i, std::min(e_[i].pair_time, e_[i].move_time));
}

// The general engine's test for a contact without speed along its normal (EventBake::grazing):
// it leaves such a pair alone until apart, which the lane does not do.
bool GasLane::grazing(const glm::dvec3 &relative, const glm::dvec3 &n) const {
    return -glm::dot(relative, n) <= 1e-9 * std::max(1.0, glm::length(relative));
}

// Whether a sphere at c moving at v after a contact touches the plane of a triangle near it
// without speed along its normal: the general engine would put it on that face
// (EventBake::try_settle). Looser than that test: any such triangle of its cell.
bool GasLane::left_touching(uint32_t i, const glm::dvec3 &c, const glm::dvec3 &v) const {
    const Event &e = e_[i];
    const double tol = 1e-6 * r_;
    const auto touching = [&](uint32_t k) {
        const Triangle &tri = triangles_[k];
        return tri.normal != glm::dvec3(0.0) &&
               std::abs(glm::dot(tri.normal, c) - tri.offset - r_) <= tol &&
               std::abs(glm::dot(v, tri.normal)) <= 1e-9 * std::max(1.0, glm::length(v));
    };
    return any_near(e, e.faces & facing_, touching);
}

// Its segment up to t, from where it started or from where this slice starts
// (EventBake::close_segment).
void GasLane::emit(uint32_t i, double t, Sink &sink) const {
    const Sphere &p = s_[i];
    const double from = std::max(p.t0, t_begin_);
    if (t <= from && !(t == t_end_ && from == t_end_)) return;
    ani_motion_segment s{};
    s.model = as_reported_[i].model;
    s.motion = as_reported_[i].motion;
    s.t0 = from;
    s.t1 = t;
    s.p0 = ani(from == p.t0 ? vec(p.x) : at(p, from));
    s.v0 = ani(from == p.t0 ? vec(p.v) : velocity(p, from));
    s.a = ani(a_);
    sink.segment(s);
}

void GasLane::restart(uint32_t i, double t, const glm::dvec3 &v, Sink &sink) {
    emit(i, t, sink);
    Sphere &p = s_[i];
    put(p.x, at(p, t));
    put(p.v, v);
    p.t0 = t;
    ++p.count;
    as_reported_[i].motion = ANI_MOTION_FREE;
}

// Two spheres meet at t: the elastic exchange between their masses along the line of centres
// (EventBake::collide_bodies). False, changing nothing, when the general engine would do other.
bool GasLane::collide(uint32_t i, uint32_t j, double t, Sink &sink) {
    const glm::dvec3 ci = at(s_[i], t), cj = at(s_[j], t), between = ci - cj;
    const glm::dvec3 n = glm::length(between) > 0.0 ? glm::normalize(between) : glm::dvec3(0, 1, 0);
    const glm::dvec3 v = velocity(s_[i], t), vo = velocity(s_[j], t);
    if (grazing(v - vo, n)) return false;
    const auto [va, vb] = elastic_exchange(e_[i].mass, v, e_[j].mass, vo, n);
    if (left_touching(i, ci, va) || left_touching(j, cj, vb)) return false;
    ani_collision_event ev{};
    ev.t = t;
    ev.a = as_reported_[i].model;
    ev.b = as_reported_[j].model;
    ev.normal = ani(n);
    ev.point = ani(ci - n * r_);
    ev.speed = std::max(0.0, -glm::dot(v - vo, n));
    restart(i, t, va, sink);
    restart(j, t, vb, sink);
    sink.collision(ev);
    return true;
}

// A sphere meets a static model at t: the reflection (EventBake::collide_obstacle).
bool GasLane::bounce(uint32_t i, double t, Sink &sink) {
    const Event &e = e_[i];
    const Contact &contact = contact_[i];
    const glm::dvec3 v = velocity(s_[i], t), n = contact.normal;
    if (grazing(v, n)) return false;
    const glm::dvec3 v1 = reflect(v, n);
    if (left_touching(i, at(s_[i], t), v1)) return false;
    ani_collision_event ev{};
    ev.t = t;
    ev.a = as_reported_[i].model;
    ev.b = triangles_[e.triangle].model;
    ev.normal = ani(n);
    ev.point = ani(contact.point);
    ev.speed = std::max(0.0, -glm::dot(v, n));
    restart(i, t, v1, sink);
    sink.collision(ev);
    return true;
}

// Into the next cell: only the 9 cells beyond it are new (the pair part found before bounds the
// others). False, changing nothing, when that cell is outside the grid.
bool GasLane::cross(uint32_t i, double now) {
    const Event &e = e_[i];
    std::array<int64_t, 3> c{e.cell[0], e.cell[1], e.cell[2]};
    c[static_cast<std::size_t>(e.axis)] += e.direction;
    for (int a = 0; a < 3; ++a)
        if (c[a] < 0 || c[a] >= grid_.counts[a]) return false;
    unlink(i);
    place(i, c);
    link(i);
    ++counts_.crossings;
    scan(i, now, beyond_[2 * e.axis + (e.direction > 0)], 9, false);
    return true;
}

// What sphere k's event will read, fetched from memory while the event before it is done, now
// that k's event record has come (asked for at that event's start): the partner of a pair part;
// for a crossing, the sphere's place in its cell's list and the cell it enters.
void GasLane::fetch_ahead(uint32_t k) const {
    const Event &e = e_[k];
    if (e.pair_time <= e.move_time && e.partner != kNone) {
        __builtin_prefetch(&s_[e.partner]);
        __builtin_prefetch(&e_[e.partner]);
        __builtin_prefetch(&as_reported_[e.partner]);
    } else if (e.triangle == kNone) {
        const int64_t to = e.index + e.direction * stride_[static_cast<std::size_t>(e.axis)];
        __builtin_prefetch(&prev_[k]);
        __builtin_prefetch(&head_[static_cast<std::size_t>(to)]);
        __builtin_prefetch(&near_from_[static_cast<std::size_t>(to)]);
    }
}

bool GasLane::run(double t_begin, double t_end, Sink &sink) {
    t_begin_ = t_begin;
    t_end_ = t_end;
    for (double t = queue_.top_time(); t <= t_end; t = queue_.top_time()) {
        const uint32_t i = queue_.top();
        // The event after this one is nearly always its bucket's second (this one's updates
        // rarely come before it): its sphere fetched from memory while this one is done.
        const uint32_t after = queue_.second();
        if (after != kNone) {
            __builtin_prefetch(&e_[after]);
            __builtin_prefetch(&s_[after]);
            __builtin_prefetch(&as_reported_[after]);
        }
        queue_.fetch(i); // (its place in the queue: updated at the end)
        Event &e = e_[i];
        at_once_ = t == last_ ? at_once_ + 1 : 0;
        last_ = t;
        if (at_once_ > 100000 + 10 * s_.size())
            throw ani::Failure(ANI_ERR_FAILED, "models keep colliding at t = " + std::to_string(t) +
                                                   " s without moving apart");
        if (e.pair_time <= e.move_time) {
            const uint32_t j = e.partner;
            __builtin_prefetch(&e_[j]); // (read after the collision: fetched meanwhile)
            queue_.fetch(j);
            if (s_[j].count != e.partner_count) { // j changed course since: predict i anew
                ++counts_.stale;
                predict_pairs(i, t);
            } else {
                if (!collide(i, j, t, sink)) {
                    stopped_at_ = t;
                    return false;
                }
                predict_pairs(i, t);
                predict_move(i, t);
                predict_pairs(j, t);
                predict_move(j, t);
                schedule(j);
            }
        } else if (e.triangle != kNone) {
            if (!bounce(i, t, sink)) {
                stopped_at_ = t;
                return false;
            }
            predict_pairs(i, t);
            predict_move(i, t);
        } else {
            if (!cross(i, t)) {
                stopped_at_ = t;
                return false;
            }
            predict_move(i, t);
        }
        if (after != kNone) fetch_ahead(after);
        schedule(i);
        if (++counts_.events % 1024 == 0) sink.progress(t);
        // The next event's sphere, fetched while the queue finds it again.
        if (queue_.top_time() <= t_end) {
            __builtin_prefetch(&e_[queue_.top()]);
            __builtin_prefetch(&s_[queue_.top()]);
        }
    }
    return true;
}

void GasLane::close(double t_begin, double t_end, Sink &sink) {
    t_begin_ = t_begin;
    t_end_ = t_end;
    for (uint32_t i = 0; i < s_.size(); ++i) emit(i, t_end, sink);
}

GasLane::Start GasLane::state(std::size_t k) const {
    const Sphere &p = s_[k];
    Start st;
    st.model = as_reported_[k].model;
    st.mass = e_[k].mass;
    st.motion = as_reported_[k].motion;
    st.t0 = p.t0;
    st.p = vec(p.x);
    st.v = vec(p.v);
    return st;
}

} // namespace physics_custom
