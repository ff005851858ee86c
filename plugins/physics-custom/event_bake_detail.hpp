// The internals of the event-driven bake (event_bake.hpp is its interface; physics.md, "Where the
// code is"): the bodies and obstacles, the predicted events, and the class EventBake, whose
// member functions are defined by stage in event_bake.cpp and bake_*.cpp. Private to the plugin.
#pragma once

#include "event_bake.hpp"

#include "event_queue.hpp"
#include "free_motion.hpp"
#include "gas_lane.hpp"
#include "grid.hpp"
#include "impulse.hpp"
#include "keyed_contact.hpp"
#include "mass_properties.hpp"
#include "material.hpp"
#include "mesh_contact.hpp"
#include "mesh_distance.hpp"
#include "overlap_memory.hpp"
#include "polynomial.hpp"
#include "response.hpp"
#include "scene_print.hpp"
#include "simultaneous_contact.hpp"
#include "spin.hpp"
#include "support_polygon.hpp"
#include "time_of_impact.hpp"
#include "turning_contact.hpp"
#include "zeno.hpp"

#include <animator/huge_pages.hpp>
#include <animator/plugin_cpp.hpp>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtx/euler_angles.hpp>
#include <glm/mat3x3.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <functional>
#include <iomanip>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <unordered_map>
#include <vector>

namespace physics_custom::bake {

constexpr double kNever = std::numeric_limits<double>::infinity();

inline glm::dvec3 vec(const ani_vec3 &v) {
    return {v.x, v.y, v.z};
}
inline ani_vec3 ani(const glm::dvec3 &v) {
    return {v.x, v.y, v.z};
}

inline const char *name_of(const ani_physics_model &m) {
    return m.desc && m.desc->name ? m.desc->name : "?";
}

// A turning model tipping over an edge it stands on, on a face of a static model, or over an edge
// of a static model its face lies across (bake_hinge.cpp): it turns about the fixed line through
// `point` along its spin's axis as the pendulum says, held there by the contact forces its motion
// needs, until a vertex lands on the face (`landing`; over an edge: a contact with the triangles
// `beyond`, if any) or those forces fail first (`ends`: the edge would lift off or slip). The
// same on a body that stands without Dynamics (a platform released from its keys), until its
// keys take it back.
struct Hinge {
    int support = -1;       // the static model (its obstacle's index), or -1
    int support_body = -1;  // or the body that stands (its index), or -1
    double support_until = kNever; // when that body may move (its keys take it back)
    glm::dvec3 point{0.0};  // the foot of its centre of mass on the line, world: still
    glm::dvec3 pivot{0.0};  // that point in the model's own frame as scaled (its segments')
    glm::dvec3 normal{0.0}; // the face's unit normal (over an edge: its own face's, at the start)
    std::vector<glm::dvec3> vertices; // its turning_vertices relative to `point`, not its centre
    double reach = 0.0;               // the farthest of them from `point`
    double landing = kNever;
    std::vector<glm::dvec3> landing_points; // world: every vertex on the face then
    double ends = kNever;
    // Over a static model's edge: that model's triangles within its reach above the top's plane
    // or beyond the edge (a step's nose, the lower steps), as corner indices of its shape's
    // triangles; their first contact with it, found as any turning model's, is its landing.
    std::vector<uint32_t> beyond;
};

// A model that takes part in collisions and moves: a sphere (Dynamics or Gravity on), or any
// model with a mesh while its keys drive it (a moving wall). Over the bake a body is keyed (its
// keys move it), free (a closed-form segment), or waiting (keyed, but with nothing to collide).
struct alignas(64) Body {
    enum class Mode { kKeyed, kFree, kCarried };
    // First, together, what the prediction of a free sphere reads of every sphere near it
    // (two cache lines: docs/performance.md, the gas).
    uint32_t model = 0;
    bool sphere = false; // the seed's sphere special case; otherwise the model's triangles
    bool active = false; // free and colliding, or keyed and colliding
    Mode mode = Mode::kFree;
    double radius = 0.0; // for a sphere: its radius when free
    double t0 = 0.0;     // start of the current free segment
    Path path;           // free: center(t) = path.at(t - t0)
    uint64_t version =
        0; // counts the changes of path: events predicted against an older one are stale
    double reach = 0.0; // the farthest a vertex is from the model's origin, in model space
    std::vector<std::array<uint32_t, 2>> edges; // not a sphere: its mesh's edges, each once
    bool dynamics = false;
    double mass = 0.0;        // its model's (kg)
    double keys_end = kNever; // when its last key passes (then it is free)
    double resume_at =
        kNever;              // released from its keys at a contact: the next key, where they resume
    double keyed_from = 0.0; // start of the current keyed stretch (to report it)
    int motion = ANI_MOTION_FREE;
    bool in_grid = false; // free spheres only
    Cell cell{};
    int ignored_obstacles = 0;    // obstacles it overlapped and does not collide with until apart
    int overlapped_obstacles = 0; // obstacles it overlapped and touches at that depth until apart
    glm::dvec3 free_a{0.0};       // its acceleration when nothing holds it up (gravity, or none)
    // Resting or sliding on a flat part of a static model: that model, the plane of the face
    // (n . x = d), and the boundary of the flat region it is on (edge start, end, and outward
    // normal in the plane), where it leaves the support.
    int support = -1;
    glm::dvec3 support_n{0.0};
    // A model that is not a sphere, free after its last key: its triangles, turned and scaled as
    // its last key left them, relative to its center (the seed's mesh-mesh tests).
    std::shared_ptr<const MeshShape> shape;
    double support_d = 0.0;
    // While on its support: the deceleration of Coulomb friction there, mu g_n (m/s^2), and,
    // while its velocity turns (sliding across a slope), when friction is aimed again.
    double rub = 0.0;
    double reaim_at = kNever;
    bool rolling = false; // a ball on its support whose touching point does not slip
    // Asleep on another body that rests (a box on a box of a stack): that body. It is still
    // until that body moves (bake_rest.cpp, "resting on other models").
    int on_body = -1;
    // Resting or sliding on a face of another body that translates at a constant velocity (a
    // keyed platform, between two of its keys; bake_carrier.cpp): that body (support stays -1),
    // its version then, and until when it keeps that velocity. support_v is the velocity of
    // the support (0 for a static model); support_edges are where they were at support_t.
    int carrier = -1;
    uint64_t carrier_version = 0;
    double carrier_until = kNever;
    glm::dvec3 support_v{0.0};
    double support_t = 0.0;
    std::vector<std::array<glm::dvec3, 3>> support_edges;
    // Mode::kCarried: sticking to a keyed body whose keys accelerate it (bake_carrier.cpp,
    // "sticking"): that body (its version then in carrier_version), from when, until when (its
    // next key), its origin's offset from the carrier's (world axes: the carrier does not turn
    // meanwhile) and its placement then (rotation and scale). Whether it turned before (its spin
    // starts again when it is dropped).
    int carried_by = -1;
    double carried_from = 0.0, carried_until = kNever;
    glm::dvec3 carried_offset{0.0};
    glm::dmat3 carried_linear{1.0};
    bool carried_spin = false;
    // Where it touches the support, relative to its center: a sphere's lowest point, or the
    // vertices of a mesh in the support's plane. It leaves the support when all have left it.
    std::vector<glm::dvec3> support_feet;
    double grazed_until = -kNever; // not a sphere: when the obstacles it grazed count again
    Material material;             // restitution, friction, turning (issue 18)
    Spin spin;                  // a free sphere that rotates: its orientation and angular velocity
    double settles_at = kNever; // put on its support by the Zeno rule: the accumulation time
    // A model that is not a sphere and turns from its contacts once free (Rotates on;
    // check_turning): its vertices scaled as its keys leave it, relative to its centre of mass,
    // the farthest of them, its inertia (a
    // spherical top's inverse moment, such as a cube's, or the principal moments and axes of
    // any other, such as a box's), and its keys' scale, which its turn (spin) is applied after.
    bool turns = false;
    std::vector<glm::dvec3> turning_vertices;
    double turning_reach = 0.0;
    double inv_inertia = 0.0; // a spherical top's; the others': spin.moments and spin.principal
    glm::dvec3 moments{0.0};  // principal moments when they differ (a box), else 0
    glm::dquat principal{1.0, 0.0, 0.0, 0.0}; // its principal axes in its own frame
    // Its centre of mass in its own frame as scaled, which it turns about (0: its origin); while
    // it turns, `path` is that point's and its vertices are relative to it.
    glm::dvec3 pivot{0.0};
    glm::dmat3 scale{1.0};
    // Tipping over an edge (bake_hinge.cpp): while set, `path` is its hinge point's (still) and
    // its spin the hinge's.
    std::shared_ptr<const Hinge> hinge;

    bool keyed() const { return mode == Mode::kKeyed; }
    bool carried() const { return mode == Mode::kCarried; }
    // Moved by keys, its own or its carrier's, not by a closed form of its own.
    bool driven() const { return mode != Mode::kFree; }
    // Held up by a face: of a static model, or of a carrier.
    bool supported() const { return support >= 0 || carrier >= 0; }
    bool free_sphere() const { return sphere && mode == Mode::kFree; }
    // Turning from its contacts now (free after its last key): its pose is its spin's.
    bool turning() const { return turns && spin.on; }
    bool still() const {
        return mode == Mode::kFree &&
               (motion == ANI_MOTION_REST ||
                (path.v == glm::dvec3(0.0) && path.a == glm::dvec3(0.0))) &&
               (!turning() || spin.w == glm::dvec3(0.0)) && !hinge;
    }
    // The farthest any of its vertices is from the point its path follows.
    double turning_reach_now() const { return hinge ? hinge->reach : turning_reach; }
};

// The triangles of a static model, in world space, with their bounding sphere.
struct Obstacle {
    uint32_t model = 0;
    std::vector<glm::dvec3> corners;        // 3 per triangle
    std::vector<Box> boxes;                 // 1 per triangle
    std::vector<glm::dvec3> normals;        // 1 per triangle, unit (0 for a triangle without area)
    std::vector<double> offsets;            // 1 per triangle: its plane is normal . x = offset
    std::shared_ptr<const MeshShape> shape; // in world space, for the mesh-mesh tests
    // A closed mesh turned inside out: a room, for the models inside it (built when needed).
    mutable std::shared_ptr<const MeshShape> room;
    glm::dvec3 center{0.0};
    double radius = 0.0;
};

// Where a body is and how it is placed at one time: world = center + linear * model-space point.
struct Pose {
    glm::dvec3 center{0.0}, velocity{0.0};
    glm::dmat3 linear{1.0};
};

// A body's earliest predicted event.
enum class EventKind {
    kNone,
    kActivation,
    kResume,
    kBody,
    kObstacle,
    kCell,
    kRelease,
    kRecheck,
    kLeave,
    kSettle,
    kFriction, // sliding on its support: it stops, or its friction is aimed again
    kHinge,    // tipping over an edge, the contact forces it needs fail: it turns freely
    kCarrier   // the body it rides changes its velocity (its next key): friction against that;
               // or the span it is carried over ends
};
struct Predicted {
    double t = kNever;
    EventKind kind = EventKind::kNone;
    int other = -1;             // the other body, or the obstacle
    uint64_t other_version = 0; // the other body's version when predicted
    Contact contact;
    std::vector<glm::dvec3> points; // a turning model's: every point touching with the contact
    bool moving_in = false; // kBody: found moving into each other (a turning model's), it responds
    Exit exit;              // for kCell
};

inline Predicted predicted(double t, EventKind kind, int other = -1, uint64_t other_version = 0,
                           const Contact &contact = {}) {
    Predicted p;
    p.t = t;
    p.kind = kind;
    p.other = other;
    p.other_version = other_version;
    p.contact = contact;
    return p;
}

// How near (times its size) the plane of a face a turning model's vertex stands on it: its feet
// for the balance check (settle_on) and for the edge it tips over (try_hinge).
constexpr double kTipSlack = 1e-6;

// Bodies from which on the grid pays for its cell crossings.
constexpr std::size_t kGridFrom = 16;

inline glm::dmat3 linear_part(const ani_model_state &s) {
    return glm::dmat3(glm::eulerAngleXYZ(glm::radians(s.angles.x), glm::radians(s.angles.y),
                                         glm::radians(s.angles.z))) *
           glm::dmat3(glm::scale(glm::dmat4(1.0), vec(s.scale)));
}

inline bool uniform(const ani_vec3 &s) {
    return s.x == s.y && s.y == s.z && s.x > 0.0;
}

inline ani_model_state keyed_state(const ani_physics_scene &scene, uint32_t m, double t,
                                   glm::dvec3 *velocity) {
    ani_model_state state{};
    ani_vec3 v{};
    if (scene.evaluate_keyed(scene.host_context, m, t, &state, &v) != ANI_OK)
        throw ani::Failure(ANI_ERR_FAILED, std::string("cannot evaluate the keys of model '") +
                                               name_of(scene.models[m]) + "'");
    if (velocity) *velocity = vec(v);
    return state;
}

inline double frobenius(const glm::dmat3 &m) {
    double sum = 0.0;
    for (int c = 0; c < 3; ++c) sum += glm::dot(m[c], m[c]);
    return std::sqrt(sum);
}

class EventBake {
  public:
    // The event loop (event_bake.cpp).
    EventBake(const ani_physics_scene &scene, double t_begin, double t_end,
              const ani_bake_sink &sink, const ani_host *host, const BakeOptions &options,
              OverlapMemory &memory);
    void run();
    bool continues(const ani_physics_scene &scene, double t_begin,
                   const BakeOptions &options) const;
    void resume(const ani_physics_scene &scene, double t_end, const ani_bake_sink &sink);

  private:
    // The types the stages share. An overlap found (bake_overlaps.cpp): the contact there (the
    // normal from the other towards the body) and how deep they are into each other along it.
    struct Seen {
        Contact contact;
        double depth = 0.0;
    };
    // A model's mesh scaled as its keys leave it at t, as a uniform solid of its mass.
    struct TurningShape {
        std::vector<glm::dvec3> vertices;
        MassProperties mass;
        double reach = 0.0;
        glm::dmat3 scale{1.0};
        glm::dvec3 pivot{0.0}; // its centre of mass, when not its origin
    };

    // The event loop, continued (event_bake.cpp).
    void set_horizon();
    void advance_to_end();
    void handle(int i, const Predicted &event, double now);
    void report(const ani_collision_event &e);
    void report_counts();
    void log_warning(const std::string &message);

    // Bodies, their poses, mass properties and turning; the reported segments (bake_bodies.cpp).
    void classify();
    // How model i stands at the slice's start: its keyed span, whether its keys have ended, whether
    // it can move (Dynamics or Gravity) and whether it collides (a mesh with triangles, not a
    // part of a jointed model).
    struct Standing {
        ani_time_span span;
        bool free_now, movable, solid;
    };
    Standing standing(uint32_t i) const;
    // Each mesh's reach (mesh_reach), measured once for the models that share it (a gas's balls).
    using Reaches = std::unordered_map<const ani_mesh_view *, double>;
    Body body_of(uint32_t i, const std::optional<double> &radius, double keys_end,
                 Reaches &reaches) const;
    void emit_unmoved(uint32_t i);
    bool keys_hold_still(uint32_t i, double last) const;
    ani_body_state start_of(uint32_t i, double t);
    double next_key(uint32_t i, double t) const;
    std::optional<double> sphere_radius(uint32_t i, double t);
    void add_obstacle(uint32_t i, double t);
    static void finish_obstacle(Obstacle &o);
    std::shared_ptr<const MeshShape> build_shape(uint32_t i, const ani_vec3 &center,
                                                 const glm::dmat3 &linear,
                                                 const glm::dvec3 &origin) const;
    void activate(Body &b, double t, const ani_body_state &start);
    static void stop(Body &b);
    ani_body_state leaving_keys(uint32_t i, double t);
    void emit(const ani_motion_segment &s);
    void emit_keyed(uint32_t i, double t0, double t1);
    void emit_free(uint32_t i, const ani_body_state &start, double free_at);
    void close_segment(Body &b, double t);
    void restart(Body &b, double t, const glm::dvec3 &velocity, bool stop);
    // The path of a free body from `now`, for time-of-impact queries over [0, t_end - now].
    static Path from_now(const Body &b, double now) {
        return Path{b.path.at(now - b.t0), b.path.velocity(now - b.t0), b.path.a};
    }
    Pose pose(const Body &b, double t) const;
    const ani_mesh_view &mesh_of(const Body &b) const;
    glm::dvec3 vertex(const ani_mesh_view &mesh, uint32_t k) const;
    PlacedMesh placed(const Body &b, const Pose &p) const;
    static PlacedMesh placed(const Obstacle &o);
    static double mesh_reach(const ani_mesh_view &mesh);
    static glm::dvec3 acceleration(const Body &b);
    double body_size(const Body &b) const;
    std::vector<glm::dvec3> placed_vertices(const Body &b, double t) const;
    void start_spin(Body &b, double t);
    void turn(Body &b, double t, const glm::dvec3 &w);
    void emit_spin(const Body &b, double t);
    void rebase(Body &b, double t);
    void restart_spin(Body &b, double t);
    std::optional<TurningShape> check_turning(uint32_t i, bool sphere, double t);
    // Tipping over an edge (bake_hinge.cpp). What a hinge turns on: the triangles of a static model
    // (its obstacle's index in `obstacle`), or of a body that stands without Dynamics placed as
    // an obstacle's (its index in `body`; it stands until `until`).
    struct HingeSupport {
        const Obstacle *triangles = nullptr;
        int obstacle = -1, body = -1;
        double until = kNever;
    };
    bool try_hinge(int i, const HingeSupport &on, const glm::dvec3 &n, const glm::dvec3 &v,
                   const glm::dvec3 &w, double t);
    bool try_hinge_over_edge(int i, const HingeSupport &on, const std::vector<glm::dvec3> &points,
                             const glm::dvec3 &v, const glm::dvec3 &w, double t);
    bool try_hinge_on_body(int i, int j, const glm::dvec3 &n, const std::vector<glm::dvec3> &points,
                           const glm::dvec3 &v, const glm::dvec3 &w, double t);
    std::shared_ptr<const ani::Pendulum>
    hinge_pendulum(const Body &b, const Obstacle &ob, const glm::dvec3 &u, const glm::dvec3 &r0,
                   const glm::dvec3 &n, const glm::dvec3 &v, const glm::dvec3 &w, double t,
                   double &psi0, double &mu) const;
    static double first_failure(const std::function<bool(double)> &holds, double t, double until);
    static std::shared_ptr<Hinge> new_hinge(const Body &b, const HingeSupport &on,
                                            const glm::dvec3 &P, const glm::dvec3 &n,
                                            const glm::dmat3 &R, const glm::dvec3 &c);
    static bool edge_holds(const ani::Pendulum &pendulum, double time, const glm::dvec3 &u,
                           const glm::dvec3 &r0, double psi0, const glm::dvec3 &n0,
                           bool normal_turns, double m, const glm::dvec3 &g, double mu);
    void begin_hinge(Body &b, double t, const glm::dquat &q, const glm::dvec3 &u,
                     std::shared_ptr<const ani::Pendulum> pendulum, std::shared_ptr<Hinge> h);
    void unhinge(Body &b, double t);
    void predict_hinge(const Body &b, double now, Predicted &next) const;
    bool on_flat_region(const Obstacle &o, const glm::dvec3 &n, double d,
                        const glm::dvec3 &x) const;
    TurningShape turning_shape(uint32_t i, double t) const;
    void set_turning(Body &b, TurningShape shape);

    // The broad phase (bake_broad_phase.cpp; for_candidates, a template, below the class).
    void build_broad_phase();
    std::unique_ptr<UniformGrid> grid_over(Box region, double widest) const;
    void file(int i, double t);
    void unfile(int i);
    template <class F> void for_candidates(int i, F &&f) const;

    // Time of impact: gaps, advancement, predictions (bake_prediction.cpp).
    glm::dvec3 nearest_on_mesh(const Body &b, const Pose &p, const glm::dvec3 &q) const;
    glm::dvec3 nearest_on_obstacle(const Obstacle &o, const glm::dvec3 &q) const;
    double point_speed(const Body &b, double t, double dt) const;
    glm::dvec3 point_velocity(const Body &b, const glm::dvec3 &point, double t) const;
    double gap_between(const Body &a, const Body &b, double t, Contact *contact = nullptr) const;
    double mesh_gap(const Body &a, const Body &b, double t, Contact *contact) const;
    static void fill_contact(const glm::dvec3 &on_a, const glm::dvec3 &on_b, const glm::dvec3 &n,
                             double t, Contact *contact);
    double gap_to_obstacle(const Body &b, const Obstacle &o, double t,
                           Contact *contact = nullptr) const;
    double radius_at(const Body &b, const Pose &p) const;
    bool within_obstacle(const Body &b, const Obstacle &o, double t, double gap) const;
    bool within_body(const Body &a, const Body &b, double t, double gap) const;
    bool overlaps_obstacle(const Body &b, const Obstacle &o, double t) const;
    bool overlaps_body(const Body &a, const Body &b, double t) const;
    bool apart_from_obstacle(const Body &b, const Obstacle &o, double t) const;
    bool apart_from_body(const Body &a, const Body &b, double t) const;
    static bool grazing(const glm::dvec3 &relative_velocity, const glm::dvec3 &n);
    static double touching(const Body &b);
    static double tolerance(const Body &b);
    void predict(int i, double now);
    void predict_release(int i, int j, double now, double &limit, Predicted &next);
    std::optional<Contact> advance(int i, int j, int obstacle, double now, double limit);
    bool sphere_and_translating(int i, int j, double now, double &limit, Predicted &next,
                                std::optional<Contact> &contact);
    void predict_obstacles(int i, double now, double limit, Predicted &next);
    std::optional<Contact> mesh_pair(const MeshShape &a, const Path &pa, const MeshShape &b,
                                     const Path &pb, double limit);
    void predict_mesh_obstacles(int i, double now, double limit, Predicted &next);
    const MeshShape &shape_facing(const Obstacle &o, const glm::dvec3 &p) const;
    static bool inside(const Obstacle &o, const glm::dvec3 &p);
    void recheck_obstacles(int i, double now, Predicted &next);
    double recheck_after(const Body &b, double now) const;
    void set_prediction(int i, const Predicted &p);
    TurningPath turning_path(const Body &b, double now) const;
    TurningMesh turning_mesh(const Body &b) const;
    void predict_turning_obstacle(int i, size_t o, double now, double limit, Predicted &next,
                                  const std::vector<uint32_t> *only = nullptr);
    std::optional<TurningContact>
    contact_moving_in(const Body &b, const TurningMesh &mb, const TurningPath &pb, const Body *o,
                      const TurningMesh &mo, const TurningPath &po, double now, double window,
                      const std::function<void(TurningContact &)> &orient);
    // A body as turning_contact.hpp sees it from `now`: its mesh about the point its path
    // follows, that path and its turn, the farthest its points are from that point, and for how
    // long (from now) this holds (kNever: until its path changes).
    struct TurningView {
        std::vector<glm::dvec3> vertices; // one that does not turn: its points as its keys hold it
        TurningMesh mesh;
        TurningPath path;
        double reach = 0.0;
        double holds = kNever;
    };
    bool turning_view(int i, double now, TurningView &view) const;
    bool keys_hold_pose(uint32_t model, double t, double end) const;
    std::optional<Contact> predict_turning_pair(int i, int j, const TurningView &vb,
                                                const TurningView &vo, double now, double limit,
                                                std::vector<glm::dvec3> &points);
    // predict_turning_pair, or its answer for the same pair from the other side at the same time
    // (handle() predicts both bodies of a contact), when neither view has changed since.
    struct PairMemo {
        int i = -1, j = -1;
        double now = 0.0, limit = 0.0;
        std::vector<glm::dvec3> vertices_i, vertices_j; // the views' vertices, as they were
        TurningView view_i, view_j;                     // their meshes point at nothing kept
        std::optional<Contact> contact;                 // the normal from j towards i
        std::vector<glm::dvec3> points;
    };
    std::optional<Contact> turning_pair_once(int i, int j, const TurningView &vb,
                                             const TurningView &vo, double now, double limit,
                                             std::vector<glm::dvec3> &points);
    static bool same_view(const TurningView &view, const TurningView &kept,
                          const std::vector<glm::dvec3> &kept_vertices);
    static void outward(TurningContact &c, const TurningPath &path);
    bool approaching(const Body &b, const TurningContact &c, double now,
                     const Body *other = nullptr) const;

    // The gas lane: a scene of plain free spheres baked by the compact engine (bake_gas.cpp).
    class GasSink;
    bool gas_from_scene();
    std::vector<GasLane::Triangle> lane_triangles() const;
    bool enter_gas_lane();
    bool run_gas_lane();
    void leave_gas_lane(double t);
    void fold_gas_counts();

    // Pairs that overlap when they start to collide (bake_overlaps.cpp).
    void find_overlaps(int i, double t);
    std::optional<Seen> overlap_with_obstacle(const Body &b, const Obstacle &o, double t) const;
    void meet_overlap(int i, int other, const Seen &seen, double t);
    void treat_as_touching(int i, int other, const OverlapRecord &record);
    void report_overlap(int i, int other, double t, double depth, const glm::dvec3 &normal);
    static std::string short_number(double x);
    uint32_t model_of(int other) const;
    bool is_overlapped(int a, int b) const;
    const OverlapRecord *overlap_of(int a, int b) const;
    double radius_against(int i, int o) const;
    glm::dvec3 shift_against(int i, int o) const;
    void radii_against(int i, int j, double &ri, double &rj) const;
    bool apart_after_overlap(int i, int o, double t) const;
    void unoverlap(int i, int other, double t);
    static std::pair<int, int> pair_key(int a, int b);
    void ignore(int i, int other, double t);
    void unignore(int i, int other, double t);
    void forget_ignored(int i, double t);
    bool is_ignored(int a, int b) const;

    // The response to a contact (bake_response.cpp).
    void release(int i, double t);
    void collide_obstacle(int i, const Obstacle &o, const Contact &contact,
                          const std::vector<glm::dvec3> &points, double t);
    void collide_bodies(int i, int j, const Contact &contact, const std::vector<glm::dvec3> &points,
                        double t);
    static ani_collision_event collision_event(uint32_t a, uint32_t b, const Contact &contact,
                                               double t, const glm::dvec3 &closing);
    bool sphere_responds(const Body &b, uint32_t other) const;
    static ImpulseBody sphere_body(const Body &b, double mass, const glm::dvec3 &v,
                                   const glm::dvec3 &n, double t);
    bool respond_to_obstacle(int i, const Obstacle &o, const glm::dvec3 &n, const glm::dvec3 &v,
                             double t);
    void respond_to_wall(Body &b, const glm::dvec3 &v, const glm::dvec3 &v_wall,
                         const glm::dvec3 &n, const Material &wall, double t);
    void respond_to_sphere(Body &b, const glm::dvec3 &v, Body &o, const glm::dvec3 &vo,
                           const glm::dvec3 &n, double t);
    bool mesh_responds(const Body &b, uint32_t other) const;
    bool settle_after_bounces(int i, const Obstacle &o, const glm::dvec3 &n, double t);
    std::vector<glm::dvec3> contact_offsets(const Body &b, const std::vector<glm::dvec3> &points,
                                            double t) const;
    ImpulseBody impulse_body(const Body &b, const glm::dvec3 &point, double t) const;
    double collision_mass(const Body &b) const;
    ImpulseResult turning_impulse_on_still(const Body &b, const Contact &contact,
                                           const std::vector<glm::dvec3> &points, double e,
                                           double mu, double t, ImpulseBody &a) const;
    double microcollision_speed(const Body &b, double g_n, double t) const;
    bool respond_turning_to_obstacle(int i, const Obstacle &o, const Contact &contact,
                                     const std::vector<glm::dvec3> &points, double t);
    void respond_turning_to_held(int i, int j, const Contact &contact,
                                 const std::vector<glm::dvec3> &points, double t);
    void respond_turning_pair(Body &b, const ImpulseBody &ib, bool b_wall, Body &o,
                              const ImpulseBody &io, bool o_wall, const glm::dvec3 &n, double t);

    // The rest manager: supports, settling, leaving (bake_rest.cpp).
    static bool in_plane(const Obstacle &o, size_t k, const glm::dvec3 &n, double d);
    static bool in_support_plane(const Body &b, const Obstacle &o, size_t k);
    bool try_settle(int i, double t);
    bool settle_on(int i, int o, const glm::dvec3 &n, double t);
    // What holds a body up when it settles: a static model (`obstacle`), or a carrier moving at
    // `velocity` until `until`.
    struct Holder {
        int obstacle = -1, carrier = -1;
        glm::dvec3 velocity{0.0};
        double until = kNever;
    };
    bool settle_on_face(int i, const Obstacle &ob, const Holder &holder, const glm::dvec3 &n,
                        double t);
    bool settle_sphere_on(int i, const Obstacle &ob, const Holder &holder, double r, double t);
    void held_by(Body &held, const Holder &holder, double t) const;
    void put_on(int i, Body held, const Obstacle &ob, const glm::dvec3 &n, double t);
    static std::vector<std::array<glm::dvec3, 3>> support_boundary(const Obstacle &o,
                                                                   const Body &b);
    std::optional<double> leaves_support(const Body &b, double now, double limit) const;
    void predict_leave(int i, double now, double limit, Predicted &next);
    void unsupport(Body &b, double t);
    void after_contact(int i, double t);
    bool try_settle_mesh(int i, double t);
    std::vector<glm::dvec3> standing_faces(int i, const Obstacle &ob, const glm::dvec3 &v_other,
                                           double t) const;
    static std::optional<glm::dvec3> standing_point(const std::vector<glm::dvec3> &points,
                                                    const glm::dvec3 &p0, const glm::dvec3 &p1,
                                                    const glm::dvec3 &p2, const glm::dvec3 &n,
                                                    double d, double slack);
    void hold_on(Body &b, const Material &support, const glm::dvec3 &n);
    void aim_friction(Body &b, bool rolls = false);
    void predict_friction(int i, double now, double &limit, Predicted &next) const;
    void friction_changes(Body &b, double now, bool stops);
    static bool resting(const Body &b) { return b.still() && (b.support >= 0 || b.on_body >= 0); }
    // Nothing moves it while it stays still: it rests, or it has no Dynamics and stands (a
    // platform a contact released from its keys, until they take it back). A turning body can
    // sleep on it.
    static bool immovable(const Body &b) {
        return resting(b) || (!b.dynamics && b.still() && !b.turning());
    }
    // A resting body that an impulse along `push` (unit) presses into what it rests on, within
    // the friction cone of that support: its support takes the blow (bake_rest.cpp).
    bool held_by_support(const Body &b, const glm::dvec3 &push) const;
    bool sleep_on_body(int x, int y, const glm::dvec3 &n, const glm::dvec3 &point, double t);
    bool balanced_on(const Body &b, const Body &y, const glm::dvec3 &n, const glm::dvec3 &point,
                     double t) const;
    void wake_riders(int j, double t);
    void settle_stacks(double t);

    // Riding a body that translates at a constant velocity: a keyed platform (bake_carrier.cpp).
    struct Carried {
        glm::dvec3 velocity{0.0};
        double until = kNever;
    };
    std::optional<Carried> carried_motion(int j, double t) const;
    Obstacle face_of(const Body &b, double t) const;
    bool try_ride(int i, double t);
    bool ride_on(int i, const Obstacle &ob, const Holder &holder, double t);
    static bool carries_along(const glm::dvec3 &u, const glm::dvec3 &n);
    bool let_go(int j, int i, double t);
    bool settle_on_carrier(int x, int y, const glm::dvec3 &n, double t);
    void recarry(int i, double t);
    void carry_on(int j, double t);
    bool carries(int i, int j) const {
        const Body &a = bodies_[static_cast<size_t>(i)], &b = bodies_[static_cast<size_t>(j)];
        return a.carrier == j || b.carrier == i || a.carried_by == j || b.carried_by == i;
    }
    // Sticking to a keyed platform that accelerates (bake_carrier.cpp).
    bool stick(int i, int j, const glm::dvec3 &n, double t);
    bool sticks(const Body &b, int j, const glm::dvec3 &n, double t, double end) const;
    void emit_carried(const Body &b, double t);
    void drop(int i, double t);
    void carry_again(int i, double t);

    // The keys' state of model m at t (keyed_state), remembered for the last time asked: a bake's
    // setup asks for each model's state where the bake starts several times over (its radius, its
    // start, its fingerprint), and each answer goes through the host and its interpolation
    // plugin (docs/performance.md, the gas's setup).
    ani_model_state keyed(uint32_t m, double t, glm::dvec3 *velocity) const;
    struct KeyedMemo {
        double t = std::numeric_limits<double>::quiet_NaN(); // none yet
        ani_model_state state{};
        glm::dvec3 velocity{0.0};
    };
    // Per model, for scene_: a memo is kept where keyed_known_ says so (forget_keyed: the memos
    // themselves, 12 MB at 100,000 models, are not rewritten for each bake, only the flags).
    mutable ani::UnwrittenVector<KeyedMemo> keyed_memo_;
    mutable std::vector<uint8_t> keyed_known_;
    void forget_keyed() {
        keyed_memo_.resize(scene_->model_count);
        keyed_known_.assign(scene_->model_count, 0);
    }

    // The data, shared by every stage.
    const ani_physics_scene *scene_; // this call's (the host builds it anew for each)
    double t_begin_, t_end_;
    const ani_bake_sink *sink_;
    const ani_host *host_;
    BakeOptions options_;
    glm::dvec3 gravity_;
    std::vector<Body> bodies_;
    std::vector<int> mesh_bodies_; // the bodies that are not spheres (what can carry a model)
    // Every model's, by model index (read once, in classify).
    ani::UnwrittenVector<Material> materials_;
    std::vector<Obstacle> obstacles_;
    std::size_t triangle_count_ = 0;
    std::unique_ptr<UniformGrid> grid_; // with many bodies
    std::vector<int> outside_;          // active bodies not in the grid (all of them without one)
    std::unique_ptr<EventQueue> queue_;
    std::unique_ptr<GasLane> gas_; // while the gas lane bakes every body (bake_gas.cpp)
    GasLane::Counts gas_counted_;  // its counts already in count_
    std::vector<Predicted> predicted_; // each body's earliest event
    // Pairs left alone until they are apart: overlapping keyed models, grazing contacts. Keys:
    // (body, other body) with the lower first, or (body, -1 - obstacle).
    std::set<std::pair<int, int>> ignored_;
    // Pairs that overlapped and touch at that depth until apart (physics.md), same keys.
    std::map<std::pair<int, int>, OverlapRecord> overlaps_;
    std::set<std::pair<int, int>> reported_; // overlaps said in this slice
    OverlapMemory &memory_;                  // overlaps found by the earlier slices of the bake
    struct {
        std::size_t done = 0, skipped = 0, predictions = 0, stale = 0, crossings = 0,
                    collisions = 0, advancements = 0, releases = 0, mesh_tests = 0, hinges = 0,
                    reused = 0, scanned = 0, lane = 0, handoffs = 0;
    } count_;
    // The turning pairs predicted at the latest time, by (lower index, higher index).
    std::map<std::pair<int, int>, PairMemo> pair_memos_;
    std::size_t reports_ = 0;
    std::size_t sleepers_ = 0;         // bodies asleep on others
    std::size_t riders_ = 0;           // bodies on carriers, or carried
    std::array<double, 14> counted_{}; // the counts reported by the earlier slices
    std::vector<bool> is_body_;        // per model: a body (the others are reported each slice)
    double horizon_ = 0.0;             // how far predictions look
    ScenePrint fingerprint_;           // the scene the bake goes on with
    std::optional<ScenePrinter> printing_; // its print while it is being made (run())
    void finish_print();
};

// Calls f(j) for every active body that body i could meet: its grid neighbours and the
// bodies outside the grid, or every body when i itself is outside.
// (f only reads: the grid does not change meanwhile.)
template <class F> void EventBake::for_candidates(int i, F &&f) const {
    const Body &b = bodies_[static_cast<size_t>(i)];
    if (b.in_grid) {
        // The neighbours are gathered first, and the first two cache lines of each one's record
        // (what a free sphere's prediction reads) fetched ahead, so that waiting for memory
        // overlaps instead of following one record after another (the 10,000-ball gas spent
        // most of its predictions waiting; docs/performance.md). Same order as the grid's.
        std::array<int, 64> batch;
        std::size_t n = 0;
        auto flush = [&] {
            for (std::size_t k = 0; k < n; ++k) f(batch[k]);
            n = 0;
        };
        grid_->for_neighbours(b.cell, [&](uint32_t j) {
            if (static_cast<int>(j) == i) return;
            const char *record = reinterpret_cast<const char *>(&bodies_[j]);
            __builtin_prefetch(record);
            __builtin_prefetch(record + 64);
            batch[n++] = static_cast<int>(j);
            if (n == batch.size()) flush();
        });
        flush();
        for (int j : outside_)
            if (j != i) f(j);
    } else {
        for (size_t j = 0; j < bodies_.size(); ++j)
            if (static_cast<int>(j) != i && bodies_[j].active) f(static_cast<int>(j));
    }
}

} // namespace physics_custom::bake
