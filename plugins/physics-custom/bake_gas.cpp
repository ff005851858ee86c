// The event-driven bake's gas lane (physics.md, "The gas lane"): which scenes the compact sphere
// engine (gas_lane.hpp) takes, handing it the bodies, reporting through the bake's sink, and
// taking them back when it meets an event it does not take.
#include "event_bake_detail.hpp"

#include "gas_lane.hpp"

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

// Whether every body is a sphere the lane takes, as they are at the bake's start: free with
// Dynamics and no acceleration, one radius, not turning, resting, carried, overlapping or left
// alone with anything; and the seed's elastic frictionless response between every pair of them
// and with every static model. Then the lane bakes them (from t_begin).
bool EventBake::enter_gas_lane() {
    if (!options_.gas_lane || !grid_ || !grid_->dense() || bodies_.empty() || t_begin_ < 0.0 ||
        !ignored_.empty() || !overlaps_.empty() || sleepers_ > 0 || riders_ > 0)
        return false;
    const double r = bodies_[0].radius;
    std::vector<const Material *> kinds; // the spheres' distinct materials
    for (const Body &b : bodies_) {
        if (!b.active || !b.free_sphere() || !b.in_grid || !b.dynamics || b.spin.on ||
            b.supported() || b.on_body >= 0 || b.hinge || b.settles_at < kNever ||
            b.resume_at < kNever || b.keys_end > t_begin_ || b.radius != r ||
            b.path.a != glm::dvec3(0.0) || b.free_a != glm::dvec3(0.0) || b.ignored_obstacles > 0 ||
            b.overlapped_obstacles > 0)
            return false;
        const Material &m = b.material;
        if (std::none_of(kinds.begin(), kinds.end(), [&](const Material *k) {
                return k->restitution == m.restitution && k->friction == m.friction;
            }))
            kinds.push_back(&m);
    }
    const auto seed_pair = [](const Material &a, const Material &b) {
        return combined_restitution(a.restitution, b.restitution) == 1.0 &&
               combined_friction(a.friction, b.friction) == 0.0;
    };
    for (const Material *a : kinds) {
        for (const Material *b : kinds)
            if (!seed_pair(*a, *b)) return false;
        for (const Obstacle &o : obstacles_)
            if (!seed_pair(*a, materials_[o.model])) return false;
    }
    std::vector<GasLane::Triangle> triangles;
    triangles.reserve(triangle_count_);
    for (const Obstacle &o : obstacles_)
        for (size_t k = 0; k < o.boxes.size(); ++k)
            triangles.push_back({o.corners[3 * k], o.corners[3 * k + 1], o.corners[3 * k + 2],
                                 o.normals[k], o.offsets[k], o.boxes[k], o.model});
    std::vector<GasLane::Start> spheres(bodies_.size());
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
    gas_ = std::make_unique<GasLane>(r, grid, std::move(triangles), spheres, t_begin_);
    return true;
}

// Runs the lane to the slice's end and reports every sphere's motion to there. When it stops
// before an event it does not take, the bodies go back to the general engine, which goes on
// from there (false).
bool EventBake::run_gas_lane() {
    GasSink sink(*this);
    const bool done = gas_->run(t_begin_, t_end_, sink);
    fold_gas_counts();
    if (!done) {
        leave_gas_lane(gas_->stopped_at());
        return false;
    }
    gas_->close(t_begin_, t_end_, sink);
    return true;
}

// Every sphere back in its body where the lane left it (a segment from its last contact), filed
// in the general grid and predicted from t, the time of the event the lane did not take.
void EventBake::leave_gas_lane(double t) {
    for (size_t i = 0; i < bodies_.size(); ++i) {
        Body &b = bodies_[i];
        const GasLane::Start st = gas_->state(i);
        b.t0 = st.t0;
        b.path = Path{st.p, st.v, glm::dvec3(0.0)};
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
