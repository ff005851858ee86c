// The gas lane of the event-driven bake (physics.md, "The gas lane"; docs/performance.md, the
// gas): a scene whose moving bodies are all plain free spheres (Dynamics on, one acceleration
// for all: gravity or none, one radius, the seed's elastic frictionless response with each other
// and with the static models, no spin, nothing resting, overlapping or ignored) is baked by this
// compact engine instead of
// the general one. It does the same exact mathematics (the same time-of-impact and response
// functions, the same grid cells and cell-crossing times), so it finds the same events to
// rounding, but with the techniques of the fast event-driven codes (Rapaport, "The Art of
// Molecular Dynamics Simulation"; Smallenburg, Eur. Phys. J. E 45, 22 (2022)):
// - each sphere's hot data in one 64-byte record (its segment's start, velocity and start time,
//   a collision counter, the next sphere in its cell), the rest in arrays read only at events;
// - one event per sphere (its earliest pair collision, and its next move: a cell crossing or a
//   static model), made stale lazily by the partner's counter; a crossing keeps the pair part
//   and scans only the 9 cells newly in reach; the first predictions compute each pair once;
// - a scan's candidates gathered and their roots computed four at a time with AVX2 where the
//   processor has it (the same operations in the same order as one at a time), and the face of
//   its cell a sphere reaches first found without branches (face_ahead);
// - the static models' triangles listed per cell once, so a sphere far from every wall tests
//   none, and a face met inside its triangle solved directly; a box closed around every sphere
//   without gravity (each face two triangles making it whole, as the cube mesh's: the
//   benchmark's gas) known as such, so that a sphere meets only the faces it moves towards,
//   from the cells beside them, where it meets their plane;
// - a calendar queue of the event times (calendar_queue.hpp); the next event's records fetched
//   ahead; nothing allocated in the loop;
// - the arrays of a value per sphere in 2 MB pages once they are large (animator/huge_pages.hpp:
//   a page fault costs 11 us on the machines measured).
// When an event is one it does not take (a grazing contact, a sphere left touching a face
// without speed along it, a sphere leaving the grid), it stops before it, and the general engine
// goes on from there with every sphere where the lane left it (EventBake::leave_gas_lane).
#pragma once

#include "calendar_queue.hpp"
#include "time_of_impact.hpp"

#include <animator/halves.hpp>
#include <animator/huge_pages.hpp>
#include <animator/physics.h>

#include <array>
#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

namespace physics_custom {

class GasLane {
  public:
    // A sphere as the lane takes it: its model, mass, how it reports its motion (FREE, or REST
    // while it has not moved), and its segment (centre p and velocity v at t0; the acceleration
    // is every sphere's).
    struct Start {
        uint32_t model = 0;
        double mass = 1.0;
        int motion = ANI_MOTION_FREE;
        double t0 = 0.0;
        glm::dvec3 p{0.0}, v{0.0};
    };
    // A triangle of a static model (world space) and that model.
    struct Triangle {
        glm::dvec3 a{0.0}, b{0.0}, c{0.0};
        glm::dvec3 normal{0.0}; // unit (0 without area), its plane normal . x = offset
        double offset = 0.0;
        Box box;
        uint32_t model = 0;
    };
    // The general engine's grid (grid.hpp): cells of side `cell` from `origin`, `counts` per axis.
    struct Grid {
        glm::dvec3 origin{0.0};
        double cell = 1.0;
        std::array<int64_t, 3> counts{1, 1, 1};
    };
    // What the lane reports, and the bake's progress.
    class Sink {
      public:
        virtual ~Sink() = default;
        virtual void segment(const ani_motion_segment &s) = 0;
        virtual void collision(const ani_collision_event &e) = 0;
        virtual void progress(double now) = 0; // every 1024 events (it may throw to cancel)
    };
    struct Counts {
        std::size_t done = 0, skipped = 0, predictions = 0, stale = 0, crossings = 0, events = 0;
    };

    // Every sphere must start inside the grid's cells and apart from the others and the
    // triangles: the general engine's checks have run, or `check` asks the lane to see to it
    // (admissible() says whether they are; if not, the lane must not be run).
    GasLane(double radius, const glm::dvec3 &acceleration, const Grid &grid,
            std::vector<Triangle> triangles, const ani::HugeVector<Start> &spheres, double now,
            bool check = false);
    bool admissible() const { return admissible_; }

    // Runs the events up to t_end (the segments from t_begin, where this slice starts). False
    // when it stopped before an event it does not take, at stopped_at(): the general engine
    // goes on from there.
    bool run(double t_begin, double t_end, Sink &sink);
    double stopped_at() const { return stopped_at_; }
    // Reports every sphere's segment up to t_end (the end of the slice).
    void close(double t_begin, double t_end, Sink &sink);
    // A sphere now (its segment, as Start has it).
    Start state(std::size_t k) const;
    std::size_t size() const { return s_.size(); }
    double radius() const { return r_; }
    const glm::dvec3 &acceleration() const { return a_; }
    const Counts &counts() const { return counts_; }

  private:
    static constexpr uint32_t kNone = 0xffffffffu;
    static constexpr double kInf = std::numeric_limits<double>::infinity();
    // What a scan of neighbours reads of each: one cache line.
    struct alignas(64) Sphere {
        double x[3]; // centre at t0 (the start of its segment)
        double v[3];
        double t0;
        uint32_t count; // its collisions: a pair event predicted at another count is stale
        uint32_t next;  // the next sphere in its cell, or kNone
    };
    // A sphere's next event: the earlier of its earliest pair collision and its next move (a
    // cell crossing, or a static model within its cell); its cell, with that cell's triangles
    // (near_[near_from, near_to)); and its mass. One cache line, read at its events.
    struct alignas(64) Event {
        double pair_time = kInf;
        uint32_t partner = kNone, partner_count = 0;
        double move_time = kInf;
        std::array<int32_t, 3> cell{};
        uint32_t index = 0; // of its cell in head_
        uint32_t near_from = 0, near_to = 0;
        uint32_t triangle = kNone; // met at move_time, with contact_ (or kNone: a crossing)
        int8_t axis = 0, direction = 0;
        uint8_t faces = 0; // the box's faces its cell is beside (a bit each: Face)
        double mass = 1.0; // (here, not in an array of its own: read at its collisions)
    };
    static_assert(sizeof(Event) == 64);

    glm::dvec3 at(const Sphere &p, double t) const;
    glm::dvec3 velocity(const Sphere &p, double t) const;
    int64_t coordinate(double x, int a) const;
    int64_t cell_index(const std::array<int64_t, 3> &c) const;
    void place(uint32_t i, const std::array<int64_t, 3> &c); // in cell c (its Event's fields)
    template <class B> bool gather(B &batch, uint32_t k, double now) const;
    void scan(uint32_t i, double now, const int64_t *offsets, int count, bool all);
    void predict_pairs(uint32_t i, double now);
    // The spheres by the layer of cells they are in: below the middle one but one, that one
    // (between), and from the middle one up; each list in the spheres' order.
    struct Layers {
        std::vector<uint32_t> below, between, above;
    };
    void link_all(const Layers *layers);
    bool predict_all_pairs(double now, bool check, const Layers *layers); // at the start
    bool all_pairs_of(double now, bool check, std::size_t &tests, const uint32_t *ids,
                      std::size_t listed);
    // The box closed around every sphere, when the static models make one (find_box in
    // gas_lane.cpp) and nothing falls: each face (2 a for the lower along axis a, 2 a + 1 the
    // upper) is two triangles making it whole, taken out of the cells' lists and met, from the
    // cells the lists would have it in (from .. to along its axis: along the others, every cell
    // inside the box), only by a sphere moving towards it (predict_move).
    struct Face {
        uint32_t first = kNone, second = kNone; // its triangles, in the general engine's order
        int32_t from = 0, to = -1;
    };
    struct BoxFaces; // (gas_lane.cpp)
    static std::optional<BoxFaces> find_box(const std::vector<Triangle> &triangles);
    bool lay_out(const ani::HugeVector<Start> &spheres, double now, bool check, const BoxFaces *box,
                 bool two, bool by_layers, Layers &layers, bool &clear);
    bool in_grid(const Event &e) const {
        for (int a = 0; a < 3; ++a)
            if (e.cell[a] < 0 || e.cell[a] >= grid_.counts[a]) return false;
        return true;
    }
    bool boxed_ = false;
    std::array<Face, 6> faces_{};
    std::array<int, 6> face_order_{}; // by their first triangle (the lists' order)
    int facing_ = 0;                  // the faces whose plane faces the box's inside (a bit each)
    void list_triangles(); // each cell's (near_from_, near_), the box's faces left out if boxed_
    template <class F> bool any_near(const Event &e, int faces, F &&f) const;
    void predict_move(uint32_t i, double now) { predict_move(i, now, counts_.done); }
    void predict_move(uint32_t i, double now, std::size_t &done); // its tests added to done
    void predict_fall(uint32_t i, double now, const Path &here, std::size_t &done);
    void schedule(uint32_t i);
    void fetch_ahead(uint32_t k) const;
    bool left_touching(uint32_t i, const glm::dvec3 &c, const glm::dvec3 &v) const;
    bool grazing(const glm::dvec3 &relative, const glm::dvec3 &n) const;
    void restart(uint32_t i, double t, const glm::dvec3 &v, Sink &sink);
    void emit(uint32_t i, double t, Sink &sink) const;
    bool collide(uint32_t i, uint32_t j, double t, Sink &sink);
    bool bounce(uint32_t i, double t, Sink &sink);
    bool cross(uint32_t i, double now);
    void unlink(uint32_t i);
    void link(uint32_t i);

    double r_, reach2_; // the radius, and (r + r)^2
    glm::dvec3 a_;      // every sphere's acceleration (gravity, or none)
    bool falls_;        // a_ is not 0: paths are parabolas
    Grid grid_;
    std::vector<Triangle> triangles_;
    // (Per sphere: written by the constructor, in two halves, not zeroed first: huge_pages.hpp.)
    ani::UnwrittenVector<Sphere> s_;
    ani::UnwrittenVector<Event> e_;
    // Each sphere's model and how its motion is reported (FREE, or REST until it first moves):
    // read together at its events, so side by side (fetched ahead with its records).
    struct AsReported {
        uint32_t model;
        int motion;
    };
    ani::UnwrittenVector<AsReported> as_reported_;
    // The cells: a layer of empty cells around the grid's (no bounds tests); each cell's first
    // sphere, each sphere's previous one, and each cell's triangles (CSR).
    std::array<int64_t, 3> stride_{};
    ani::HugeVector<uint32_t> head_;
    ani::UnwrittenVector<uint32_t> prev_;   // (each written as its sphere is linked)
    ani::UnwrittenVector<Contact> contact_; // each sphere's with the triangle of its event, if any
    ani::HugeVector<uint32_t> near_from_; // (a value per cell: 2 MB pages, kept when freed)
    std::vector<uint32_t> near_;
    int64_t around_[27];
    int64_t beyond_[6][9]; // after a crossing along axis a, way d: the 9 new cells, at 2a + d
    CalendarQueue queue_;
    Counts counts_;
    bool admissible_ = true;
    bool clear_of(uint32_t i, const glm::dvec3 &c) const;
    double stopped_at_ = kInf;
    double t_begin_ = 0.0, t_end_ = 0.0; // the slice's
    std::size_t at_once_ = 0;
    double last_ = -kInf;
};

} // namespace physics_custom
