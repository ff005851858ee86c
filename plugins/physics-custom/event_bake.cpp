// The event-driven bake's event loop (physics.md, "Where the code is"): EventBake's constructor,
// run and resume, and the loop that takes the earliest predicted event, handles it and reports
// the motion; then bake_scene and the bake in progress between slices. The stages it calls are
// in bake_*.cpp; the types they share are event_bake_detail.hpp's.
#include "event_bake.hpp"
#include "event_bake_detail.hpp"

#include <animator/halves.hpp>

#include <limits>
#include <optional>
#include <system_error>
#include <thread>
#include <utility>

namespace physics_custom::bake {

EventBake::EventBake(const ani_physics_scene &scene, double t_begin, double t_end,
                     const ani_bake_sink &sink, const ani_host *host, const BakeOptions &options,
                     OverlapMemory &memory)
    : scene_(&scene), t_begin_(t_begin), t_end_(t_end), sink_(&sink), host_(host),
      options_(options), gravity_(vec(gravity_vector(scene.gravity, scene.down_axis))),
      memory_(memory) {
    memory_.begin(t_begin);
    set_horizon();
}

namespace {

// A large scene's print finished on a thread of its own beside the general engine's setup (it
// reads every model's description and keys, about 3.5% of a bake of 100,000 balls, all cache
// misses), asking the host for the keys directly (evaluate_keyed is [thread: any]; the keys'
// memo is the setup's). Done, its thread joined, when it goes.
class PrintBeside {
  public:
    explicit PrintBeside(ScenePrinter &printer) {
        const auto all = [&printer] { printer.step(std::numeric_limits<uint32_t>::max()); };
        try {
            thread_ = std::thread(all);
        } catch (const std::system_error &) { // no thread to be had: here, now
            all();
        }
    }
    PrintBeside(const PrintBeside &) = delete;
    PrintBeside &operator=(const PrintBeside &) = delete;
    ~PrintBeside() {
        if (thread_.joinable()) thread_.join();
    }

  private:
    std::thread thread_;
};

} // namespace

void EventBake::run() {
    forget_keyed();
    // The scene's print, for the next bake to know whether it goes on from this one: for a large
    // scene, made where a core has nothing better to do (finish_print).
    if (scene_->model_count >= ani::kWorthTwoHalves)
        printing_.emplace(*scene_);
    else
        fingerprint_ = scene_print(*scene_, [&](uint32_t m, double t, ani_model_state &s, ani_vec3 &v) {
            try {
                glm::dvec3 velocity;
                s = keyed(m, t, &velocity);
                v = ani(velocity);
                return true;
            } catch (const ani::Failure &) {
                return false;
            }
        });
    if (gas_from_scene()) { // a gas: the lane from the start, no body made (bake_gas.cpp)
        advance_to_end();   // (its print made by the lane's reporting thread while it waits)
        finish_print();
        return;
    }
    std::optional<PrintBeside> beside;
    if (printing_) beside.emplace(*printing_);
    classify();
    build_broad_phase();
    queue_ = std::make_unique<EventQueue>(bodies_.size());
    predicted_.assign(bodies_.size(), Predicted{});
    for (size_t i = 0; i < bodies_.size(); ++i)
        if (bodies_[i].active) {
            find_overlaps(static_cast<int>(i), t_begin_);
            if (!try_settle(static_cast<int>(i), t_begin_))
                try_settle_mesh(static_cast<int>(i), t_begin_);
        }
    settle_stacks(t_begin_);
    if (!enter_gas_lane())
        for (size_t i = 0; i < bodies_.size(); ++i) predict(static_cast<int>(i), t_begin_);
    beside.reset();
    finish_print();
    advance_to_end();
}

// The print begun at the start of run() finished here (what is left of it) and kept.
void EventBake::finish_print() {
    if (!printing_) return;
    printing_->step(std::numeric_limits<uint32_t>::max());
    fingerprint_ = printing_->print();
    printing_.reset();
}

// Whether a bake of `scene` from t_begin is the next slice of this one: it starts where this
// one stopped, and the scene is the same (the models, their meshes, physics flags, keyed
// spans, key times and the states at their keys; gravity). The host rebuilds the scene for
// every call, and an edit before where the bake stopped makes it bake from earlier.
bool EventBake::continues(const ani_physics_scene &scene, double t_begin,
                          const BakeOptions &options) const {
    return t_begin == t_end_ && options.broad_phase == options_.broad_phase &&
           options.gas_lane == options_.gas_lane && scene_print(scene) == fingerprint_;
}

// The next slice, [t_end of the last, t_end]: the events predicted beyond the last slice's
// end are still valid, so it goes on from them, as one bake would (issue 16: the editor's
// slices each started over, and redid the predictions and advancements of every body).
void EventBake::resume(const ani_physics_scene &scene, double t_end, const ani_bake_sink &sink) {
    scene_ = &scene;
    forget_keyed(); // its answers were the last scene's
    sink_ = &sink;
    t_begin_ = t_end_;
    t_end_ = t_end;
    set_horizon();
    for (uint32_t i = 0; i < scene_->model_count; ++i)
        if (!is_body_[i]) emit_unmoved(i);
    advance_to_end();
}

// Predictions look past the slice's end (the slices that follow use them): as far again as
// has been baked, at least 10 s, so that a bake cut into slices predicts a body again only
// a few times more than one whole bake (each time the baked span doubles).
void EventBake::set_horizon() {
    horizon_ = std::max(horizon_, t_end_ + std::max(10.0, t_end_));
}

// Processes the events up to t_end and reports every body's motion to t_end.
void EventBake::advance_to_end() {
    if (gas_ && run_gas_lane()) { // to t_end, or to an event it hands to the loop below
        report_counts();
        return;
    }
    std::size_t events_at_once = 0;
    double last_event = -kNever;
    while (!bodies_.empty() && queue_->top_time() <= t_end_) {
        const int i = static_cast<int>(queue_->top());
        // Taken, not copied: predict(i) writes its next event there at the end of handle().
        const Predicted event = std::move(predicted_[static_cast<size_t>(i)]);
        const double now = event.t;
        events_at_once = now == last_event ? events_at_once + 1 : 0;
        last_event = now;
        if (events_at_once > 100000 + 10 * bodies_.size())
            throw ani::Failure(ANI_ERR_FAILED, "models keep colliding at t = " +
                                                   std::to_string(now) + " s without moving apart");
        handle(i, event, now);
        if (sink_->progress && ++reports_ % 1024 == 0 &&
            !sink_->progress(sink_->context,
                             (now - t_begin_) / std::max(t_end_ - t_begin_, 1e-300)))
            throw ani::Failure(ANI_ERR_CANCELLED, "the bake was cancelled");
    }
    for (Body &b : bodies_) {
        if (b.keyed())
            emit_keyed(b.model, b.keyed_from, t_end_);
        else if (b.carried())
            emit_carried(b, t_end_);
        else if (b.active)
            close_segment(b, t_end_);
        if (b.spin.on) emit_spin(b, t_end_);
    }
    report_counts();
}

// ---- events ----------------------------------------------------------------------------

void EventBake::handle(int i, const Predicted &event, double now) {
    Body &b = bodies_[static_cast<size_t>(i)];
    // A body tipping over an edge meets anything, or its hinge ends: it turns freely from here,
    // and the response sees it as any other turning body (bake_hinge.cpp). Not at a contact
    // that did not happen: one predicted with a body that has changed course since (stale), or
    // an undecided one (looked at again, still hinged).
    const bool no_contact =
        (event.kind == EventKind::kBody || event.kind == EventKind::kObstacle) &&
        (event.contact.normal == glm::dvec3(0.0) ||
         (event.kind == EventKind::kBody &&
          bodies_[static_cast<size_t>(event.other)].version != event.other_version));
    if (b.hinge && event.kind != EventKind::kRecheck && event.kind != EventKind::kRelease &&
        event.kind != EventKind::kNone && !no_contact)
        unhinge(b, now);
    switch (event.kind) {
    case EventKind::kNone:
        break;
    case EventKind::kActivation: // its last key: free from here, as physics.md says
        if (b.keyed()) emit_keyed(b.model, b.keyed_from, now);
        unfile(i);
        activate(b, now, leaving_keys(b.model, now));
        b.resume_at = kNever;
        file(i, now);
        // Pairs left alone while its keys held it inside another are, now that it is free,
        // touching (physics.md): found again as it is now.
        forget_ignored(i, now);
        find_overlaps(i, now);
        if (!try_settle(i, now)) try_settle_mesh(i, now);
        break;
    case EventKind::kResume: // released at a contact, its next key takes it back
        drop(i, now);
        close_segment(b, now);
        unfile(i);
        b.mode = Body::Mode::kKeyed;
        b.keyed_from = now;
        b.resume_at = kNever;
        ++b.version;
        file(i, now);
        find_overlaps(i, now);
        break;
    case EventKind::kCell: {
        ++count_.crossings;
        grid_->remove(static_cast<uint32_t>(i), b.cell);
        b.cell[static_cast<size_t>(event.exit.axis)] += event.exit.direction;
        if (grid_->inside(b.cell)) {
            grid_->insert(static_cast<uint32_t>(i), b.cell);
        } else {
            b.in_grid = false;
            outside_.push_back(i);
        }
        break;
    }
    case EventKind::kBody: {
        Body &o = bodies_[static_cast<size_t>(event.other)];
        if (o.version != event.other_version) {
            ++count_.stale; // the other body changed course since: predict again
            break;
        }
        if (event.contact.normal == glm::dvec3(0.0)) break; // undecided: look again
        unhinge(o, now);
        // (A turning model always responds to a contact found moving in, as one against a static
        // model: they part at least at the microcollision speed, so neither is left inside the
        // other.)
        if (!event.moving_in && grazing(point_velocity(b, event.contact.point, now) -
                                            point_velocity(o, event.contact.point, now),
                                        event.contact.normal)) {
            ignore(i, event.other, now);
            break;
        }
        // One stuck to a platform is knocked off it (free where it is, it takes the blow), unless
        // the blow presses it into the platform, which takes it (held_by_support).
        if (b.carried() && !held_by_support(b, event.contact.normal)) drop(i, now);
        if (o.carried() && !held_by_support(o, -event.contact.normal)) drop(event.other, now);
        collide_bodies(i, event.other, event.contact, event.points, now);
        predict(event.other, now);
        break;
    }
    case EventKind::kObstacle:
        if (event.contact.normal == glm::dvec3(0.0)) break;
        // (A turning model always responds: it leaves at least at the microcollision speed,
        // bake_response.cpp, so it is never left inside a static model.)
        if (!b.turning() &&
            grazing(point_velocity(b, event.contact.point, now), event.contact.normal)) {
            if (!settle_on(i, event.other, event.contact.normal, now))
                ignore(i, -1 - event.other, now);
            break;
        }
        drop(i, now);
        collide_obstacle(i, obstacles_[static_cast<size_t>(event.other)], event.contact,
                         event.points, now);
        break;
    case EventKind::kRelease:
        unignore(i, event.other, now);
        unoverlap(i, event.other, now);
        break;
    case EventKind::kRecheck:
        break; // predict() rechecks
    case EventKind::kLeave:
        unsupport(b, now);
        break;
    case EventKind::kFriction:
        friction_changes(b, now, event.other == 1);
        break;
    case EventKind::kHinge: // unhinged above
        break;
    case EventKind::kCarrier: // its carrier's next key
        if (b.carried())
            carry_again(i, now);
        else
            recarry(i, now);
        break;
    case EventKind::kSettle: // the Zeno bounces' accumulation time: resting from here
        rebase(b, now);
        b.settles_at = kNever;
        break;
    }
    if (sleepers_ > 0) { // the bodies asleep on one that moved wake
        wake_riders(i, now);
        if (event.kind == EventKind::kBody) wake_riders(event.other, now);
    }
    if (riders_ > 0) { // the bodies on a carrier whose motion changed follow it
        carry_on(i, now);
        if (event.kind == EventKind::kBody) carry_on(event.other, now);
    }
    predict(i, now);
}

void EventBake::report(const ani_collision_event &e) {
    auto finite = [](const ani_vec3 &v) {
        return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
    };
    if (!finite(e.normal) || !finite(e.point) || !std::isfinite(e.speed) || !std::isfinite(e.t))
        throw ani::Failure(ANI_ERR_FAILED, std::string("the contact of models '") +
                                               name_of(scene_->models[e.a]) + "' and '" +
                                               name_of(scene_->models[e.b]) + "' is not finite");
    ++count_.collisions;
    if (sink_->event) sink_->event(sink_->context, &e);
}

// The work counted, for `animator bake --stats` (ABI 1.1 hosts).
void EventBake::report_counts() {
    if (!sink_->count) return;
    const std::pair<const char *, std::size_t> counts[] = {
        {"pair tests done", count_.done},
        {"pair tests skipped", count_.skipped},
        {"predictions", count_.predictions},
        {"stale predictions", count_.stale},
        {"cell crossings", count_.crossings},
        {"collisions", count_.collisions},
        {"conservative advancements", count_.advancements},
        {"releases from keys", count_.releases},
        {"mesh feature tests", count_.mesh_tests},
        {"tips about an edge", count_.hinges},
        {"pair predictions reused", count_.reused},
        {"bodies scanned after contacts", count_.scanned},
        {"gas lane events", count_.lane},
        {"gas lane hand-offs", count_.handoffs},
    };
    // Each slice reports its own work: the host adds them up.
    for (size_t k = 0; k < std::size(counts); ++k) {
        const double value = static_cast<double>(counts[k].second);
        sink_->count(sink_->context, counts[k].first, value - counted_[k]);
        counted_[k] = value;
    }
}

void EventBake::log_warning(const std::string &message) {
    if (host_ && host_->log) host_->log(host_, ANI_LOG_WARNING, "physics.custom", message.c_str());
}

} // namespace physics_custom::bake

namespace physics_custom {

using bake::EventBake;

struct BakeInProgress::State {
    OverlapMemory overlaps;
    std::unique_ptr<EventBake> bake; // the last slice's, to go on with
};

BakeInProgress::BakeInProgress() : state_(std::make_unique<State>()) {}
BakeInProgress::~BakeInProgress() = default;

void bake_scene(const ani_physics_scene &scene, double t_begin, double t_end,
                const ani_bake_sink &sink, const ani_host *host, const BakeOptions &options,
                BakeInProgress *in_progress) {
    if (!in_progress) {
        OverlapMemory one_bake;
        EventBake(scene, t_begin, t_end, sink, host, options, one_bake).run();
        return;
    }
    auto &state = *in_progress->state_;
    try {
        if (state.bake && state.bake->continues(scene, t_begin, options)) {
            state.bake->resume(scene, t_end, sink);
            return;
        }
        state.bake.reset();
        auto bake =
            std::make_unique<EventBake>(scene, t_begin, t_end, sink, host, options, state.overlaps);
        bake->run();
        state.bake = std::move(bake);
    } catch (...) {
        state.bake.reset(); // cancelled or failed half-way: the next bake starts afresh
        throw;
    }
}

} // namespace physics_custom
