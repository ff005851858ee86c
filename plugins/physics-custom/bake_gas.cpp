// The event-driven bake's gas lane (physics.md, "The gas lane"): which scenes the compact sphere
// engine (gas_lane.hpp) takes, handing it the bodies, reporting through the bake's sink, and
// taking them back when it meets an event it does not take.
#include "event_bake_detail.hpp"

#include "gas_lane.hpp"
#include "sink_aside.hpp"

#include <animator/halves.hpp>

#include <exception>
#include <limits>
#include <optional>

namespace physics_custom::bake {

// What the lane reports goes out as the general engine's would: checked, counted, and the
// bake's progress asked every 1024 events.
class EventBake::GasSink final : public GasLane::Sink {
  public:
    explicit GasSink(EventBake &bake) : bake_(bake) {}
    void segment(const ani_motion_segment &s) override { bake_.emit(s); }
    void collision(const ani_collision_event &e) override { bake_.report(e); }
    void progress(double now) override {
        const ani_bake_sink &sink = *bake_.sink_;
        const double span = std::max(bake_.t_end_ - bake_.t_begin_, 1e-300);
        if (sink.progress && !sink.progress(sink.context, (now - bake_.t_begin_) / span))
            throw ani::Failure(ANI_ERR_CANCELLED, "the bake was cancelled");
    }

  private:
    EventBake &bake_;
};

namespace {

// From this many balls a gas lane's report is made on another core. The thread's start and end
// (a tenth of a millisecond) are then a small part of a bake or of an editor's slice; over the
// bench's gas the report aside took physics.custom from 0.87 to 0.93 of the reference at 100
// balls, 0.85 to 0.90 at 300, 1.04 to 1.12 at 1,000 and 0.91 to 0.99 at 3,000 (it had been
// made aside from 4,096 balls only).
constexpr std::size_t kReportAsideFrom = 64;

// Adds m to `kinds`, the distinct materials (restitution and friction) of a set of balls, unless
// one there is the same (a gas has one or few).
void add_kind(std::vector<const Material *> &kinds, const Material *m) {
    if (std::none_of(kinds.begin(), kinds.end(), [&](const Material *k) {
            return k->restitution == m->restitution && k->friction == m->friction;
        }))
        kinds.push_back(m);
}

// The seed's elastic, frictionless response between every two of the balls' materials (their
// distinct kinds) and between each of them and each wall's.
bool elastic(const std::vector<const Material *> &kinds,
             const std::vector<const Material *> &walls) {
    const auto seed_pair = [](const Material &a, const Material &b) {
        return combined_restitution(a.restitution, b.restitution) == 1.0 &&
               combined_friction(a.friction, b.friction) == 0.0;
    };
    for (const Material *a : kinds) {
        for (const Material *b : kinds)
            if (!seed_pair(*a, *b)) return false;
        for (const Material *w : walls)
            if (!seed_pair(*a, *w)) return false;
    }
    return true;
}

} // namespace

// The static models' triangles, as the lane takes them.
std::vector<GasLane::Triangle> EventBake::lane_triangles() const {
    std::vector<GasLane::Triangle> triangles;
    triangles.reserve(triangle_count_);
    for (const Obstacle &o : obstacles_)
        for (size_t k = 0; k < o.boxes.size(); ++k)
            triangles.push_back({o.corners[3 * k], o.corners[3 * k + 1], o.corners[3 * k + 2],
                                 o.normals[k], o.offsets[k], o.boxes[k], o.model});
    return triangles;
}

// Whether every body is a sphere the lane takes, as they are at the bake's start: free with
// Dynamics and one acceleration for all (gravity, or none), one radius, not turning, resting,
// carried, overlapping or left alone with anything; and the seed's elastic frictionless response
// between every pair of them and with every static model. Then the lane bakes them (from t_begin).
bool EventBake::enter_gas_lane() {
    if (!options_.gas_lane || !grid_ || !grid_->dense() || bodies_.empty() || t_begin_ < 0.0 ||
        !ignored_.empty() || !overlaps_.empty() || sleepers_ > 0 || riders_ > 0)
        return false;
    const double r = bodies_[0].radius;
    const glm::dvec3 a = bodies_[0].free_a;
    std::vector<const Material *> balls, walls;
    for (const Body &b : bodies_) {
        if (!b.active || !b.free_sphere() || !b.in_grid || !b.dynamics || b.spin.on ||
            b.supported() || b.on_body >= 0 || b.hinge || b.settles_at < kNever ||
            b.resume_at < kNever || b.keys_end > t_begin_ || b.radius != r || b.path.a != a ||
            b.free_a != a || b.ignored_obstacles > 0 || b.overlapped_obstacles > 0)
            return false;
        balls.push_back(&b.material);
    }
    for (const Obstacle &o : obstacles_) walls.push_back(&materials_[o.model]);
    if (!elastic(balls, walls)) return false;
    ani::HugeVector<GasLane::Start> spheres(bodies_.size());
    for (size_t i = 0; i < bodies_.size(); ++i) {
        const Body &b = bodies_[i];
        spheres[i] = {b.model, b.mass, b.motion, b.t0, b.path.p, b.path.v};
    }
    GasLane::Grid grid;
    grid.origin = grid_->origin();
    grid.cell = grid_->cell_size();
    grid.counts = grid_->counts();
    // The lane keeps its own cells: the general grid is emptied until the lane hands back.
    for (size_t i = 0; i < bodies_.size(); ++i) unfile(static_cast<int>(i));
    gas_ = std::make_unique<GasLane>(r, a, grid, lane_triangles(), spheres, t_begin_);
    return true;
}

// The gas lane taken straight from the scene, before any body is made (a gas of a million balls
// needs no 1 KB body record each, nor the general engine's checks of every ball): every model
// that moves is a free sphere with Dynamics, one acceleration for all and no turning, of one
// radius; every
// model with triangles that does not move is free of its keys (a static model); the seed's
// response between them all; enough spheres for the grid; and, the lane checks, every ball apart
// from the others and from the static models (not even touching them). Any of it missing: false,
// having reported nothing, and the bake goes the general way (which may still give the lane the
// gas: enter_gas_lane). The bodies are made only if the lane hands the bake back.
bool EventBake::gas_from_scene() {
    if (!options_.gas_lane || options_.broad_phase == BroadPhase::kAllPairs || t_begin_ < 0.0)
        return false;
    const uint32_t n = scene_->model_count;
    // Each model's material, kept if the lane takes the gas (at 100,000 balls 5 MB: written in
    // the halves below, not zeroed first: huge_pages.hpp).
    ani::UnwrittenVector<Material> materials(n);
    // What each half of the models finds, merged in their order: a half stops at its first model
    // that keeps the lane out (or whose values are refused), as one pass over them in order would.
    struct Part {
        std::vector<uint32_t> walls;
        std::vector<uint32_t> unmoved; // the models not balls (walls among them), in order
        ani::HugeVector<GasLane::Start> starts;
        Box region{glm::dvec3(std::numeric_limits<double>::infinity()),
                   glm::dvec3(-std::numeric_limits<double>::infinity())}; // of the balls' centres
        std::vector<const Material *> kinds; // the balls' materials (add_kind)
        double r = -1.0;
        glm::dvec3 a{0.0}; // one for all: gravity (Gravity on), or none
        bool gas = true;
        std::exception_ptr failed;
    };
    Part parts[2];
    // Whether model i leaves the gas to the lane (its findings added to `part`).
    const auto takes = [&](Part &part, uint32_t i) {
        const ani_physics_model &m = scene_->models[i];
        if (!m.desc) return false;
        materials[i] = material_of(*m.desc); // refuses values out of range, as classify
        const auto [span, free_now, movable, solid] = standing(i);
        if (!solid) { // collides with nothing: reported as it moves (emit_unmoved)
            part.unmoved.push_back(i);
            return true;
        }
        if (!free_now) return false; // keyed here: a moving wall, or a ball still on its keys
        if (!movable) {
            part.walls.push_back(i);
            part.unmoved.push_back(i);
            return true;
        }
        if (!m.desc->dynamics || materials[i].rotates) return false;
        const std::optional<double> radius = sphere_radius(i, t_begin_);
        if (!radius || (part.r >= 0.0 && *radius != part.r)) return false;
        part.r = *radius;
        const ani_motion_segment s =
            free_segment(i, *m.desc, start_of(i, t_begin_), t_begin_, t_end_, ani(gravity_));
        if (part.starts.empty()) part.a = vec(s.a);
        if (vec(s.a) != part.a) return false;
        part.starts.push_back({i, m.desc->mass, s.motion, t_begin_, vec(s.p0), vec(s.v0)});
        part.region.lo = glm::min(part.region.lo, vec(s.p0));
        part.region.hi = glm::max(part.region.hi, vec(s.p0));
        add_kind(part.kinds, &materials[i]);
        return true;
    };
    // A hundred nanoseconds or more a model, most of it waiting on its records (its description
    // alone is six cache lines): two halves at once for a large scene.
    ani::in_halves(n >= ani::kWorthTwoHalves, n, [&](std::size_t from, std::size_t to) {
        Part &part = parts[from == 0 ? 0 : 1];
        // (The first half's with room for the second's, appended to it below.)
        part.starts.reserve(from == 0 ? n : to - from);
        try {
            for (auto i = static_cast<uint32_t>(from); i < to && part.gas; ++i)
                part.gas = takes(part, i);
        } catch (...) {
            part.failed = std::current_exception();
        }
    });
    for (const Part &part : parts) {
        if (part.failed) std::rethrow_exception(part.failed);
        if (!part.gas) return false;
    }
    Part &first = parts[0], &second = parts[1];
    if (first.r >= 0.0 && second.r >= 0.0 && first.r != second.r) return false;
    const double r = first.r >= 0.0 ? first.r : second.r;
    if (!first.starts.empty() && !second.starts.empty() && first.a != second.a) return false;
    const glm::dvec3 a = first.starts.empty() ? second.a : first.a;
    std::vector<uint32_t> walls = std::move(first.walls);
    walls.insert(walls.end(), second.walls.begin(), second.walls.end());
    ani::HugeVector<GasLane::Start> starts = std::move(first.starts);
    starts.insert(starts.end(), second.starts.begin(), second.starts.end());
    if (starts.empty() ||
        (options_.broad_phase == BroadPhase::kAutomatic && starts.size() < kGridFrom))
        return false;
    std::vector<const Material *> kinds = std::move(first.kinds), wall_materials;
    for (const Material *m : second.kinds) add_kind(kinds, m);
    for (uint32_t w : walls) wall_materials.push_back(&materials[w]);
    if (!elastic(kinds, wall_materials)) return false;
    // The static models, and the grid as build_broad_phase makes it (grid_over).
    for (uint32_t w : walls) add_obstacle(w, t_begin_);
    const auto give_up = [&] {
        obstacles_.clear();
        triangle_count_ = 0;
        return false;
    };
    const Box region{glm::min(first.region.lo, second.region.lo),
                     glm::max(first.region.hi, second.region.hi)};
    auto grid = grid_over(region, 2.0 * r);
    if (!grid->dense()) return give_up();
    const GasLane::Grid geometry{grid->origin(), grid->cell_size(), grid->counts()};
    auto lane = std::make_unique<GasLane>(r, a, geometry, lane_triangles(), starts, t_begin_, true);
    if (!lane->admissible()) return give_up();
    // Taken: every other model is reported as classify reports it.
    materials_ = std::move(materials);
    is_body_.assign(n, true);
    for (const Part &part : parts)
        for (uint32_t i : part.unmoved) {
            is_body_[i] = false;
            emit_unmoved(i);
        }
    grid_ = std::move(grid);
    gas_ = std::move(lane);
    return true;
}

// Runs the lane to the slice's end and reports every sphere's motion to there. When it stops
// before an event it does not take, the bodies go back to the general engine, which goes on
// from there (false).
bool EventBake::run_gas_lane() {
    GasSink here(*this);
    // (The segments and collisions of a gas of kReportAsideFrom balls or more reported on
    // another core: sink_aside.hpp. And the scene's print, if it is being made, made there a
    // few hundred models at a time.)
    std::optional<SinkAside> aside;
    if (gas_->size() >= kReportAsideFrom) {
        std::function<bool()> print;
        if (printing_) print = [this] { return printing_->step(512); };
        aside.emplace(here, std::move(print));
    }
    GasLane::Sink &sink = aside ? static_cast<GasLane::Sink &>(*aside) : here;
    const bool done = gas_->run(t_begin_, t_end_, sink);
    if (done) gas_->close(t_begin_, t_end_, sink);
    if (aside) aside->finish();
    fold_gas_counts();
    if (!done) leave_gas_lane(gas_->stopped_at());
    return done;
}

// Every sphere back in its body where the lane left it (a segment from its last contact), filed
// in the general grid and predicted from t, the time of the event the lane did not take.
void EventBake::leave_gas_lane(double t) {
    if (bodies_.empty()) { // taken from the scene (gas_from_scene): the bodies are made now
        Reaches reaches;
        bodies_.reserve(gas_->size());
        for (size_t k = 0; k < gas_->size(); ++k) {
            bodies_.push_back(body_of(gas_->state(k).model, gas_->radius(), t_begin_, reaches));
            Body &b = bodies_.back();
            b.free_a = gas_->acceleration();
            b.mode = Body::Mode::kFree;
            b.active = true;
        }
        queue_ = std::make_unique<EventQueue>(bodies_.size());
        predicted_.assign(bodies_.size(), Predicted{});
    }
    for (size_t i = 0; i < bodies_.size(); ++i) {
        Body &b = bodies_[i];
        const GasLane::Start st = gas_->state(i);
        b.t0 = st.t0;
        b.path = Path{st.p, st.v, gas_->acceleration()};
        b.motion = st.motion;
        ++b.version;
        file(static_cast<int>(i), t);
    }
    gas_.reset();
    ++count_.handoffs;
    if (host_ && host_->log)
        host_->log(
            host_, ANI_LOG_INFO, "physics.custom",
            ("the gas lane handed the bake to the general engine at t = " + short_number(t) + " s")
                .c_str());
    for (size_t i = 0; i < bodies_.size(); ++i) predict(static_cast<int>(i), t);
}

// The lane's work counted since the last fold, into the bake's counts.
void EventBake::fold_gas_counts() {
    if (!gas_) return;
    const GasLane::Counts &c = gas_->counts();
    count_.done += c.done - gas_counted_.done;
    count_.skipped += c.skipped - gas_counted_.skipped;
    count_.predictions += c.predictions - gas_counted_.predictions;
    count_.stale += c.stale - gas_counted_.stale;
    count_.crossings += c.crossings - gas_counted_.crossings;
    count_.lane += c.events - gas_counted_.events;
    gas_counted_ = c;
}

} // namespace physics_custom::bake
