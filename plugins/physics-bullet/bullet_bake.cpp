#include "bullet_bake.hpp"

#include "../physics-custom/scene_print.hpp" // physics.custom's, shared
#include "material.hpp"
#include "shapes.hpp"
#include "track.hpp"

#include <animator/plugin_cpp.hpp>

#include <BulletCollision/Gimpact/btGImpactCollisionAlgorithm.h>
#include <btBulletDynamicsCommon.h>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtx/euler_angles.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <deque>
#include <iomanip>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace physics_bullet {

namespace {

constexpr double kNever = std::numeric_limits<double>::infinity();
constexpr char kPluginId[] = "physics.bullet";

glm::dvec3 vec(const ani_vec3 &v) {
    return {v.x, v.y, v.z};
}
glm::dvec3 vec(const btVector3 &v) {
    return {v.x(), v.y(), v.z()};
}
ani_vec3 ani(const glm::dvec3 &v) {
    return {v.x, v.y, v.z};
}
btVector3 bt(const glm::dvec3 &v) {
    return {v.x, v.y, v.z};
}
btQuaternion bt(const glm::dquat &q) {
    return {q.x, q.y, q.z, q.w};
}
glm::dquat quat(const btQuaternion &q) {
    return {q.w(), q.x(), q.y(), q.z()};
}
bool finite(const glm::dvec3 &v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}
bool finite(const ani_vec3 &v) {
    return finite(vec(v));
}

// A model's orientation from its keyed angles: R = Rx Ry Rz (the documents' convention).
glm::dquat orientation(const ani_model_state &s) {
    const glm::dmat4 m = glm::eulerAngleXYZ(glm::radians(s.angles.x), glm::radians(s.angles.y),
                                            glm::radians(s.angles.z));
    return glm::normalize(glm::quat_cast(glm::dmat3(m)));
}

btTransform transform(const glm::dvec3 &center, const glm::dquat &q) {
    return btTransform(bt(q), bt(center));
}

const char *name_of(const ani_physics_model &m) {
    return m.desc && m.desc->name ? m.desc->name : "?";
}

bool uniform(const glm::dvec3 &s) {
    return s.x == s.y && s.y == s.z && s.x > 0.0;
}

// How a body moves now: its keys drive it (kinematic), Bullet does (dynamic), or the closed form
// of a model without Dynamics: falling (kinematic) or resting (kinematic).
enum class Mode { kKeyed, kDynamic, kFalling, kRest };

struct Body {
    uint32_t model = 0;
    bool dynamics = false, gravity = false;
    double mass = 1.0;
    Mode mode = Mode::kRest;
    std::unique_ptr<Shape> shape;
    std::unique_ptr<btRigidBody> rb;
    std::unique_ptr<Track> track;
    std::unique_ptr<RotationTrack> rotation; // only when Bullet turns it
    bool gyroscopic = false;                 // turned, with moments that differ (start_dynamic)
    bool turns = false;                      // Rotates and Dynamics: Bullet turns it
    glm::dvec3 pivot{0.0};                   // its centre of mass when not its origin (pivot_of)
    glm::dvec3 a{0.0};                       // its acceleration when free (gravity or none)
    double keyed_from = 0.0;                 // start of the current keyed span
    double keys_end = 0.0;                   // where its keyed span ends: free from there
    double resume_at = kNever;               // released from its keys at a contact: its next key
    double last_key = 0.0;                   // its keys turn and scale it until then
    bool kinematic = true;                   // as Bullet knows it now
    bool fixed_orientation = false; // past its last key: the orientation its keys left it in
    glm::dquat orientation{1.0, 0.0, 0.0, 0.0};
    // Over the current step: the kinematic velocity (linear, angular), and the state before it.
    glm::dvec3 kin_v{0.0}, kin_w{0.0}, pre_x{0.0}, pre_v{0.0}, pre_w{0.0};
};

struct Obstacle {
    uint32_t model = 0;
    std::unique_ptr<Shape> shape;
    std::unique_ptr<btRigidBody> rb;
};

class Bake;

bool same_options(const BakeOptions &a, const BakeOptions &b) {
    return a.step == b.step && a.solver_iterations == b.solver_iterations && a.ccd == b.ccd &&
           a.rotate_on_contact == b.rotate_on_contact && a.friction == b.friction &&
           a.restitution == b.restitution && a.margin == b.margin;
}

// Dispatches like Bullet's, then lets the bake drop the contacts of pairs it ignores.
class Dispatcher : public btCollisionDispatcher {
  public:
    Dispatcher(btCollisionConfiguration *config, Bake *owner)
        : btCollisionDispatcher(config), bake(owner) {}
    Bake *bake;
};

// Pairs that never collide: two static models, parts of one jointed model.
class Filter : public btOverlapFilterCallback {
  public:
    explicit Filter(const std::vector<uint32_t> *groups) : groups_(groups) {}
    bool needBroadphaseCollision(btBroadphaseProxy *p0, btBroadphaseProxy *p1) const override {
        return may_collide(static_cast<const btCollisionObject *>(p0->m_clientObject),
                           static_cast<const btCollisionObject *>(p1->m_clientObject));
    }
    bool may_collide(const btCollisionObject *a, const btCollisionObject *b) const {
        if (!a || !b) return true;
        if (a->getUserIndex2() < 0 && b->getUserIndex2() < 0) return false; // both static
        const auto ma = static_cast<size_t>(a->getUserIndex()),
                   mb = static_cast<size_t>(b->getUserIndex());
        return (*groups_)[ma] != (*groups_)[mb];
    }

  private:
    const std::vector<uint32_t> *groups_;
};

using PairKey = std::pair<uint32_t, uint32_t>;
PairKey key_of(uint32_t a, uint32_t b) {
    return a < b ? PairKey{a, b} : PairKey{b, a};
}

// The deepest point of the contact between two objects at the start of a step.
struct Touch {
    const btCollisionObject *o0 = nullptr, *o1 = nullptr;
    double distance = kNever; // negative: penetrating
    glm::dvec3 normal{0.0};   // Bullet's normal on o1, pointing towards o0
    glm::dvec3 point{0.0};
};

class Bake {
  public:
    Bake(const ani_physics_scene &scene, double t_begin, double t_end, const ani_bake_sink &sink,
         const ani_host *host, const BakeOptions &options, SaidInBake &reported)
        : scene_(&scene), t_begin_(t_begin), t_end_(t_end), sink_(&sink), host_(host),
          options_(options), requested_(options), dt_(options.step), filter_(&groups_),
          reported_(reported) {
        reported_.begin(t_begin);
        const int axis = scene.down_axis >= 0 && scene.down_axis <= 2 ? scene.down_axis : 1;
        gravity_[axis] = -scene.gravity;
        with_rotation_sink_ = sink.rotation != nullptr;
    }

    ~Bake() {
        // The world first (it detaches the bodies), then the bodies and shapes.
        world_.reset();
    }

    void run() {
        read_materials();
        print_ = physics_custom::scene_print(*scene_);
        out_.resize(scene_->model_count);
        rotation_out_.resize(scene_->model_count);
        pivots_.assign(scene_->model_count, glm::dvec3(0.0));
        ++worlds_;
        setup_world();
        classify();
        set_kinematic_poses(t_begin_, t_begin_ + dt_);
        find_overlaps(nullptr);
        t_ = previous_ = t_begin_;
        k_ = static_cast<int64_t>(std::floor(t_begin_ / dt_ + 1e-9)) + 1;
        end_slice();
    }

    // Whether a bake of `scene` from t_begin is the next slice of this one: it starts where this
    // one stopped (not at 0), with the same options, and the scene is the same (scene_print: the
    // models, their meshes, physics flags, keyed spans, key times and the states at their keys;
    // gravity). The host builds the scene anew for every call.
    bool continues(const ani_physics_scene &scene, double t_begin, const BakeOptions &options,
                   const ani_bake_sink &sink) const {
        return t_begin > 0.0 && t_begin == t_end_ && same_options(options, requested_) &&
               (sink.rotation != nullptr) == with_rotation_sink_ &&
               physics_custom::scene_print(scene) == print_;
    }

    // The next slice, [t_end of the last, t_end]: Bullet's world goes on from where the last
    // slice left it (its bodies, contacts and tracks as they are), so the slices step as one bake
    // would (issue 16: each slice built a new world and restarted from the host's states).
    void resume(const ani_physics_scene &scene, double t_end, const ani_bake_sink &sink) {
        scene_ = &scene;
        sink_ = &sink;
        t_begin_ = t_end_;
        t_end_ = t_end;
        flush();
        end_slice();
    }

    // Called by the near callback after Bullet computed a pair's contacts. A pair let go while
    // it moved apart from an overlap stays let go while it still moves apart; once it no longer
    // does (it turns back, or rests), Bullet takes it (its contact holds it and pushes it out),
    // so that it never sinks deeper than it was.
    void after_near(btBroadphasePair &pair) {
        if (ignored_.empty() || !pair.m_algorithm) return;
        const auto *a = static_cast<const btCollisionObject *>(pair.m_pProxy0->m_clientObject);
        const auto *b = static_cast<const btCollisionObject *>(pair.m_pProxy1->m_clientObject);
        const PairKey key = key_of(static_cast<uint32_t>(a->getUserIndex()),
                                   static_cast<uint32_t>(b->getUserIndex()));
        if (!ignored_.count(key)) return;
        manifolds_.resizeNoInitialize(0);
        pair.m_algorithm->getAllContactManifolds(manifolds_);
        const btManifoldPoint *deepest = nullptr;
        const btPersistentManifold *in = nullptr;
        for (int k = 0; k < manifolds_.size(); ++k)
            for (int p = 0; p < manifolds_[k]->getNumContacts(); ++p) {
                const btManifoldPoint &point = manifolds_[k]->getContactPoint(p);
                if (!deepest || point.getDistance() < deepest->getDistance()) {
                    deepest = &point;
                    in = manifolds_[k];
                }
            }
        if (deepest && !keyed(a) && !keyed(b) &&
            !moving_apart(in->getBody0(), in->getBody1(), vec(deepest->m_normalWorldOnB),
                          0.5 * (vec(deepest->getPositionWorldOnA()) +
                                 vec(deepest->getPositionWorldOnB())))) {
            ignored_.erase(key); // Bullet's from now on: its manifold stays
            return;
        }
        for (int k = 0; k < manifolds_.size(); ++k) manifolds_[k]->clearManifold();
        if (deepest && deepest->getDistance() < -overlap_tolerance(a, b))
            still_overlapping_.insert(key);
    }

    // A pair already in contact whose bodies meet slower than gravity brings them together over
    // two steps (2 |G| dt, this step's pull included) is resting on each other, not bouncing:
    // its points get no restitution this step. Bullet's own threshold would also turn slow
    // collisions of free bodies inelastic; this one leaves a fresh contact its restitution at
    // any speed. Without it a resting body hops at each step by its restitution, and the hops
    // of a ball with e = 1 that rolls, held by the contact threshold (configure_material), grow
    // into bounces; a box on a box then meets a blow in mid-hop (physics-bullet.md, "Settings").
    void settle(btBroadphasePair &pair) {
        if (!pair.m_algorithm || contacts_.empty()) return;
        const auto *a = static_cast<const btCollisionObject *>(pair.m_pProxy0->m_clientObject);
        const auto *b = static_cast<const btCollisionObject *>(pair.m_pProxy1->m_clientObject);
        const PairKey key = key_of(static_cast<uint32_t>(a->getUserIndex()),
                                   static_cast<uint32_t>(b->getUserIndex()));
        const bool resting = contacts_.count(key) != 0;
        const double slow = 2.0 * glm::length(gravity_) * dt_;
        manifolds_.resizeNoInitialize(0);
        pair.m_algorithm->getAllContactManifolds(manifolds_);
        for (int k = 0; k < manifolds_.size(); ++k) {
            btPersistentManifold &m = *manifolds_[k];
            const double e = combined_restitution(m.getBody0()->getRestitution(),
                                                  m.getBody1()->getRestitution());
            for (int p = 0; p < m.getNumContacts(); ++p) {
                btManifoldPoint &point = m.getContactPoint(p);
                const glm::dvec3 at =
                    0.5 * (vec(point.getPositionWorldOnA()) + vec(point.getPositionWorldOnB()));
                const double approach =
                    glm::dot(pulled_velocity(m.getBody1(), at) - pulled_velocity(m.getBody0(), at),
                             vec(point.m_normalWorldOnB));
                point.m_combinedRestitution = resting && approach < slow ? 0.0 : e;
            }
        }
    }

    // A point's velocity once this step's gravity is added (as Bullet's solver sees it).
    glm::dvec3 pulled_velocity(const btCollisionObject *o, const glm::dvec3 &point) {
        const Body *body = body_of(o);
        glm::dvec3 v = velocity_of(o, point);
        if (body && !body->kinematic && body->mode == Mode::kDynamic) v += body->a * dt_;
        return v;
    }

    bool keyed(const btCollisionObject *o) const {
        const int ref = o->getUserIndex2();
        return ref >= 0 && bodies_[static_cast<size_t>(ref)].mode == Mode::kKeyed;
    }

    // Whether o0 moves away from o1 along n (Bullet's normal on o1, towards o0) at `point`.
    bool moving_apart(const btCollisionObject *o0, const btCollisionObject *o1, const glm::dvec3 &n,
                      const glm::dvec3 &point) const {
        const glm::dvec3 relative = velocity_of(o0, point) - velocity_of(o1, point);
        return glm::dot(relative, n) > 1e-9 * std::max(1.0, glm::length(relative));
    }

    // The velocity of an object's material point now: its keys' (kinematic) or Bullet's.
    glm::dvec3 velocity_of(const btCollisionObject *o, const glm::dvec3 &point) const {
        const int ref = o->getUserIndex2();
        if (ref < 0) return glm::dvec3(0.0);
        const Body &b = bodies_[static_cast<size_t>(ref)];
        const glm::dvec3 x = vec(b.rb->getWorldTransform().getOrigin());
        if (b.kinematic) return b.kin_v + glm::cross(b.kin_w, point - x);
        return vec(b.rb->getLinearVelocity()) +
               glm::cross(vec(b.rb->getAngularVelocity()), point - x);
    }

    // The static triangle mesh with inner edges in a pair whose other member is convex, if any.
    const Obstacle *flat_mesh_in(const btCollisionObject *a, const btCollisionObject *b) const {
        for (int k = 0; k < 2; ++k) {
            const btCollisionObject *o = k ? b : a, *other = k ? a : b;
            if (o->getUserIndex2() < 0 && !obstacle_of(o).shape->flat.empty() &&
                other->getCollisionShape()->isConvex())
                return &obstacle_of(o);
        }
        return nullptr;
    }

    const Obstacle &obstacle_of(const btCollisionObject *o) const {
        return obstacles_[static_cast<size_t>(-1 - o->getUserIndex2())];
    }

  private:
    // ---- setup -----------------------------------------------------------------------------

    // Each model's restitution, friction, Rotates and angular velocity (material.hpp).
    void read_materials() {
        bool turning = false;
        for (uint32_t i = 0; i < scene_->model_count; ++i) {
            const ani_physics_model &m = scene_->models[i];
            if (!m.desc) throw ani::Failure(ANI_ERR_INVALID_ARGUMENT, "a model has no description");
            materials_.push_back(material_of(*m.desc, name_of(m), options_.restitution,
                                             options_.friction, options_.rotate_on_contact));
            turning = turning || (materials_.back().rotates && m.desc->dynamics);
        }
        if (turning && !sink_->rotation) {
            // Bullet would turn models that the host then shows turned by their keys.
            log(ANI_LOG_WARNING, "Rotates (and rotate_on_contact) needs a host that takes "
                                 "rotation segments; models turn by their keys only");
            for (Material &m : materials_) m.rotates = false;
        }
    }

    // The orientation and angular velocity a body Bullet turns starts with at t (q: its keys'
    // orientation there): the host's when Bullet turned it in an earlier bake, the model's own
    // at t = 0, else its keys' angular velocity where they leave it (over the step before t).
    glm::dvec3 start_spin(const Body &b, double t, glm::dquat &q) const {
        if (!b.rotation) return glm::dvec3(0.0);
        const ani_physics_model &m = scene_->models[b.model];
        if (t == t_begin_ && ANI_PHYSICS_MODEL_HAS_TURNING(&m) && m.start_turning) {
            const glm::dquat s(m.start_orientation.w, m.start_orientation.x, m.start_orientation.y,
                               m.start_orientation.z);
            const glm::dvec3 w = vec(m.start_angular_velocity);
            if (!finite(w) || !std::isfinite(glm::length(glm::dvec4(s.x, s.y, s.z, s.w))) ||
                !(glm::length(glm::dvec4(s.x, s.y, s.z, s.w)) > 0.0))
                not_finite(b.model);
            q = glm::normalize(s);
            return w;
        }
        if (t <= 0.0) return materials_[b.model].angular_velocity;
        const double before = std::max(0.0, t - dt_);
        return angular_velocity(orientation(keyed_state(b.model, before)), q, t - before);
    }

    // Bullet meets a body moving over the inner edge between two coplanar triangles of a static
    // mesh on that edge too, with a normal tilted towards the body: beside the face's contact,
    // the solver's two restitution targets add energy (a ball in a box at dt 1/60 gained 10% in
    // 1000 s, and more after). As Bullet's btAdjustInternalEdgeContacts does, but without its
    // global callback, such a contact is turned into the face's before the manifold takes it.
    class InnerEdgeResult : public btManifoldResult {
      public:
        InnerEdgeResult(const btCollisionObjectWrapper *w0, const btCollisionObjectWrapper *w1,
                        const Obstacle &mesh)
            : btManifoldResult(w0, w1), mesh_(mesh) {}

        void addContactPoint(const btVector3 &normal_on_b, const btVector3 &point_on_b,
                             btScalar depth) override {
            // Bullet's convention (btManifoldResult::addContactPoint): the point is on the
            // manifold's second body, the normal points from it towards the first.
            const bool mesh_is_a = m_manifoldPtr->getBody0() == mesh_.rb.get();
            const bool mesh_wrapped_first = getBody0Wrap()->getCollisionObject() == mesh_.rb.get();
            const btCollisionObjectWrapper *other =
                mesh_wrapped_first ? getBody1Wrap() : getBody0Wrap();
            const int index = mesh_wrapped_first ? m_index0 : m_index1;
            // From the mesh towards the other body, and the contact point on the mesh.
            const btVector3 m = mesh_is_a ? -normal_on_b : normal_on_b;
            const btVector3 on_mesh = mesh_is_a ? point_on_b + normal_on_b * depth : point_on_b;
            const btTransform &to_world = mesh_.rb->getWorldTransform();
            const btTransform to_local = to_world.inverse();
            const glm::dvec3 local = vec(to_local(on_mesh));
            const glm::dvec3 normal = vec(to_world.getBasis().transpose() * m);
            glm::dvec3 face;
            if (!other->getCollisionShape()->isConvex() ||
                !inner_edge_contact(*mesh_.shape, index, local, normal, &face)) {
                btManifoldResult::addContactPoint(normal_on_b, point_on_b, depth);
                return;
            }
            if (glm::dot(face, normal) < 0.0) face = -face;
            const btVector3 f = to_world.getBasis() * bt(face);
            // The other body's deepest point towards the face, and its distance from the plane.
            const auto *convex = static_cast<const btConvexShape *>(other->getCollisionShape());
            const btTransform &other_world = other->getWorldTransform();
            const btVector3 q = other_world(
                convex->localGetSupportingVertex(other_world.getBasis().transpose() * -f));
            const btVector3 corner = to_world(bt(corner_of(*mesh_.shape, index)));
            const btScalar distance = (q - corner).dot(f);
            const btVector3 on_plane = q - f * distance;
            if (mesh_is_a)
                btManifoldResult::addContactPoint(-f, q, distance);
            else
                btManifoldResult::addContactPoint(f, on_plane, distance);
        }

      private:
        const Obstacle &mesh_;
    };

    static void near_callback(btBroadphasePair &pair, btCollisionDispatcher &dispatcher,
                              const btDispatcherInfo &info) {
        Bake &self = *static_cast<Dispatcher &>(dispatcher).bake;
        auto *o0 = static_cast<btCollisionObject *>(pair.m_pProxy0->m_clientObject);
        auto *o1 = static_cast<btCollisionObject *>(pair.m_pProxy1->m_clientObject);
        const Obstacle *mesh = self.flat_mesh_in(o0, o1);
        if (!mesh || info.m_dispatchFunc != btDispatcherInfo::DISPATCH_DISCRETE) {
            btCollisionDispatcher::defaultNearCallback(pair, dispatcher, info);
        } else if (dispatcher.needsCollision(o0, o1)) {
            // Bullet's default near callback, with the result that fixes inner edges.
            btCollisionObjectWrapper w0(nullptr, o0->getCollisionShape(), o0,
                                        o0->getWorldTransform(), -1, -1);
            btCollisionObjectWrapper w1(nullptr, o1->getCollisionShape(), o1,
                                        o1->getWorldTransform(), -1, -1);
            if (!pair.m_algorithm)
                pair.m_algorithm =
                    dispatcher.findAlgorithm(&w0, &w1, nullptr, BT_CONTACT_POINT_ALGORITHMS);
            if (pair.m_algorithm) {
                InnerEdgeResult result(&w0, &w1, *mesh);
                pair.m_algorithm->processCollision(&w0, &w1, info, &result);
            }
        }
        self.after_near(pair);
        self.settle(pair);
    }

    static void pre_tick(btDynamicsWorld *world, btScalar) {
        auto *self = static_cast<Bake *>(world->getWorldUserInfo());
        for (Body &b : self->bodies_)
            if (b.kinematic) {
                b.rb->setLinearVelocity(bt(b.kin_v));
                b.rb->setAngularVelocity(bt(b.kin_w));
            }
    }

    void setup_world() {
        for (uint32_t i = 0; i < scene_->model_count; ++i)
            groups_.push_back(scene_->models[i].group);
        // Bullet's default pools hold 4096 manifolds and algorithms, cleared when a world is made;
        // the editor made one per bake slice, which under ASan cost seconds each (a slice now goes
        // on with the last one's world, but every edit still starts a new one). Small pools
        // overflow to the heap when a scene needs more (Bullet's default dynamic allocation).
        btDefaultCollisionConstructionInfo pools;
        pools.m_defaultMaxPersistentManifoldPoolSize = 64;
        pools.m_defaultMaxCollisionAlgorithmPoolSize = 64;
        config_ = std::make_unique<btDefaultCollisionConfiguration>(pools);
        dispatcher_ = std::make_unique<Dispatcher>(config_.get(), this);
        dispatcher_->setNearCallback(near_callback);
        btGImpactCollisionAlgorithm::registerAlgorithm(dispatcher_.get());
        broadphase_ = std::make_unique<btDbvtBroadphase>();
        broadphase_->getOverlappingPairCache()->setOverlapFilterCallback(&filter_);
        solver_ = std::make_unique<btSequentialImpulseConstraintSolver>();
        world_ = std::make_unique<btDiscreteDynamicsWorld>(dispatcher_.get(), broadphase_.get(),
                                                           solver_.get(), config_.get());
        world_->setGravity(bt(gravity_));
        // physics.md, "Bullet facts worth knowing": the settings closest to the seed's model.
        btContactSolverInfo &info = world_->getSolverInfo();
        info.m_numIterations = options_.solver_iterations;
        info.m_restitutionVelocityThreshold = 0.0;
        info.m_splitImpulse = 1;
        info.m_splitImpulsePenetrationThreshold = 0.0;
        info.m_linearSlop = 0.0;
        info.m_warmstartingFactor = 0.0;
        info.m_solverMode &= ~SOLVER_USE_WARMSTARTING;
        world_->getDispatchInfo().m_allowedCcdPenetration = 0.0;
        world_->setInternalTickCallback(pre_tick, this, true);
    }

    ani_model_state keyed_state(uint32_t m, double t, glm::dvec3 *velocity = nullptr) const {
        ani_model_state state{};
        ani_vec3 v{};
        if (scene_->evaluate_keyed(scene_->host_context, m, t, &state, &v) != ANI_OK)
            throw ani::Failure(ANI_ERR_FAILED, std::string("cannot evaluate the keys of model '") +
                                                   name_of(scene_->models[m]) + "'");
        if (!finite(state.center) || !finite(state.angles) || !finite(state.scale) || !finite(v))
            throw ani::Failure(ANI_ERR_FAILED, std::string("the keys of model '") +
                                                   name_of(scene_->models[m]) +
                                                   "' give a value that is not finite");
        if (velocity) *velocity = vec(v);
        return state;
    }

    bool has_key_times(const ani_physics_model &m) const {
        return m.struct_size >= offsetof(ani_physics_model, key_count) + sizeof(m.key_count) &&
               m.key_times;
    }

    // The first of the model's keys after t (the end of its keyed span if none is in between).
    double next_key(uint32_t i, double t) const {
        const ani_physics_model &m = scene_->models[i];
        if (has_key_times(m))
            for (uint32_t k = 0; k < m.key_count; ++k)
                if (m.key_times[k] > t) return m.key_times[k];
        return m.keyed_span_count ? m.keyed_spans[0].end : t;
    }

    double last_key(uint32_t i) const {
        const ani_physics_model &m = scene_->models[i];
        double last = m.keyed_span_count ? m.keyed_spans[0].end : 0.0;
        if (has_key_times(m) && m.key_count) last = std::max(last, m.key_times[m.key_count - 1]);
        return last;
    }

    // Whether a model's keys from t_begin to its last key all place it the same way and leave it
    // still (as physics.custom decides: checked at each key and half-way between keys).
    bool keys_hold_still(uint32_t i, double last) const {
        const ani_physics_model &m = scene_->models[i];
        if (!has_key_times(m)) return false;
        std::vector<double> times = {t_begin_};
        for (uint32_t k = 0; k < m.key_count; ++k)
            if (m.key_times[k] > t_begin_ && m.key_times[k] <= last) {
                times.push_back(0.5 * (times.back() + m.key_times[k]));
                times.push_back(m.key_times[k]);
            }
        const ani_model_state first = keyed_state(i, t_begin_);
        auto same = [](const ani_vec3 &a, const ani_vec3 &b) {
            return a.x == b.x && a.y == b.y && a.z == b.z;
        };
        for (double t : times) {
            glm::dvec3 v;
            const ani_model_state s = keyed_state(i, t, &v);
            if (v != glm::dvec3(0.0) || !same(s.center, first.center) ||
                !same(s.angles, first.angles) || !same(s.scale, first.scale))
                return false;
        }
        return true;
    }

    // The state a model is in at t: the host's where a resumed bake starts, otherwise its keys'.
    ani_body_state start_of(uint32_t i, double t) const {
        const ani_physics_model &m = scene_->models[i];
        if (t == t_begin_ && m.start.motion != ANI_MOTION_KEYED) return m.start;
        glm::dvec3 v;
        const ani_model_state s = keyed_state(i, t, &v);
        ani_body_state state{};
        state.motion = ANI_MOTION_KEYED;
        state.center = s.center;
        state.velocity = ani(v);
        return state;
    }

    // Sorts the models as physics.custom does: static models with a mesh are static bodies;
    // models with a mesh that move (Dynamics or Gravity) or are keyed during the bake are bodies;
    // the rest (jointed parts, models without a mesh) move without collisions.
    void classify() {
        std::vector<uint32_t> statics;
        for (uint32_t i = 0; i < scene_->model_count; ++i) {
            const ani_physics_model &m = scene_->models[i];
            if (!m.desc) throw ani::Failure(ANI_ERR_INVALID_ARGUMENT, "a model has no description");
            const ani_time_span span =
                m.keyed_span_count ? m.keyed_spans[0] : ani_time_span{t_begin_, t_begin_};
            const bool free_now = span.end <= t_begin_;
            const bool released = !free_now && m.start.motion != ANI_MOTION_KEYED;
            const ani_model_desc &d = *m.desc;
            const bool movable = d.dynamics || d.gravity;
            const bool solid = m.mesh && m.mesh->triangle_count > 0 && m.mesh->positions &&
                               m.mesh->triangles && m.group == i;
            const bool held_still =
                !free_now && !released && solid && !movable && keys_hold_still(i, span.end);
            const bool keyed_here = !free_now && span.end > t_begin_ && !held_still;
            check_mesh(i);

            // Models outside Bullet's stepping: keyed to the end of their keys, then a closed
            // form, reported up to the end of each slice (cut()).
            if (!movable && (free_now || held_still) && solid) {
                statics.push_back(i);
                const double from = held_still ? std::max(span.end, t_begin_) : t_begin_;
                Fixed f{i, t_begin_, from, Track(i, segment_sink())};
                f.track.start_closed(from, vec(start_of(i, from).center), glm::dvec3(0.0),
                                     glm::dvec3(0.0), ANI_MOTION_REST);
                fixed_.push_back(std::move(f));
                continue;
            }
            if (solid && (movable || keyed_here)) {
                add_body(i, span, free_now, released);
                continue;
            }
            const double from = free_now ? t_begin_ : span.end;
            Fixed f{i, t_begin_, from, Track(i, segment_sink())};
            if (std::isfinite(from)) free_closed_form(f.track, i, start_of(i, from), from);
            fixed_.push_back(std::move(f));
        }
        set_kinematic_poses(t_begin_, t_begin_ + dt_); // where the bodies start, for rooms
        for (uint32_t i : statics) add_obstacle(i);
        for (Body &b : bodies_) world_add(b);
    }

    void check_mesh(uint32_t i) const {
        const ani_physics_model &m = scene_->models[i];
        if (!m.mesh || !m.mesh->positions) return;
        for (size_t k = 0; k < 3 * static_cast<size_t>(m.mesh->vertex_count); ++k)
            if (!std::isfinite(m.mesh->positions[k]))
                throw ani::Failure(ANI_ERR_INVALID_ARGUMENT,
                                   std::string("model '") + name_of(m) +
                                       "' has a mesh vertex that is not finite");
        for (size_t k = 0; k < 3 * static_cast<size_t>(m.mesh->triangle_count); ++k)
            if (m.mesh->triangles && m.mesh->triangles[k] >= m.mesh->vertex_count)
                throw ani::Failure(ANI_ERR_INVALID_ARGUMENT,
                                   std::string("model '") + name_of(m) +
                                       "' has a triangle with a vertex index out of range");
    }

    // physics.md's four cases after a model's keys, as one closed form (no collisions).
    void free_closed_form(Track &track, uint32_t i, const ani_body_state &start, double t) const {
        const ani_model_desc &d = *scene_->models[i].desc;
        const bool carries = d.dynamics || (d.gravity && start.motion == ANI_MOTION_FREE);
        const glm::dvec3 v = carries ? vec(start.velocity) : glm::dvec3(0.0);
        const glm::dvec3 a = d.gravity ? gravity_ : glm::dvec3(0.0);
        const bool moves = d.gravity || v != glm::dvec3(0.0);
        track.start_closed(t, vec(start.center), v, a, moves ? ANI_MOTION_FREE : ANI_MOTION_REST);
    }

    const MeshInfo &info_of(uint32_t i) {
        const ani_mesh_view *mesh = scene_->models[i].mesh;
        auto it = mesh_info_.find(mesh);
        if (it == mesh_info_.end()) it = mesh_info_.emplace(mesh, analyse_mesh(*mesh)).first;
        return it->second;
    }

    // The point a turning body turns about: its closed mesh's centre of mass under `scale`, in
    // its own frame, when that is not its origin (1e-9 of its size); Bullet's body is placed
    // there, its shape relative to it, and the host told (free-rotation segments' pivot).
    glm::dvec3 pivot_of(const Body &b, const glm::dvec3 &scale) {
        const ani_mesh_view &mesh = *scene_->models[b.model].mesh;
        if (!b.turns || mesh.is_sphere || !info_of(b.model).closed) return glm::dvec3(0.0);
        const glm::dvec3 com = centre_of_mass(mesh, scale);
        const double size = mesh.bound_radius * std::max({scale.x, scale.y, scale.z}) +
                            glm::length(vec(mesh.bound_center) * scale);
        const glm::dvec3 pivot = glm::length(com) > 1e-9 * size ? com : glm::dvec3(0.0);
        pivots_[b.model] = pivot;
        return pivot;
    }

    // The shape of model i at a scale: a sphere, a box, a convex hull, or its triangles (a BVH
    // when it never moves, GImpact when it does). `room`: a static convex mesh a body starts
    // inside.
    std::unique_ptr<Shape> make_shape(uint32_t i, const glm::dvec3 &scale, bool moving,
                                      bool room = false,
                                      const glm::dvec3 &pivot = glm::dvec3(0.0)) {
        const ani_mesh_view &mesh = *scene_->models[i].mesh;
        if (!(scale.x > 0.0 && scale.y > 0.0 && scale.z > 0.0))
            throw ani::Failure(ANI_ERR_INVALID_ARGUMENT, std::string("model '") +
                                                             name_of(scene_->models[i]) +
                                                             "' has a scale that is not positive");
        std::unique_ptr<Shape> shape;
        if (mesh.is_sphere && uniform(scale) && mesh.bound_radius > 0.0 &&
            glm::length(vec(mesh.bound_center)) <= 1e-9 * mesh.bound_radius) {
            shape = sphere_shape(mesh.bound_radius * scale.x);
        } else {
            const MeshInfo &info = info_of(i);
            if (!info.has_area)
                throw ani::Failure(ANI_ERR_INVALID_ARGUMENT,
                                   std::string("model '") + name_of(scene_->models[i]) +
                                       "' has a mesh without area (every triangle is degenerate)");
            if (info.convex && !room) {
                shape = box_shape(mesh, scale, options_.margin, pivot);
                if (!shape) shape = hull_shape(mesh, scale, options_.margin, pivot);
            } else {
                shape = triangle_shape(mesh, scale, moving, pivot);
            }
        }
        shape->scale = scale;
        ++shapes_built_;
        if (described_.insert(i).second) {
            ++counts_[shape->count_name()];
            std::string what = shape->describe();
            if (room) what += ", a room: a moving model starts inside it";
            if (reported_.first_description(i)) // once per bake, not once per slice
                log(ANI_LOG_INFO,
                    std::string("model '") + name_of(scene_->models[i]) + "': " + what);
        }
        return shape;
    }

    void add_obstacle(uint32_t i) {
        const ani_model_state s = keyed_state(i, t_begin_);
        glm::dvec3 center = vec(s.center);
        const ani_physics_model &m = scene_->models[i];
        if (m.start.motion != ANI_MOTION_KEYED && finite(m.start.center))
            center = vec(m.start.center);
        const glm::dquat q = orientation(s);
        // A closed convex mesh that a moving model starts inside is a room: its triangles.
        bool room = false;
        if (info_of(i).convex && !m.mesh->is_sphere) {
            for (const Body &b : bodies_) {
                const glm::dvec3 c = vec(b.rb->getWorldTransform().getOrigin());
                const glm::dvec3 local = glm::conjugate(q) * (c - center) / vec(s.scale);
                if (inside_convex(*m.mesh, local)) room = true;
            }
        }
        Obstacle o;
        o.model = i;
        o.shape = make_shape(i, vec(s.scale), false, room);
        btRigidBody::btRigidBodyConstructionInfo ci(0.0, nullptr, o.shape->shape.get());
        o.rb = std::make_unique<btRigidBody>(ci);
        o.rb->setWorldTransform(transform(center, q));
        configure_material(*o.rb, i, o.shape->reach);
        o.rb->setUserIndex(static_cast<int>(i));
        o.rb->setUserIndex2(-1 - static_cast<int>(obstacles_.size()));
        world_->addRigidBody(o.rb.get(), btBroadphaseProxy::DefaultFilter,
                             btBroadphaseProxy::AllFilter);
        obstacles_.push_back(std::move(o));
    }

    void configure_material(btRigidBody &rb, uint32_t model, double reach) const {
        // The model's own values: the combine callbacks take the lower restitution and the
        // higher friction of a contact's two bodies (install_combine_rules).
        rb.setRestitution(materials_[model].restitution);
        rb.setFriction(materials_[model].friction);
        rb.setRollingFriction(0.0);
        rb.setSpinningFriction(0.0);
        // Bullet's solver takes a contact point only while its gap is below the smaller of the
        // two bodies' thresholds. Below the gap a resting body hops by at each step (the
        // separation of the pair, separation()), so that a box resting on a box is held at every
        // corner at every step (at 0, a corner that hopped clear drops out of the solve and the
        // stack shudders: 0.1 m at any step); a model approaching from farther is met once it
        // touches, as with 0 (Bullet would otherwise stop it early, by up to the gap).
        rb.setContactProcessingThreshold(2.0 * glm::length(gravity_) * dt_ * dt_ + 1e-6 * reach);
    }

    void add_body(uint32_t i, const ani_time_span &span, bool free_now, bool released) {
        const ani_physics_model &m = scene_->models[i];
        const ani_model_desc &d = *m.desc;
        Body b;
        b.model = i;
        b.dynamics = d.dynamics != 0;
        b.gravity = d.gravity != 0;
        b.mass = d.mass;
        if (b.dynamics && !(std::isfinite(b.mass) && b.mass > 0.0))
            throw ani::Failure(ANI_ERR_INVALID_ARGUMENT,
                               std::string("model '") + name_of(m) +
                                   "' has Dynamics and a mass that is not a positive number");
        b.a = b.gravity ? gravity_ : glm::dvec3(0.0);
        b.keys_end = free_now ? t_begin_ : span.end;
        b.last_key = last_key(i);
        b.track = std::make_unique<Track>(i, segment_sink());
        const ani_model_state s = keyed_state(i, t_begin_);
        b.turns = materials_[i].rotates && b.dynamics;
        b.pivot = pivot_of(b, vec(s.scale));
        b.shape = make_shape(i, vec(s.scale), true, false, b.pivot);
        if (b.turns) {
            b.rotation =
                std::make_unique<RotationTrack>(i, rotation_sink(), std::max(b.shape->reach, 1e-9));
            b.rotation->set_gravity(glm::length(b.a));
        }
        btRigidBody::btRigidBodyConstructionInfo ci(0.0, nullptr, b.shape->shape.get());
        b.rb = std::make_unique<btRigidBody>(ci);
        configure_material(*b.rb, i, b.shape->reach);
        b.rb->setDamping(0.0, 0.0);
        b.rb->setFlags(b.rb->getFlags() & ~BT_ENABLE_GYROSCOPIC_FORCE_IMPLICIT_BODY);
        b.rb->setUserIndex(static_cast<int>(i));
        b.rb->setUserIndex2(static_cast<int>(bodies_.size()));
        b.rb->setWorldTransform(
            transform(vec(s.center) + orientation(s) * b.pivot, orientation(s)));

        if (released) {
            // Released from its keys at a contact in an earlier bake: free until its next key.
            b.resume_at = next_key(i, t_begin_);
            if (b.dynamics) {
                glm::dquat q = orientation(s);
                const glm::dvec3 w = start_spin(b, t_begin_, q);
                start_dynamic(b, t_begin_, vec(m.start.center), bullet_velocity(b, m.start), q, w);
            } else {
                start_rest(b, t_begin_, vec(m.start.center));
            }
        } else if (free_now) {
            const ani_body_state start = start_of(i, t_begin_);
            start_free(b, t_begin_, start, orientation(s));
        } else {
            b.mode = Mode::kKeyed;
            b.keyed_from = t_begin_;
            b.kinematic = true;
        }
        bodies_.push_back(std::move(b));
    }

    // A segment's velocity at a step time is Bullet's plus a h / 2 (track.hpp); a body starting
    // from an exact state gets Bullet's velocity v - a h / 2, so its steps lie on the exact
    // parabola.
    glm::dvec3 bullet_velocity(const Body &b, const ani_body_state &s) const {
        const glm::dvec3 v = vec(s.velocity);
        return s.motion == ANI_MOTION_REST ? v : v - 0.5 * dt_ * b.a;
    }

    // Free from t with `start` (its keys' state when it leaves them, or the host's): physics.md's
    // four cases.
    void start_free(Body &b, double t, const ani_body_state &start, const glm::dquat &q) {
        if (b.dynamics) {
            glm::dquat turned_to = q;
            const glm::dvec3 w = start_spin(b, t, turned_to);
            start_dynamic(b, t, vec(start.center), bullet_velocity(b, start), turned_to, w);
        } else if (b.gravity && start.motion != ANI_MOTION_REST) {
            // Without Dynamics it drops from rest, except that a fall under way goes on.
            const glm::dvec3 v =
                start.motion == ANI_MOTION_FREE ? vec(start.velocity) : glm::dvec3(0.0);
            b.mode = Mode::kFalling;
            b.track->start_closed(t, vec(start.center), v, b.a, ANI_MOTION_FREE);
            set_kinematic(b);
        } else {
            start_rest(b, t, vec(start.center));
        }
    }

    void start_rest(Body &b, double t, const glm::dvec3 &center) {
        b.mode = Mode::kRest;
        b.track->start_closed(t, center, glm::dvec3(0.0), glm::dvec3(0.0), ANI_MOTION_REST);
        set_kinematic(b);
    }

    void start_dynamic(Body &b, double t, const glm::dvec3 &origin, const glm::dvec3 &origin_v,
                       const glm::dquat &q, const glm::dvec3 &w = glm::dvec3(0.0)) {
        // A body turning about its centre of mass: Bullet's body is that point. Its velocity is
        // its origin's (leaving its keys, or from the host), except when it is free from the
        // start: thrown with the model's velocity at its centre of mass (as in physics.custom).
        glm::dvec3 x = origin, v = origin_v;
        if (b.pivot != glm::dvec3(0.0)) {
            const glm::dvec3 arm = q * b.pivot;
            x += arm;
            if (b.keys_end > 0.0) v += glm::cross(w, arm);
        }
        b.mode = Mode::kDynamic;
        const bool was_in_world = b.rb->isInWorld();
        if (was_in_world) world_->removeRigidBody(b.rb.get());
        b.kinematic = false;
        int flags = b.rb->getCollisionFlags();
        flags &= ~(btCollisionObject::CF_KINEMATIC_OBJECT | btCollisionObject::CF_STATIC_OBJECT);
        b.rb->setCollisionFlags(flags);
        btVector3 inertia(0.0, 0.0, 0.0);
        b.shape->shape->calculateLocalInertia(b.mass, inertia);
        b.rb->setMassProps(b.mass, inertia);
        const double turn = b.rotation ? 1.0 : 0.0; // Rotates: inertia from the shape
        b.rb->setAngularFactor(btVector3(turn, turn, turn));
        // Moments that differ (a box): its angular velocity changes in free flight (Euler's
        // equations), so Bullet's implicit gyroscopic term is on; a spherical top keeps w.
        const double most = inertia.x() > inertia.y() ? std::max(inertia.x(), inertia.z())
                                                      : std::max(inertia.y(), inertia.z()),
                     least = inertia.x() < inertia.y() ? std::min(inertia.x(), inertia.z())
                                                       : std::min(inertia.y(), inertia.z());
        b.gyroscopic = b.rotation && most - least > 1e-9 * most;
        b.rb->setFlags(b.gyroscopic ? b.rb->getFlags() | BT_ENABLE_GYROSCOPIC_FORCE_IMPLICIT_BODY
                                    : b.rb->getFlags() & ~BT_ENABLE_GYROSCOPIC_FORCE_IMPLICIT_BODY);
        b.rb->setLinearFactor(btVector3(1.0, 1.0, 1.0));
        if (b.gravity) {
            b.rb->setFlags(b.rb->getFlags() & ~BT_DISABLE_WORLD_GRAVITY);
        } else {
            b.rb->setFlags(b.rb->getFlags() | BT_DISABLE_WORLD_GRAVITY);
        }
        b.rb->setCenterOfMassTransform(transform(x, q));
        b.rb->setLinearVelocity(bt(v));
        b.rb->setAngularVelocity(bt(b.rotation ? w : glm::dvec3(0.0)));
        b.rb->updateInertiaTensor();
        if (options_.ccd && b.shape->inner > 0.0) {
            b.rb->setCcdMotionThreshold(0.5 * b.shape->inner);
            b.rb->setCcdSweptSphereRadius(0.9 * b.shape->inner);
        } else {
            b.rb->setCcdMotionThreshold(0.0);
            b.rb->setCcdSweptSphereRadius(0.0);
        }
        b.track->start_stepping(t, x, v, b.a, dt_);
        if (b.rotation) b.rotation->start(t, q, w, dt_);
        if (was_in_world) world_add(b);
    }

    void set_kinematic(Body &b) {
        if (b.kinematic && b.rb->isInWorld()) return;
        const bool was_in_world = b.rb->isInWorld();
        if (was_in_world) world_->removeRigidBody(b.rb.get());
        b.kinematic = true;
        b.rb->setMassProps(0.0, btVector3(0.0, 0.0, 0.0));
        int flags = b.rb->getCollisionFlags();
        flags &= ~btCollisionObject::CF_STATIC_OBJECT;
        flags |= btCollisionObject::CF_KINEMATIC_OBJECT;
        b.rb->setCollisionFlags(flags);
        b.rb->setLinearVelocity(btVector3(0.0, 0.0, 0.0));
        b.rb->setAngularVelocity(btVector3(0.0, 0.0, 0.0));
        b.rb->setCcdMotionThreshold(0.0);
        b.rb->setCcdSweptSphereRadius(0.0);
        if (was_in_world) world_add(b);
    }

    void world_add(Body &b) {
        if (b.kinematic) {
            int flags = b.rb->getCollisionFlags();
            flags &= ~btCollisionObject::CF_STATIC_OBJECT;
            flags |= btCollisionObject::CF_KINEMATIC_OBJECT;
            b.rb->setCollisionFlags(flags);
        }
        world_->addRigidBody(b.rb.get(), btBroadphaseProxy::DefaultFilter,
                             btBroadphaseProxy::AllFilter);
        b.rb->forceActivationState(DISABLE_DEACTIVATION);
        if (!b.kinematic && !b.gravity) b.rb->setGravity(btVector3(0.0, 0.0, 0.0));
    }

    // ---- the loop --------------------------------------------------------------------------

    // Times where a body changes how it moves: steps end there.
    double next_breakpoint(double t) const {
        double next = kNever;
        const double after = t + 1e-9 * dt_;
        for (const Body &b : bodies_) {
            if (b.mode == Mode::kKeyed && b.keys_end > after) next = std::min(next, b.keys_end);
            if (b.resume_at > after) next = std::min(next, b.resume_at);
        }
        return next;
    }

    bool same_time(double a, double b) const { return std::abs(a - b) <= 1e-9 * dt_; }

    // Steps end on the grid k dt (anchored at 0, so a resumed bake steps where one bake would)
    // and at each breakpoint, never at t_end: a bake steps on past it until the step it is on
    // starts at t_end or later, since a step finds the contacts at its start and dates them back
    // into the step before (contacts()). Then every contact before t_end is known, and a bake in
    // slices takes the very steps one whole bake takes; what lies beyond t_end is held back for
    // the next slice (put()). A step of the grid is exactly dt long (times far from 0 round).
    void loop() {
        while (previous_ < t_end_ && !same_time(previous_, t_end_)) {
            if (handle_breakpoints(t_)) {
                set_kinematic_poses(t_, t_ + dt_);
                find_overlaps(&switched_);
            }
            double grid = static_cast<double>(k_) * dt_;
            while (grid <= t_ || same_time(grid, t_)) grid = static_cast<double>(++k_) * dt_;
            if (try_coast()) continue;
            const double next = std::min(grid, next_breakpoint(t_));
            const bool whole =
                same_time(next, grid) && same_time(t_, static_cast<double>(k_ - 1) * dt_);
            step(t_, next, whole ? dt_ : next - t_, whole, previous_);
            previous_ = t_;
            t_ = next;
            took({0, 0, next, false});
            if (++taken_ % 256 == 0) progress();
        }
    }

    void progress() const {
        const double done = std::min(1.0, (t_ - t_begin_) / std::max(t_end_ - t_begin_, 1e-300));
        if (sink_->progress && !sink_->progress(sink_->context, done))
            throw ani::Failure(ANI_ERR_CANCELLED, "the bake was cancelled");
    }

    // ---- coasting ---------------------------------------------------------------------------
    //
    // While no two models can come near each other, Bullet's steps only integrate: every body
    // follows its stretch's parabola exactly (track.hpp). Then the bake advances whole steps in
    // closed form, the same positions Bullet's steps would reach, without stepping: a ball in a
    // box for 300000 s costs its contacts, not its 7e7 steps. Allowed only after every body's last
    // key, with no pair ignored, and for a window in which the boxes the models
    // sweep, grown by the distance at which a pair stays in contact, do not meet. Then nothing
    // that Bullet would do in those steps is skipped: it finds no contact at any of them, and its
    // CCD sweep (within the boxes) none either.

    bool try_coast() {
        double &t = t_;
        int64_t &k = k_;
        double &previous = previous_;
        if (coast_wait_ > 0) {
            --coast_wait_;
            return false;
        }
        if (!same_time(t, static_cast<double>(k - 1) * dt_) || !ignored_.empty()) return false;
        for (const Body &b : bodies_) {
            if (b.mode == Mode::kKeyed || b.resume_at < kNever) return false;
            if (t < b.last_key && !same_time(t, b.last_key)) return false;
            if (b.mode == Mode::kDynamic && !b.track->stepping()) return false;
            if (b.mode == Mode::kDynamic && b.gyroscopic) return false; // w changes: steps
        }
        // Not bounded by t_end: where a bake coasts to (and so where Bullet steps again) must
        // not depend on where it is cut into slices. A bake may coast past its end (closed
        // forms cost nothing); the next slice goes on from there.
        const double to_breakpoint =
            std::floor(next_breakpoint(t) / dt_ + 1e-9) - static_cast<double>(k - 1);
        if (to_breakpoint < 2.0) return false; // just before a breakpoint: nothing to wait for
        int64_t n = to_breakpoint < static_cast<double>(coast_window_)
                        ? static_cast<int64_t>(to_breakpoint)
                        : coast_window_;
        while (n >= 2 && !clear_for(t, static_cast<double>(n) * dt_)) n /= 2;
        if (n < 2) {
            coast_wait_ = coast_backoff_;
            coast_backoff_ = std::min<int64_t>(2 * coast_backoff_, 16);
            return false;
        }
        coast_backoff_ = 1;
        coast_window_ = std::min<int64_t>(2 * n, int64_t(1) << 30);
        const double t_new = static_cast<double>(k - 1 + n) * dt_;
        for (Body &b : bodies_) {
            if (b.mode != Mode::kDynamic) continue;
            const Track::State s = b.track->coast(t_new, n);
            if (!finite(s.x) || !finite(s.v)) not_finite(b.model);
            btTransform tr = b.rb->getWorldTransform();
            tr.setOrigin(bt(s.x));
            if (b.rotation) {
                const RotationTrack::State r = b.rotation->coast(t_new, n);
                tr.setRotation(bt(r.q));
                b.rb->setAngularVelocity(bt(r.w));
            }
            b.rb->setCenterOfMassTransform(tr);
            b.rb->setLinearVelocity(bt(s.v));
        }
        took({k, k - 1 + n, t_new, true});
        k += n;
        previous = t_new - dt_;
        t = t_new;
        progress();
        return true;
    }

    struct Box {
        glm::dvec3 lo, hi;
        const btCollisionObject *object;
    };

    // The extent of u tau + a tau^2 / 2 over [0, T] along each axis.
    static void sweep(const glm::dvec3 &u, const glm::dvec3 &a, double T, glm::dvec3 &lo,
                      glm::dvec3 &hi) {
        for (int c = 0; c < 3; ++c) {
            auto f = [&](double tau) { return u[c] * tau + 0.5 * a[c] * tau * tau; };
            double l = std::min(0.0, f(T)), h = std::max(0.0, f(T));
            if (a[c] != 0.0) {
                const double vertex = -u[c] / a[c];
                if (vertex > 0.0 && vertex < T) {
                    l = std::min(l, f(vertex));
                    h = std::max(h, f(vertex));
                }
            }
            lo[c] += l;
            hi[c] += h;
        }
    }

    // Whether no two models can come within contact distance of each other over [t, t + T].
    bool clear_for(double t, double T) {
        ++coast_checks_;
        // Farther apart than a pair stays in contact (separation()), with room for rounding.
        double largest = 0.0;
        for (const Body &b : bodies_) largest = std::max(largest, b.shape->reach);
        for (const Obstacle &o : obstacles_) largest = std::max(largest, o.shape->reach);
        const double grow = 2.0 * glm::length(gravity_) * dt_ * dt_ + 1e-6 * largest;
        std::vector<Box> boxes; // obstacles and bodies at rest, then moving bodies
        boxes.reserve(bodies_.size() + obstacles_.size());
        auto aabb = [&](const btCollisionObject *o) {
            btVector3 lo, hi;
            o->getCollisionShape()->getAabb(o->getWorldTransform(), lo, hi);
            return Box{vec(lo) - glm::dvec3(grow), vec(hi) + glm::dvec3(grow), o};
        };
        for (const Obstacle &o : obstacles_) boxes.push_back(aabb(o.rb.get()));
        for (const Body &b : bodies_) {
            Box box = aabb(b.rb.get());
            if (b.mode == Mode::kFalling) { // its closed form is ahead of Bullet's pose
                const glm::dvec3 shift =
                    b.track->position(t) - vec(b.rb->getWorldTransform().getOrigin());
                box.lo += shift;
                box.hi += shift;
            }
            if (b.rotation) { // it may turn: its bounding sphere
                const glm::dvec3 c = vec(b.rb->getWorldTransform().getOrigin());
                box.lo = c - glm::dvec3(b.shape->reach + grow);
                box.hi = c + glm::dvec3(b.shape->reach + grow);
            }
            if (b.mode == Mode::kDynamic)
                sweep(b.track->velocity(t), b.track->acceleration(), T, box.lo, box.hi);
            else if (b.mode == Mode::kFalling)
                sweep(b.track->velocity(t), b.track->acceleration(), T, box.lo, box.hi);
            if (!finite(box.lo) || !finite(box.hi)) return false;
            boxes.push_back(box);
        }
        std::sort(boxes.begin(), boxes.end(),
                  [](const Box &x, const Box &y) { return x.lo.x < y.lo.x; });
        for (size_t i = 0; i < boxes.size(); ++i)
            for (size_t j = i + 1; j < boxes.size() && boxes[j].lo.x <= boxes[i].hi.x; ++j) {
                const Box &p = boxes[i], &q = boxes[j];
                if (p.lo.y > q.hi.y || q.lo.y > p.hi.y || p.lo.z > q.hi.z || q.lo.z > p.hi.z)
                    continue;
                if (!filter_.may_collide(p.object, q.object) ||
                    (!moves(p.object) && !moves(q.object)))
                    continue; // a pair that nothing moves stays as it is (at rest on a floor)
                // A body inside a room's box may still be clear of all its triangles.
                const Box *body = &p, *other = &q;
                if (body->object->getUserIndex2() < 0) std::swap(body, other);
                if (other->object->getUserIndex2() < 0 &&
                    obstacle_of(other->object).shape->kind == ShapeKind::kBvhTriangles &&
                    clear_of_triangles(*body, obstacle_of(other->object)))
                    continue;
                return false;
            }
        return true;
    }

    bool moves(const btCollisionObject *o) {
        const Body *b = body_of(o);
        return b && (b->mode == Mode::kDynamic || b->mode == Mode::kFalling);
    }

    // Whether no triangle of a static mesh meets the box (in world space).
    static bool clear_of_triangles(const Box &box, const Obstacle &o) {
        const btTransform inverse = o.rb->getWorldTransform().inverse();
        btVector3 lo(kNever, kNever, kNever), hi(-kNever, -kNever, -kNever);
        for (int corner = 0; corner < 8; ++corner) {
            const btVector3 p = inverse(btVector3(corner & 1 ? box.hi.x : box.lo.x,
                                                  corner & 2 ? box.hi.y : box.lo.y,
                                                  corner & 4 ? box.hi.z : box.lo.z));
            lo.setMin(p);
            hi.setMax(p);
        }
        struct Meets : btTriangleCallback {
            btVector3 lo, hi;
            bool met = false;
            void processTriangle(btVector3 *v, int, int) override {
                btVector3 tlo = v[0], thi = v[0];
                for (int k = 1; k < 3; ++k) {
                    tlo.setMin(v[k]);
                    thi.setMax(v[k]);
                }
                if (tlo.x() <= hi.x() && thi.x() >= lo.x() && tlo.y() <= hi.y() &&
                    thi.y() >= lo.y() && tlo.z() <= hi.z() && thi.z() >= lo.z())
                    met = true;
            }
        } meets;
        meets.lo = lo;
        meets.hi = hi;
        static_cast<const btConcaveShape *>(o.shape->shape.get())
            ->processAllTriangles(&meets, lo, hi);
        return !meets.met;
    }

    // Activations (a keyed span ends) and resumptions (a released body's next key) at t.
    bool handle_breakpoints(double t) {
        switched_.clear();
        last_switch_ = t;
        for (Body &b : bodies_) {
            if (b.mode != Mode::kKeyed && b.resume_at < kNever &&
                (b.resume_at <= t || same_time(b.resume_at, t))) {
                // Its keys take it back: placed where they say (a jump, if the contact moved it).
                close_free(b, t);
                b.mode = Mode::kKeyed;
                b.keyed_from = t;
                b.resume_at = kNever;
                set_kinematic(b);
                switched_.insert(b.model);
            }
            if (b.mode == Mode::kKeyed && (b.keys_end <= t || same_time(b.keys_end, t))) {
                b.track->keyed(b.keyed_from, t);
                glm::dvec3 v;
                const ani_model_state s = keyed_state(b.model, t, &v);
                ani_body_state start{};
                start.motion = ANI_MOTION_KEYED;
                start.center = s.center;
                start.velocity = ani(v);
                start_free(b, t, start, orientation(s));
                switched_.insert(b.model);
            }
        }
        return !switched_.empty();
    }

    void close_free(Body &b, double t) {
        b.track->close(t);
        if (b.rotation) b.rotation->close(t);
    }

    // Where each kinematic body is at t0 and how fast it moves to where it is at t1; the keys'
    // orientation and scale for every body they still turn.
    void set_kinematic_poses(double t0, double t1) {
        const double h = t1 - t0;
        for (Body &b : bodies_) {
            const bool keys_turn = t0 < b.last_key;
            if (b.mode == Mode::kDynamic) {
                if (keys_turn && !b.rotation) {
                    const ani_model_state s = keyed_state(b.model, t0);
                    update_shape(b, vec(s.scale));
                    btTransform tr = b.rb->getWorldTransform();
                    tr.setRotation(bt(orientation(s)));
                    b.rb->setCenterOfMassTransform(tr);
                }
                continue;
            }
            glm::dvec3 c0, c1;
            glm::dquat q0, q1;
            if (b.mode == Mode::kKeyed) {
                const ani_model_state s0 = keyed_state(b.model, t0), s1 = keyed_state(b.model, t1);
                q0 = orientation(s0);
                q1 = orientation(s1);
                update_shape(b, vec(s0.scale));
                c0 = vec(s0.center) + q0 * b.pivot;
                c1 = vec(s1.center) + q1 * b.pivot;
            } else {
                c0 = b.track->position(t0);
                c1 = b.track->position(t1);
                if (keys_turn || !b.fixed_orientation) {
                    const ani_model_state s0 = keyed_state(b.model, t0),
                                          s1 = keyed_state(b.model, t1);
                    q0 = orientation(s0);
                    q1 = orientation(s1);
                    update_shape(b, vec(s0.scale));
                    if (!keys_turn) {
                        b.fixed_orientation = true;
                        b.orientation = q0;
                    }
                } else {
                    q0 = q1 = b.orientation;
                }
            }
            if (!finite(c0) || !finite(c1)) not_finite(b.model);
            b.rb->setWorldTransform(transform(c0, q0));
            b.rb->setInterpolationWorldTransform(transform(c0, q0));
            b.kin_v = h > 0.0 ? (c1 - c0) / h : glm::dvec3(0.0);
            b.kin_w = h > 0.0 ? angular_velocity(q0, q1, h) : glm::dvec3(0.0);
        }
    }

    // Keys that scale a model change its shape: built again for the new scale.
    void update_shape(Body &b, const glm::dvec3 &scale) {
        if (b.shape->scale == scale) return;
        b.pivot = pivot_of(b, scale);
        std::unique_ptr<Shape> shape = make_shape(b.model, scale, true, false, b.pivot);
        const bool in_world = b.rb->isInWorld();
        if (in_world) world_->removeRigidBody(b.rb.get());
        b.rb->setCollisionShape(shape->shape.get());
        b.shape = std::move(shape);
        if (!b.kinematic) {
            btVector3 inertia(0.0, 0.0, 0.0);
            b.shape->shape->calculateLocalInertia(b.mass, inertia);
            b.rb->setMassProps(b.mass, inertia);
            b.rb->updateInertiaTensor();
        }
        if (in_world) world_add(b);
    }

    void step(double t0, double t1, double h, bool whole, double previous) {
        set_kinematic_poses(t0, t1);
        for (Body &b : bodies_) {
            b.pre_x = vec(b.rb->getWorldTransform().getOrigin());
            if (b.kinematic) {
                b.pre_v = b.kin_v;
                b.pre_w = b.kin_w;
            } else {
                b.pre_v = vec(b.rb->getLinearVelocity());
                b.pre_w = vec(b.rb->getAngularVelocity());
            }
        }
        still_overlapping_.clear();
        world_->stepSimulation(h, 0, h);
        // Pairs ignored since they overlapped are apart once Bullet no longer finds them so.
        for (auto it = ignored_.begin(); it != ignored_.end();)
            it = still_overlapping_.count(*it) ? std::next(it) : ignored_.erase(it);

        const std::vector<Pending> pending = contacts(t0, previous);
        for (Body &b : bodies_)
            if (b.mode == Mode::kDynamic && !b.kinematic) record(b, t1, h, whole);
        for (const Pending &p : pending) apply(p, t1);
    }

    struct Pending {
        Body *body;
        bool release; // else: stop (a falling model without Dynamics)
        double t;
    };

    Body *body_of(const btCollisionObject *o) {
        const int ref = o->getUserIndex2();
        return ref >= 0 ? &bodies_[static_cast<size_t>(ref)] : nullptr;
    }

    double reach_of(const btCollisionObject *o) const {
        const int ref = o->getUserIndex2();
        return ref >= 0 ? bodies_[static_cast<size_t>(ref)].shape->reach
                        : obstacles_[static_cast<size_t>(-1 - ref)].shape->reach;
    }

    // Closer than this counts as overlapping (meshes are read in single precision).
    double overlap_tolerance(const btCollisionObject *a, const btCollisionObject *b) const {
        return 1e-5 * std::min(reach_of(a), reach_of(b));
    }

    // A pair in contact stays so until it is farther apart than this: a ball resting on a floor
    // hops by about G dt^2 at each step, which is not a new contact.
    double separation(const btCollisionObject *a, const btCollisionObject *b) const {
        return 2.0 * glm::length(gravity_) * dt_ * dt_ + 1e-6 * (reach_of(a) + reach_of(b));
    }

    std::map<PairKey, Touch> touches() {
        std::map<PairKey, Touch> out;
        for (int i = 0; i < dispatcher_->getNumManifolds(); ++i) {
            const btPersistentManifold *m = dispatcher_->getManifoldByIndexInternal(i);
            if (m->getNumContacts() == 0) continue;
            const btCollisionObject *o0 = m->getBody0(), *o1 = m->getBody1();
            const PairKey key = key_of(static_cast<uint32_t>(o0->getUserIndex()),
                                       static_cast<uint32_t>(o1->getUserIndex()));
            if (ignored_.count(key)) continue;
            Touch &touch = out[key];
            for (int p = 0; p < m->getNumContacts(); ++p) {
                const btManifoldPoint &pt = m->getContactPoint(p);
                const double d = pt.getDistance();
                if (d < touch.distance) {
                    touch.o0 = o0;
                    touch.o1 = o1;
                    touch.distance = d;
                    touch.normal = vec(pt.m_normalWorldOnB);
                    touch.point =
                        0.5 * (vec(pt.getPositionWorldOnA()) + vec(pt.getPositionWorldOnB()));
                }
            }
        }
        return out;
    }

    glm::dvec3 point_velocity(const btCollisionObject *o, const glm::dvec3 &point) {
        const Body *b = body_of(o);
        if (!b) return glm::dvec3(0.0);
        return b->pre_v + glm::cross(b->pre_w, point - b->pre_x);
    }

    // The contacts Bullet found at the start of the step from t0 (the positions at t0): events
    // for the new ones, and the rules Bullet does not know (release from keys, stop without
    // Dynamics) for the bodies they touch.
    std::vector<Pending> contacts(double t0, double previous) {
        struct Hit {
            double t;
            ani_collision_event event;
            bool fresh, strikes;
            Body *bodies[2];
        };
        std::vector<Hit> hits;
        std::set<PairKey> in_contact;
        for (const auto &[key, touch] : touches()) {
            if (touch.distance <= separation(touch.o0, touch.o1)) in_contact.insert(key);
            if (touch.distance > 0.0) continue;
            Body *b0 = body_of(touch.o0), *b1 = body_of(touch.o1);
            // The first model is the one that moves freely: a body against a static model, a
            // dynamic body against a kinematic one; else the lower index.
            bool first0 = true;
            if (!b1)
                first0 = true;
            else if (!b0)
                first0 = false;
            else if (b0->kinematic != b1->kinematic)
                first0 = !b0->kinematic;
            else
                first0 = touch.o0->getUserIndex() < touch.o1->getUserIndex();
            const btCollisionObject *oa = first0 ? touch.o0 : touch.o1,
                                    *ob = first0 ? touch.o1 : touch.o0;
            const glm::dvec3 n = first0 ? touch.normal : -touch.normal; // from b towards a
            const double speed = std::max(
                0.0,
                -glm::dot(point_velocity(oa, touch.point) - point_velocity(ob, touch.point), n));
            // Met between the previous step's positions and these: back along the approach by
            // the depth.
            double t = t0;
            if (speed > 0.0 && touch.distance < 0.0) t = t0 + touch.distance / speed;
            t = std::max(t, previous);
            for (const Body *b : {b0, b1}) {
                if (!b) continue;
                if (b->mode == Mode::kKeyed) t = std::max(t, b->keyed_from);
                if (b->mode == Mode::kFalling) t = std::max(t, b->track->stretch_start());
            }
            t = std::min(t, t0);
            Hit hit{};
            hit.t = t;
            hit.fresh = !contacts_.count(key);
            hit.bodies[0] = b0;
            hit.bodies[1] = b1;
            ani_collision_event &e = hit.event;
            e.t = t;
            e.a = static_cast<uint32_t>(oa->getUserIndex());
            e.b = static_cast<uint32_t>(ob->getUserIndex());
            e.normal = ani(n);
            e.point = ani(touch.point);
            e.speed = speed;
            // A keyed body is released by a collision, not by a model resting or sliding on it
            // (a box on a keyed platform), which meets it by about G dt at each step.
            hit.strikes = speed > 2.0 * glm::length(gravity_) * dt_;
            if (hit.fresh || speed > 0.0) hits.push_back(hit);
        }
        contacts_ = std::move(in_contact);
        std::sort(hits.begin(), hits.end(), [](const Hit &x, const Hit &y) { return x.t < y.t; });
        std::vector<Pending> pending;
        std::set<const Body *> handled;
        for (const Hit &hit : hits) {
            if (hit.fresh) report(hit.event);
            for (Body *b : hit.bodies) {
                if (!b || handled.count(b)) continue;
                if (b->mode == Mode::kKeyed) {
                    if (!hit.strikes) continue;
                    pending.push_back({b, true, hit.t});
                    handled.insert(b);
                } else if (b->mode == Mode::kFalling) {
                    pending.push_back({b, false, hit.t});
                    handled.insert(b);
                }
            }
        }
        return pending;
    }

    // A body Bullet moved: its state after the step, on its track.
    void record(Body &b, double t1, double h, bool whole) {
        btTransform tr = b.rb->getWorldTransform();
        const glm::dvec3 x = vec(tr.getOrigin()), v = vec(b.rb->getLinearVelocity());
        if (!finite(x) || !finite(v)) not_finite(b.model);
        const Track::State s = b.track->step(t1, h, whole, x, v);
        bool changed = s.x != x || s.v != v;
        if (b.rotation) {
            const glm::dquat q = quat(tr.getRotation());
            const glm::dvec3 w = vec(b.rb->getAngularVelocity());
            if (!finite(w) || !std::isfinite(q.w) || !std::isfinite(q.x) || !std::isfinite(q.y) ||
                !std::isfinite(q.z))
                not_finite(b.model);
            const RotationTrack::State r = b.rotation->step(t1, h, whole, q, w);
            tr.setRotation(bt(r.q));
            b.rb->setAngularVelocity(bt(r.w));
            changed = true;
        }
        if (changed) {
            tr.setOrigin(bt(s.x));
            b.rb->setCenterOfMassTransform(tr);
            b.rb->setLinearVelocity(bt(s.v));
        }
    }

    [[noreturn]] void not_finite(uint32_t model) const {
        throw ani::Failure(ANI_ERR_FAILED, std::string("model '") + name_of(scene_->models[model]) +
                                               "' would move to a value that is not finite");
    }

    void apply(const Pending &p, double t1) {
        Body &b = *p.body;
        if (!p.release) { // without Dynamics it stops at the moment of contact
            const glm::dvec3 at = b.track->position(p.t);
            b.track->close(p.t);
            start_rest(b, p.t, at);
            return;
        }
        // A keyed body that collides is released from its keys (physics.md): free from the
        // contact until its next key, with the velocity its keys gave it, or at rest without
        // Dynamics.
        ++releases_;
        b.track->keyed(b.keyed_from, p.t);
        b.resume_at = next_key(b.model, p.t);
        glm::dvec3 v;
        const ani_model_state s = keyed_state(b.model, p.t, &v);
        if (!b.dynamics) {
            start_rest(b, p.t, vec(s.center));
            return;
        }
        // Its exact flight from the contact to the end of this step, then Bullet's.
        b.track->start_closed(p.t, vec(s.center), v, b.a, ANI_MOTION_FREE);
        const glm::dvec3 x1 = b.track->position(t1), v1 = b.track->velocity(t1);
        b.track->close(t1);
        const glm::dquat q1 = orientation(keyed_state(b.model, t1));
        const glm::dvec3 w1 = b.rotation ? b.kin_w : glm::dvec3(0.0); // its keys', this step
        start_dynamic(b, t1, x1, v1 - 0.5 * dt_ * b.a, q1, w1);
    }

    // Pairs overlapping now (at the start, or when a body becomes free or is keyed again) are
    // treated as touching (physics.md), and said once per bake: moving apart, they are let go
    // until apart (or until they turn back, after_near); approaching, they are a new contact
    // (an event, and Bullet's response); neither, they are in contact already (no event), and
    // Bullet's contact holds them and pushes them out. Pairs touching now are in contact
    // already.
    void find_overlaps(const std::set<uint32_t> *only) {
        world_->performDiscreteCollisionDetection();
        const double t = only ? last_switch_ : t_begin_;
        for (const auto &[key, touch] : touches()) {
            if (only && !only->count(key.first) && !only->count(key.second)) continue;
            if (touch.distance < -overlap_tolerance(touch.o0, touch.o1)) {
                if (reported_.first(key.first, key.second, t)) {
                    ani_overlap o{};
                    o.t = t;
                    o.a = static_cast<uint32_t>(touch.o0->getUserIndex());
                    o.b = static_cast<uint32_t>(touch.o1->getUserIndex());
                    o.normal = ani_vec3{touch.normal.x, touch.normal.y, touch.normal.z};
                    o.depth = -touch.distance;
                    put_overlap(
                        o, std::string("models '") + name_of(scene_->models[key.first]) +
                               "' and '" + name_of(scene_->models[key.second]) +
                               "' overlap at t = " + short_number(t) + " s by " +
                               short_number(-touch.distance) +
                               " m: treated as touching (neither moves deeper into the other; "
                               "approaching, they collide at once; moving apart, they are let go)");
                }
                const glm::dvec3 relative =
                    velocity_of(touch.o0, touch.point) - velocity_of(touch.o1, touch.point);
                const double along = glm::dot(relative, touch.normal);
                const double still = 1e-9 * std::max(1.0, glm::length(relative));
                // A model its keys drive is where its keys say: left alone until apart.
                const Body *b0 = body_of(touch.o0), *b1 = body_of(touch.o1);
                const bool keyed =
                    (b0 && b0->mode == Mode::kKeyed) || (b1 && b1->mode == Mode::kKeyed);
                if (along > still || keyed) {
                    ignored_.insert(key);
                    contacts_.erase(key);
                } else if (along < -still) {
                    contacts_.erase(key);
                } else {
                    contacts_.insert(key);
                }
            } else if (touch.distance <= separation(touch.o0, touch.o1)) {
                contacts_.insert(key);
            }
        }
    }

    // Each slice's end: loops past t_end, then reports every model's motion up to t_end
    // without closing what goes on (the rest is reported by the next slice, or never).
    void end_slice() {
        loop();
        cut();
        report_counts();
    }

    // Reports what each track has open up to t_end (from copies: the tracks go on; put() holds
    // back what lies past t_end, and the next slice reports only what follows what was said).
    void cut() {
        provisional_ = true;
        for (Body &b : bodies_) {
            if (b.mode == Mode::kKeyed) {
                b.track->keyed(b.keyed_from, t_end_);
            } else {
                Track open = *b.track;
                open.close(t_end_);
            }
            if (b.rotation && b.rotation->open()) {
                RotationTrack open = *b.rotation;
                open.close(t_end_);
            }
        }
        for (Fixed &f : fixed_) {
            f.track.keyed(f.keyed_from, f.keyed_to);
            Track open = f.track;
            open.close(t_end_);
        }
        provisional_ = false;
    }

    // ---- reporting -------------------------------------------------------------------------

    SegmentSink segment_sink() {
        return [this](const ani_motion_segment &s) {
            // Its end too: a closed form may overflow within the segment.
            const double tau = s.t1 - s.t0;
            const glm::dvec3 end = vec(s.p0) + vec(s.v0) * tau + 0.5 * tau * tau * vec(s.a);
            if (!finite(s.p0) || !finite(s.v0) || !finite(s.a) || !std::isfinite(s.t0) ||
                !std::isfinite(s.t1) || !finite(end) || !finite(vec(s.v0) + tau * vec(s.a)))
                not_finite(s.model);
            put(s);
        };
    }

    RotationSink rotation_sink() {
        return [this](const ani_rotation_segment &s) {
            if (!finite(s.w) || !std::isfinite(s.q0.w) || !std::isfinite(s.q0.x) ||
                !std::isfinite(s.q0.y) || !std::isfinite(s.q0.z))
                not_finite(s.model);
            put(s);
        };
    }

    // What the host is told of a model's motion, slice by slice: each segment's part from where
    // the model was reported to (`said`) up to this slice's t_end; a segment that goes on past
    // t_end is kept (`later`), with every one after it, for the next slice. A provisional segment
    // (cut(): an open track up to t_end) is not kept: its track reports it again, in full.
    template <class Segment> struct Out {
        double said = -kNever;
        std::vector<Segment> later;
    };

    template <class Segment> void put(std::vector<Out<Segment>> &outs, const Segment &s) {
        if (s.model >= outs.size()) return;
        Out<Segment> &out = outs[s.model];
        const bool past = !out.later.empty() || s.t1 > t_end_;
        const double t0 = std::max(s.t0, out.said), t1 = std::min(s.t1, t_end_);
        if (out.later.empty() && t1 > t0) {
            Segment part = s;
            if (t0 > s.t0) from(part, t0);
            part.t1 = t1;
            out.said = t1;
            send(part);
        }
        if (past && !provisional_) out.later.push_back(s);
    }
    void put(const ani_motion_segment &s) { put(out_, s); }
    void put(const ani_rotation_segment &s) { put(rotation_out_, s); }

    // The segment from t on (t within it): the same motion, restated at t.
    static void from(ani_motion_segment &s, double t) {
        const double tau = t - s.t0;
        if (s.motion != ANI_MOTION_KEYED) {
            const glm::dvec3 v0 = vec(s.v0), a = vec(s.a);
            s.p0 = ani(vec(s.p0) + v0 * tau + 0.5 * tau * tau * a);
            s.v0 = ani(v0 + a * tau);
        }
        s.t0 = t;
    }
    static void from(ani_rotation_segment &s, double t) {
        const glm::dquat q = turned(glm::dquat(s.q0.w, s.q0.x, s.q0.y, s.q0.z), vec(s.w), t - s.t0);
        s.q0 = ani_quat{q.w, q.x, q.y, q.z};
        s.t0 = t;
    }

    void send(const ani_motion_segment &s) {
        ++segments_;
        sink_->segment(sink_->context, &s);
    }
    void send(const ani_rotation_segment &s) {
        const glm::dvec3 pivot = pivots_[s.model];
        if (pivot == glm::dvec3(0.0)) {
            if (sink_->rotation) sink_->rotation(sink_->context, &s);
            return;
        }
        // Turned about its centre of mass: the host needs the pivot (a spherical top's moments,
        // so that the closed form is the constant angular velocity of this segment).
        if (!sink_->free_rotation) return;
        ani_free_rotation_segment f{};
        f.model = s.model;
        f.t0 = s.t0;
        f.t1 = s.t1;
        f.q0 = s.q0;
        f.w0 = s.w;
        f.moments = ani_vec3{1.0, 1.0, 1.0};
        f.principal = ani_quat{1.0, 0.0, 0.0, 0.0};
        f.pivot = ani(pivot);
        sink_->free_rotation(sink_->context, &f);
    }

    // At the start of a slice, what the last one held back, up to the new t_end.
    void flush() {
        for (auto &out : out_) {
            std::vector<ani_motion_segment> later;
            later.swap(out.later);
            for (const auto &s : later) put(s);
        }
        for (auto &out : rotation_out_) {
            std::vector<ani_rotation_segment> later;
            later.swap(out.later);
            for (const auto &s : later) put(s);
        }
        std::vector<ani_collision_event> events;
        events.swap(later_events_);
        for (const auto &e : events) put_event(e);
        std::vector<std::pair<ani_overlap, std::string>> overlaps;
        overlaps.swap(later_overlaps_);
        for (const auto &[o, message] : overlaps) put_overlap(o, message);
    }

    // Events and overlaps past t_end are told by the slice that reaches them (in time order).
    void put_event(const ani_collision_event &e) {
        if (e.t > t_end_ || !later_events_.empty()) {
            later_events_.push_back(e);
            return;
        }
        if (sink_->event) sink_->event(sink_->context, &e);
    }

    void put_overlap(const ani_overlap &o, const std::string &message) {
        if (o.t > t_end_ || !later_overlaps_.empty()) {
            later_overlaps_.emplace_back(o, message);
            return;
        }
        if (sink_->overlap) sink_->overlap(sink_->context, &o);
        log(ANI_LOG_WARNING, message);
    }

    void report(const ani_collision_event &e) {
        if (!finite(e.normal) || !finite(e.point) || !std::isfinite(e.speed) || !std::isfinite(e.t))
            throw ani::Failure(ANI_ERR_FAILED, std::string("the contact of models '") +
                                                   name_of(scene_->models[e.a]) + "' and '" +
                                                   name_of(scene_->models[e.b]) +
                                                   "' is not finite");
        ++contacts_found_;
        put_event(e);
    }

    // Each call reports the work it did (the host adds the calls up): a slice that goes on with
    // the world reports no world or shape built.
    // The steps a bake took, or coasted, up to t_end: a bake goes on past t_end (loop(),
    // try_coast()), and the steps it took there are counted by the slice that reaches their end,
    // so that slices count what one bake counts. `first`, `last`: grid indices of coasted steps.
    struct Steps {
        int64_t first, last;
        double end;
        bool coasted;
    };

    void took(const Steps &steps) {
        uncounted_.push_back(steps);
        count_steps();
    }

    void count_steps() {
        const auto last = static_cast<int64_t>(std::floor(t_end_ / dt_ + 1e-9));
        while (!uncounted_.empty()) {
            Steps &u = uncounted_.front();
            if (!u.coasted) {
                if (u.end > t_end_ && !same_time(u.end, t_end_)) return;
                ++steps_;
                uncounted_.pop_front();
                continue;
            }
            if (u.first > last) return;
            const int64_t n = std::min(u.last, last) - u.first + 1;
            steps_ += n;
            coasted_ += n;
            u.first += n;
            if (u.first <= u.last) return;
            uncounted_.pop_front();
        }
    }

    void report_counts() {
        count_steps();
        if (!sink_->count) return;
        std::map<std::string, double> totals = counts_;
        totals["steps"] = static_cast<double>(steps_);
        totals["steps coasted"] = static_cast<double>(coasted_);
        totals["coasting checks"] = static_cast<double>(coast_checks_);
        totals["contacts"] = static_cast<double>(contacts_found_);
        totals["releases from keys"] = static_cast<double>(releases_);
        totals["segments"] = static_cast<double>(segments_);
        totals["worlds built"] = static_cast<double>(worlds_);
        totals["shapes built"] = static_cast<double>(shapes_built_);
        for (const char *name : {"sphere shapes", "box shapes", "convex hulls", "triangle meshes"})
            totals[name] += 0.0;
        for (const auto &[name, value] : totals) {
            double &said = counted_[name];
            sink_->count(sink_->context, name.c_str(), value - said);
            said = value;
        }
    }

    static std::string short_number(double x) {
        std::ostringstream out;
        out << std::setprecision(4) << (std::abs(x) < 1e-12 ? 0.0 : x);
        return out.str();
    }

    void log(ani_log_level level, const std::string &message) const {
        if (host_ && host_->log) host_->log(host_, level, kPluginId, message.c_str());
    }

    const ani_physics_scene *scene_; // this call's (the host builds it anew for each)
    double t_begin_, t_end_;         // this slice's
    const ani_bake_sink *sink_;
    const ani_host *host_;
    BakeOptions options_, requested_;
    bool with_rotation_sink_ = false;
    physics_custom::ScenePrint print_; // the scene the bake goes on with
    double dt_;
    glm::dvec3 gravity_{0.0};
    // Where Bullet's world is (t_, on or past t_end), the start of the step before (previous_),
    // the grid index of the next step's end (k_).
    double t_ = 0.0, previous_ = 0.0;
    int64_t k_ = 1;
    std::vector<uint32_t> groups_;
    std::vector<Material> materials_; // per model (read_materials)
    Filter filter_;
    std::unique_ptr<btDefaultCollisionConfiguration> config_;
    std::unique_ptr<Dispatcher> dispatcher_;
    std::unique_ptr<btDbvtBroadphase> broadphase_;
    std::unique_ptr<btSequentialImpulseConstraintSolver> solver_;
    std::unique_ptr<btDiscreteDynamicsWorld> world_;
    std::vector<Body> bodies_;
    std::vector<glm::dvec3> pivots_; // per model: what it turns about (pivot_of), 0: its origin
    std::vector<Obstacle> obstacles_;
    // The models outside Bullet's stepping: keyed over [keyed_from, keyed_to], then `track`.
    struct Fixed {
        uint32_t model;
        double keyed_from, keyed_to;
        Track track;
    };
    std::vector<Fixed> fixed_;
    std::vector<Out<ani_motion_segment>> out_;
    std::vector<Out<ani_rotation_segment>> rotation_out_;
    std::vector<ani_collision_event> later_events_;
    std::vector<std::pair<ani_overlap, std::string>> later_overlaps_;
    bool provisional_ = false;
    std::map<const ani_mesh_view *, MeshInfo> mesh_info_;
    std::set<uint32_t> described_;
    // Pairs that overlapped and move apart, let go until apart; pairs apart by the end of a step.
    std::set<PairKey> ignored_, still_overlapping_, contacts_;
    SaidInBake &reported_;
    std::set<uint32_t> switched_;
    double last_switch_ = 0.0;
    btManifoldArray manifolds_;
    std::map<std::string, double> counts_, counted_; // counted_: what earlier slices reported
    std::size_t worlds_ = 0, shapes_built_ = 0;
    std::deque<Steps> uncounted_; // steps past t_end, counted by the slice that reaches them
    int64_t taken_ = 0;           // Bullet's steps, for progress
    int64_t steps_ = 0, coasted_ = 0, coast_checks_ = 0;
    int64_t coast_wait_ = 0, coast_backoff_ = 1, coast_window_ = 64;
    std::size_t contacts_found_ = 0, releases_ = 0, segments_ = 0;
};

} // namespace

struct BakeInProgress::State {
    SaidInBake said;
    std::unique_ptr<Bake> bake; // the last slice's, to go on with
};

BakeInProgress::BakeInProgress() : state_(std::make_unique<State>()) {}
BakeInProgress::~BakeInProgress() = default;

void bake_scene(const ani_physics_scene &scene, double t_begin, double t_end,
                const ani_bake_sink &sink, const ani_host *host, const BakeOptions &options,
                BakeInProgress *in_progress) {
    install_combine_rules(); // process-wide, always the same min / max functions
    if (!in_progress) {
        SaidInBake one_bake;
        Bake(scene, t_begin, t_end, sink, host, options, one_bake).run();
        return;
    }
    auto &state = *in_progress->state_;
    try {
        if (state.bake && state.bake->continues(scene, t_begin, options, sink)) {
            state.bake->resume(scene, t_end, sink);
            return;
        }
        state.bake.reset();
        auto bake = std::make_unique<Bake>(scene, t_begin, t_end, sink, host, options, state.said);
        bake->run();
        state.bake = std::move(bake);
    } catch (...) {
        state.bake.reset(); // cancelled or failed half-way: the next bake starts afresh
        throw;
    }
}

} // namespace physics_bullet
