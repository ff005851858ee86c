#include "editor/editor_session.hpp"

#include "editor/model_edits.hpp"
#include "editor/motion_paths.hpp"
#include "editor/overlap_fix.hpp"
#include "editor/time_steps.hpp"
#include "io/document_io.hpp"
#include "render/frustum.hpp"
#include "render/scene_math.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace fs = std::filesystem;

namespace animator {

namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

constexpr double kMinChunk = 1e-3; // seconds of animation

} // namespace

EditorSession::EditorSession(Environment &env)
    : env_(env), timeline_(std::make_unique<Timeline>(doc_, env.plugins)) {}

fs::path EditorSession::demo_path(const AssetPaths &assets) {
    for (const fs::path &root : assets.roots()) {
        std::error_code ec;
        if (fs::is_regular_file(root / "scenes" / "simple.lua", ec)) return root / "scenes" / "simple.lua";
    }
    return {};
}

bool EditorSession::open(const fs::path &path, std::string &error) { return load(path, path, error); }

bool EditorSession::recover(const fs::path &recovery, const fs::path &original, std::string &error) {
    // Unsaved changes to the document as it is on disk (when it was opened), else to nothing.
    Document on_disk = path_ == original && !original.empty() ? saved_ : Document();
    if (!load(recovery, original, error)) return false;
    saved_ = std::move(on_disk);
    dirty_ = true;
    return true;
}

bool EditorSession::load(const fs::path &file, const fs::path &path, std::string &error) {
    try {
        OpenedDocument opened = open_document(env_.plugins, file);
        auto timeline = std::make_unique<Timeline>(opened.document, env_.plugins);
        std::vector<std::string> ids, more, warnings = std::move(opened.warnings); // the reader's first
        for (const Model &m : opened.document.models()) ids.push_back(m.mesh);
        auto meshes = load_meshes(ids, env_.assets, path, more);
        for (std::string &w : not_said_before(std::move(more), warnings)) warnings.push_back(std::move(w));
        timeline->set_meshes(meshes);
        // Nothing can fail from here on: the new document replaces the old one whole.
        doc_ = std::move(opened.document);
        saved_ = doc_;
        path_ = path;
        export_to_path_ = path.extension() == ".ani";
        timeline_ = std::move(timeline);
        meshes_ = std::move(meshes);
        mesh_cache_.clear();
        for (size_t i = 0; i < ids.size() && i < meshes_.size(); ++i)
            if (meshes_[i]) mesh_cache_[ids[i]] = meshes_[i];
        preview_.reset(); // baked with the meshes of the document before
        warnings_ = std::move(warnings);
        history_.clear();
        selection_.clear();
        hidden_.clear(); // a view of the document before
        pinned_paths_.clear();
        last_selected_ = -1;
        drag_.reset();
        playing_ = false;
        time_ms_ = 0;
        free_view_on_ = view_started_ = false; // a new scene: the view starts from its camera
        chunk_ = 0.25;
        bake_error_.clear();
        dirty_ = false;
        ++version_;
        return true;
    } catch (const std::exception &e) {
        error = e.what();
        return false;
    }
}

void EditorSession::set_time_ms(std::int64_t ms) {
    time_ms_ = std::clamp<std::int64_t>(ms, 0, doc_.settings().max_time_ms);
}

void EditorSession::step_frames(int frames) {
    if (drag_) return; // the drag's preview is at this time
    playing_ = false;
    time_ms_ = animator::step_frames(time_ms_, frames, kStepFramesPerSecond, doc_.settings().max_time_ms);
}

void EditorSession::jump_keyframe(int direction) {
    if (drag_) return;
    playing_ = false;
    time_ms_ = neighbour_keyframe(doc_, time_ms_, direction);
}

bool EditorSession::bake_some(double budget) {
    if (!bake_error_.empty()) return false;
    const double end = max_time();
    const auto start = std::chrono::steady_clock::now();
    while (timeline_->baked_until() < end && seconds_since(start) < budget) {
        const double until = std::min(end, timeline_->baked_until() + chunk_);
        const auto slice = std::chrono::steady_clock::now();
        // A slice far over budget is given up and tried smaller (never the smallest one).
        const bool may_cancel = chunk_ > kMinChunk;
        try {
            timeline_->bake(until, [&](double) { return !may_cancel || seconds_since(slice) < 4.0 * budget; });
        } catch (const BakeCancelled &) {
            chunk_ = std::max(kMinChunk, chunk_ / 4.0);
            continue;
        } catch (const std::exception &e) {
            bake_error_ = e.what();
            return false;
        }
        const double took = seconds_since(slice);
        if (took < budget / 4.0) chunk_ *= 2.0;
        else if (took > budget) chunk_ = std::max(kMinChunk, chunk_ / 2.0);
    }
    return timeline_->baked_until() < end;
}

void EditorSession::toggle_play(double wall) {
    if (playing_) {
        playing_ = false;
        return;
    }
    if (time_ms_ >= doc_.settings().max_time_ms) time_ms_ = 0; // at the end, play from the start
    playing_ = true;
    play_from_ = time();
    play_wall_ = wall;
}

void EditorSession::tick(double wall) {
    if (!playing_) return;
    double t = play_from_ + (wall - play_wall_);
    // Real time: frames are dropped rather than slowed. Only the bake can hold playback back.
    const double baked = timeline_->baked_until();
    if (t > baked && baked < max_time()) {
        play_wall_ += t - baked;
        t = baked;
    }
    if (t >= max_time()) {
        t = max_time();
        playing_ = false;
    }
    time_ms_ = std::clamp<std::int64_t>(static_cast<std::int64_t>(std::floor(t * 1000.0)), 0,
                                        doc_.settings().max_time_ms);
}

void EditorSession::click(int model, bool add) {
    if (model < 0 || model >= static_cast<int>(doc_.models().size())) {
        if (!add) {
            selection_.clear();
            last_selected_ = -1;
        }
        return;
    }
    if (!add) {
        selection_ = {model};
        last_selected_ = model;
    } else if (selection_.erase(model)) {
        if (last_selected_ == model) last_selected_ = selection_.empty() ? -1 : *selection_.rbegin();
    } else {
        selection_.insert(model);
        last_selected_ = model;
    }
}

bool EditorSession::shown(int model) const {
    const auto &models = doc_.models();
    // Parents come before their children, so the walk up ends.
    for (int m = model; m >= 0 && m < static_cast<int>(models.size()); m = models[static_cast<size_t>(m)].parent)
        if (hidden_.count(m)) return false;
    return true;
}

void EditorSession::set_hidden(int model, bool hidden) {
    if (model < 0 || model >= static_cast<int>(doc_.models().size())) return;
    if (!hidden) {
        hidden_.erase(model);
        return;
    }
    hidden_.insert(model);
    // What cannot be seen is not left selected (a drag would move it unseen), as in Blender.
    for (int m : hidden_models()) selection_.erase(m);
    if (last_selected_ >= 0 && !selection_.count(last_selected_))
        last_selected_ = selection_.empty() ? -1 : *selection_.rbegin();
}

std::set<int> EditorSession::hidden_models() const {
    std::set<int> out;
    if (hidden_.empty()) return out;
    for (int m = 0; m < static_cast<int>(doc_.models().size()); ++m)
        if (!shown(m)) out.insert(m);
    return out;
}

bool EditorSession::set_field(const std::set<int> &models, ModelField field, const Model &from, std::string *error) {
    try {
        auto edit = field_edit(doc_, models, field, from);
        return !edit || perform(std::move(edit), error);
    } catch (const std::exception &e) {
        if (error) *error = e.what();
        return false;
    }
}

bool EditorSession::rename_model(int index, const std::string &name, std::string *error) {
    if (index < 0 || index >= static_cast<int>(doc_.models().size())) {
        if (error) *error = "no model " + std::to_string(index);
        return false;
    }
    const std::string trimmed = trim_name(name);
    if (const std::string problem = check_rename(doc_, index, trimmed); !problem.empty()) {
        if (error) *error = problem;
        return false;
    }
    Model m = doc_.models()[static_cast<size_t>(index)];
    m.name = trimmed;
    return set_model(index, m, error);
}

Frame EditorSession::frame() const {
    Frame f = timeline_->evaluate(std::min(time(), timeline_->baked_until()));
    if (!drag_) return f;
    if (mode_ == EditMode::Camera) {
        f.camera = drag_camera(drag_->camera, drag_->button, drag_->delta, drag_->metres_per_pixel);
        return f;
    }
    for (size_t i = 0; i < drag_->models.size(); ++i) {
        const int m = drag_->models[i].first;
        const ModelState s = dragged_state(*drag_, i);
        ModelPose &pose = f.models[static_cast<size_t>(m)];
        pose.center = s.center;
        pose.angles = s.angles;
        pose.scale = s.scale;
    }
    return f;
}

ModelState EditorSession::state_now(int model, const Frame &frame) const {
    const int k = keyframe_here();
    if (k >= 0) {
        const auto &state = doc_.keyframes()[static_cast<size_t>(k)].states[static_cast<size_t>(model)];
        if (state) return *state;
    }
    const ModelPose &pose = frame.models[static_cast<size_t>(model)];
    ModelState s;
    s.center = pose.center;
    s.angles = pose.angles;
    s.scale = pose.scale;
    return s;
}

double EditorSession::view_depth(const Frame &frame) const {
    // The depth of what is dragged: the selected models' centers, else the scene's.
    const glm::dvec3 forward = frame.camera.rotation * glm::dvec3(0, 0, -1);
    double sum = 0.0;
    int n = 0;
    const bool models = mode_ != EditMode::Camera && !selection_.empty();
    for (size_t m = 0; m < frame.models.size(); ++m) {
        if (models && !selection_.count(static_cast<int>(m))) continue;
        sum += glm::dot(frame.models[m].center - frame.camera.position, forward);
        ++n;
    }
    const double depth = n > 0 ? sum / n : 10.0;
    return depth > 0.1 ? depth : 10.0;
}

void EditorSession::begin_drag(DragButton button, int viewport_height) {
    if (playing_ || (mode_ != EditMode::Camera && selection_.empty())) return;
    const Frame f = timeline_->evaluate(std::min(time(), timeline_->baked_until()));
    Drag d{button, viewport_height, glm::dvec2(0.0), {}, f.camera,
           metres_per_pixel(view_depth(f), f.camera.fov_degrees, viewport_height), std::nullopt};
    if (mode_ != EditMode::Camera)
        for (int m : selection_) d.models.emplace_back(m, state_now(m, f));
    drag_ = d;
}

void EditorSession::update_drag(glm::dvec2 delta) {
    if (!drag_ || drag_->delta == delta) return;
    drag_->delta = delta;
    update_gizmo_change();
    preview_stale_ = true;
}

ModelState EditorSession::dragged_state(const Drag &d, size_t i) const { return dragged_clamp(d, i).state; }

JointClamp EditorSession::dragged_clamp(const Drag &d, size_t i) const {
    const auto &[model, start] = d.models[i];
    const ModelState s = d.gizmo ? apply_gizmo_change(start, d.gizmo->parents[i], d.gizmo->change)
                                 : drag_model(start, mode_, d.button, d.delta, d.metres_per_pixel);
    // A turn stops at a joint's range (joint_clamp.hpp); a move or a scale, turning no angle,
    // comes back as it is.
    return clamp_to_joint(doc_.models()[static_cast<size_t>(model)], start, s);
}

std::string EditorSession::joint_note() const {
    if (!drag_ || mode_ == EditMode::Camera) return "";
    std::string note;
    for (size_t i = 0; i < drag_->models.size(); ++i) {
        const std::string said =
            joint_stop_text(doc_.models()[static_cast<size_t>(drag_->models[i].first)], dragged_clamp(*drag_, i));
        if (!said.empty()) note += (note.empty() ? "" : "; ") + said;
    }
    return note;
}

void EditorSession::update_gizmo_change() {
    if (!drag_ || !drag_->gizmo) return;
    auto &g = *drag_->gizmo;
    // A ring's turn goes on from the last one, so it counts past half a turn.
    g.change = gizmo_drag(g.gizmo, g.view, g.handle, g.start, g.start + drag_->delta, g.snap, g.change.degrees);
}

void EditorSession::set_snap(bool on) {
    if (!drag_ || !drag_->gizmo || drag_->gizmo->snap == on) return;
    drag_->gizmo->snap = on;
    update_gizmo_change();
    preview_stale_ = true;
}

GizmoView EditorSession::gizmo_view(int width, int height) const {
    GizmoView v;
    v.camera = shown_frame().camera;
    v.width = std::max(width, 1);
    v.height = std::max(height, 1);
    return v;
}

std::optional<Gizmo> EditorSession::gizmo(const GizmoView &view) const {
    if (mode_ == EditMode::Camera || playing_ || last_selected_ < 0 || !selection_.count(last_selected_))
        return std::nullopt;
    const Frame f = frame();
    return place_gizmo(view, mode_, gizmo_target(doc_.models(), f.models, last_selected_));
}

bool EditorSession::begin_gizmo_drag(glm::dvec2 cursor, const GizmoView &view) {
    if (drag_) return false;
    const auto g = gizmo(view);
    if (!g) return false;
    const GizmoHandle handle = gizmo_hit(*g, view, cursor);
    if (handle == GizmoHandle::None) return false;
    begin_drag(DragButton::Left, view.height);
    if (!drag_) return false;
    const Frame f = frame();
    const std::vector<glm::dmat3> parents = parent_matrices(doc_.models(), f.models);
    Drag::OnGizmo on{*g, view, handle, cursor, false, {}, {}};
    on.change.mode = mode_;
    for (const auto &[m, start] : drag_->models) on.parents.push_back(parents[static_cast<size_t>(m)]);
    drag_->gizmo = std::move(on);
    update_gizmo_change();
    return true;
}

std::optional<Document> EditorSession::dragged_document() const {
    if (!drag_ || mode_ == EditMode::Camera) return std::nullopt;
    std::vector<std::pair<int, ModelState>> after;
    for (size_t i = 0; i < drag_->models.size(); ++i) {
        const ModelState s = dragged_state(*drag_, i);
        if (!(s == drag_->models[i].second)) after.emplace_back(drag_->models[i].first, s);
    }
    if (after.empty()) return std::nullopt;
    Document doc = doc_;
    try {
        transform_edit(after, std::nullopt)->apply(doc);
    } catch (const std::exception &) {
        return std::nullopt; // the drop would be refused too; the paths stay as baked
    }
    return doc;
}

void EditorSession::pin_path(int model, bool on) {
    if (on) pinned_paths_.insert(model);
    else pinned_paths_.erase(model);
}

std::vector<int> EditorSession::path_models() const {
    std::set<int> shown = pinned_paths_;
    if (paths_on_) shown.insert(selection_.begin(), selection_.end());
    std::vector<int> out;
    for (int m : shown)
        if (m >= 0 && m < static_cast<int>(doc_.models().size())) out.push_back(m);
    return out;
}

std::vector<MotionPath> EditorSession::motion_paths() const {
    const std::vector<int> models = path_models();
    if (models.empty()) return {};
    // During a drag, the dragged document's own bake (as far as it has gone).
    if (drag_ && preview_ && preview_doc_ && !preview_stale_)
        return sample_motion_paths(*preview_doc_, *preview_, models, max_time(), kStepFramesPerSecond);
    return sample_motion_paths(doc_, *timeline_, models, max_time(), kStepFramesPerSecond);
}

bool EditorSession::preview_some(double budget) {
    if (!drag_ || path_models().empty()) return false;
    if (preview_stale_) {
        preview_stale_ = false;
        ++preview_version_;
        preview_doc_ = dragged_document();
        if (!preview_doc_) return false;
        try {
            if (preview_ && preview_->backend_id() != timeline_->backend_id()) preview_.reset();
            if (!preview_) {
                preview_ = std::make_unique<Timeline>(*preview_doc_, env_.plugins, timeline_->backend_override());
                preview_->set_meshes(meshes_);
            } else {
                preview_->edit(*preview_doc_);
            }
        } catch (const std::exception &) {
            preview_.reset();
            preview_doc_.reset();
            return false;
        }
    }
    if (!preview_ || !preview_doc_) return false;
    const double end = max_time();
    const auto start = std::chrono::steady_clock::now();
    while (preview_->baked_until() < end && seconds_since(start) < budget) {
        try {
            // Slices of the main bake's size (bake_some() keeps it to its budget).
            preview_->bake(std::min(end, preview_->baked_until() + chunk_));
        } catch (const std::exception &) {
            preview_.reset();
            preview_doc_.reset();
            return false;
        }
    }
    return preview_->baked_until() < end;
}

std::unique_ptr<Edit> EditorSession::transform_edit(const std::vector<std::pair<int, ModelState>> &models,
                                                    const std::optional<CameraState> &camera) const {
    if (keyframe_here() < 0) {
        // A transformation at a time with no keyframe creates one, keying only what moved.
        Keyframe k;
        k.time_ms = time_ms_;
        k.states.resize(doc_.models().size());
        for (const auto &[m, s] : models) k.states[static_cast<size_t>(m)] = s;
        k.camera = camera;
        return std::make_unique<AddKeyframeEdit>(std::move(k));
    }
    std::vector<std::unique_ptr<Edit>> edits;
    for (const auto &[m, s] : models) edits.push_back(std::make_unique<SetStateEdit>(time_ms_, m, s));
    if (camera) edits.push_back(std::make_unique<SetCameraEdit>(time_ms_, camera));
    if (edits.size() == 1) return std::move(edits.front());
    return std::make_unique<CompositeEdit>("transform models", std::move(edits));
}

ModelState EditorSession::state_at_time(int model) const {
    if (drag_)
        for (size_t i = 0; i < drag_->models.size(); ++i)
            if (drag_->models[i].first == model) return dragged_state(*drag_, i);
    return state_now(model, frame());
}

bool EditorSession::key_states(const std::vector<std::pair<int, ModelState>> &states, std::string *error) {
    if (drag_ || states.empty()) return false;
    for (const auto &[m, s] : states)
        if (m < 0 || m >= static_cast<int>(doc_.models().size())) {
            if (error) *error = "no model " + std::to_string(m);
            return false;
        }
    return perform(transform_edit(states, std::nullopt), error);
}

void EditorSession::end_drag() {
    if (!drag_) return;
    ended_joint_note_ = joint_note();
    const Drag d = *drag_;
    drag_.reset();
    if (d.delta == glm::dvec2(0.0)) return;
    if (mode_ == EditMode::Camera) {
        perform(transform_edit({}, drag_camera(d.camera, d.button, d.delta, d.metres_per_pixel)));
        return;
    }
    std::vector<std::pair<int, ModelState>> after;
    for (size_t i = 0; i < d.models.size(); ++i) {
        const ModelState s = dragged_state(d, i);
        if (!(s == d.models[i].second)) after.emplace_back(d.models[i].first, s);
    }
    if (!after.empty()) perform(transform_edit(after, std::nullopt));
}

void EditorSession::scroll(double notches) {
    if (playing_ || drag_ || mode_ != EditMode::Camera || notches == 0.0) return;
    const Frame f = frame();
    perform(transform_edit({}, scroll_camera(f.camera, notches, view_depth(f))));
}

void EditorSession::set_free_view(bool on) {
    if (on && !view_started_) {
        const Frame f = frame();
        view_ = free_view_from(f.camera, view_depth(f));
        view_started_ = true;
    }
    free_view_on_ = on;
}

void EditorSession::set_view(const FreeView &view) {
    set_free_view(true);
    view_ = view;
}

std::vector<Sphere> EditorSession::model_spheres(bool selected_only) const {
    const Frame f = frame();
    std::vector<glm::dmat4> world;
    world_matrices(doc_.models(), f.models, world);
    apply_rest_shapes(doc_.models(), world);
    std::vector<Sphere> spheres;
    const std::set<int> hidden = hidden_models();
    for (size_t m = 0; m < world.size() && m < meshes_.size(); ++m) {
        if (!meshes_[m] || (selected_only && !selection_.count(static_cast<int>(m)))) continue;
        if (hidden.count(static_cast<int>(m))) continue; // not drawn: nothing to frame
        Sphere s;
        transform_bounding_sphere(world[m], meshes_[m]->bound_center, meshes_[m]->bound_radius, s.center, s.radius);
        spheres.push_back(s);
    }
    return spheres;
}

bool EditorSession::frame_models(bool selected_only, double aspect) {
    const std::vector<Sphere> spheres = model_spheres(selected_only);
    if (spheres.empty()) return false;
    set_free_view(true);
    view_ = frame_spheres(view_, spheres, aspect);
    return true;
}

Frame EditorSession::shown_frame() const {
    Frame f = frame();
    if (free_view_on_) f.camera = free_view_camera(view_);
    return f;
}

std::int64_t EditorSession::history_key() const {
    // Away from a keyframe only the document's stack applies: no keyframe is at -1 ms.
    return keyframe_here() >= 0 ? time_ms_ : -1;
}

void EditorSession::changed() {
    ++version_;
    dirty_ = !(doc_ == saved_);
    if (time_ms_ > doc_.settings().max_time_ms) time_ms_ = doc_.settings().max_time_ms;
    bake_error_.clear();
    chunk_ = 0.25;
}

bool EditorSession::perform(std::unique_ptr<Edit> edit, std::string *error) {
    const std::vector<std::string> names = model_names();
    try {
        // Tried on a copy first: the timeline may refuse the result (a missing plugin), and then
        // neither the document nor the history changes.
        Document trial = doc_;
        edit->apply(trial);
        timeline_->edit(trial);
        history_.perform(doc_, std::move(edit));
    } catch (const std::exception &e) {
        if (error) *error = e.what();
        return false;
    }
    changed();
    if (names.size() != doc_.models().size()) follow_models(names);
    return true;
}

bool EditorSession::set_settings(const Settings &settings, std::string *error) {
    if (settings == doc_.settings()) return true;
    return perform(std::make_unique<SetSettingsEdit>(settings), error);
}

bool EditorSession::set_model(int index, const Model &model, std::string *error) {
    if (model == doc_.models()[static_cast<size_t>(index)]) return true;
    return perform(std::make_unique<SetModelEdit>(index, model), error);
}

bool EditorSession::delete_keyframe(std::int64_t time_ms, std::string *error) {
    return perform(std::make_unique<DeleteKeyframeEdit>(time_ms), error);
}

std::set<int> EditorSession::overlapping_models() const {
    return animator::overlapping_models(timeline_->overlaps(), doc_.models().size());
}

bool EditorSession::lift_out(std::size_t index, std::string *error) {
    const auto &found = timeline_->overlaps();
    if (index >= found.size()) {
        if (error) *error = "no such overlap";
        return false;
    }
    const auto lift = plan_lift_out(doc_, meshes_, found[index], error);
    return lift && perform(lift_out_edit(*lift), error);
}

bool EditorSession::undo() {
    const std::vector<std::string> names = model_names();
    if (drag_ || !history_.undo(doc_, history_key())) return false;
    follow_document();
    if (names.size() != doc_.models().size()) follow_models(names);
    return true;
}

bool EditorSession::redo() {
    const std::vector<std::string> names = model_names();
    if (drag_ || !history_.redo(doc_, history_key())) return false;
    follow_document();
    if (names.size() != doc_.models().size()) follow_models(names);
    return true;
}

std::vector<std::string> EditorSession::model_names() const {
    std::vector<std::string> names;
    for (const Model &m : doc_.models()) names.push_back(m.name);
    return names;
}

void EditorSession::follow_models(const std::vector<std::string> &names) {
    // Each model's state goes where its name is now (gone with a model deleted).
    const auto now = [&](int before) {
        return before >= 0 && before < static_cast<int>(names.size()) ? doc_.find_model(names[static_cast<size_t>(before)]) : -1;
    };
    const auto follow = [&](std::set<int> &models) {
        std::set<int> moved;
        for (int m : models)
            if (const int n = now(m); n >= 0) moved.insert(n);
        models = std::move(moved);
    };
    follow(selection_);
    follow(hidden_);
    follow(pinned_paths_);
    last_selected_ = now(last_selected_);
    if (last_selected_ < 0 && !selection_.empty()) last_selected_ = *selection_.rbegin();
    meshes_.clear();
    for (const Model &m : doc_.models()) {
        std::string warning;
        meshes_.push_back(m.mesh.empty() ? nullptr : mesh_of(m.mesh, &warning));
        if (!warning.empty()) warnings_.push_back(warning);
    }
    timeline_->set_meshes(meshes_);
    // The drag's bake had the models before.
    preview_.reset();
    preview_doc_.reset();
    ++version_;
}

std::shared_ptr<const Mesh> EditorSession::mesh_of(const std::string &id, std::string *error) {
    if (const auto it = mesh_cache_.find(id); it != mesh_cache_.end() && it->second) return it->second;
    std::vector<std::string> warnings;
    auto mesh = load_meshes({id}, env_.assets, path_, warnings).front();
    if (!mesh) {
        if (error) *error = warnings.empty() ? "mesh '" + id + "' could not be read" : warnings.front();
        return nullptr;
    }
    mesh_cache_[id] = mesh;
    return mesh;
}

bool EditorSession::add_model(const std::string &mesh_id, std::string &message) {
    if (drag_) {
        message = "cannot add a model during a drag";
        return false;
    }
    std::string error;
    // A mesh that is not there is refused (a scene's may load as a stand-in, a new model may not).
    if (!env_.assets.resolve(ANI_ASSET_MESH, mesh_id, path_)) {
        message = "cannot add a model: mesh '" + mesh_id + "' not found (" +
                  env_.assets.searched(ANI_ASSET_MESH, mesh_id, path_) + ")";
        return false;
    }
    if (!mesh_of(mesh_id, &error)) {
        message = "cannot add a model: " + error;
        return false;
    }
    Model model;
    model.name = unique_model_name(doc_, name_from_mesh(mesh_id));
    model.mesh = mesh_id;
    // Where the view looks: the free view's pivot, else along the camera's view at the depth of
    // the scene (the mean of the models' depths; 10 m in an empty one).
    ModelState state;
    if (free_view_on_) {
        state.center = view_.pivot;
    } else {
        const Frame f = frame();
        std::vector<glm::dmat4> world;
        world_matrices(doc_.models(), f.models, world);
        const glm::dvec3 forward = f.camera.rotation * glm::dvec3(0, 0, -1);
        double sum = 0.0;
        for (const glm::dmat4 &w : world) sum += glm::dot(glm::dvec3(w[3]) - f.camera.position, forward);
        double depth = world.empty() ? 10.0 : sum / static_cast<double>(world.size());
        if (!(depth > 0.1)) depth = 10.0;
        state.center = f.camera.position + depth * forward;
    }
    if (!perform(std::make_unique<AddModelEdit>(model, state), &error)) {
        message = "cannot add '" + model.name + "': " + error;
        return false;
    }
    const int index = doc_.find_model(model.name);
    selection_ = {index};
    last_selected_ = index;
    message = "added '" + model.name + "'";
    return true;
}

bool EditorSession::add_model_from_asset(const std::string &id, std::string &message) {
    return add_model(id, message);
}

bool EditorSession::add_model_from_file(const fs::path &file, std::string &message) {
    std::error_code ec;
    if (!fs::is_regular_file(file, ec)) {
        message = "cannot add a model: " + file.string() + ": no such mesh file";
        return false;
    }
    return add_model(mesh_reference(file, path_, export_to_path_), message);
}

bool EditorSession::duplicate_selected(std::string &message) {
    if (drag_) {
        message = "cannot duplicate during a drag";
        return false;
    }
    if (selection_.empty()) {
        message = "nothing selected to duplicate";
        return false;
    }
    // The copies move apart from their originals as the models are placed at t = 0.
    const Frame f = timeline_->evaluate(0.0);
    std::vector<glm::dmat4> world;
    world_matrices(doc_.models(), f.models, world);
    std::string error;
    try {
        const std::vector<ModelCopy> copies = plan_copies(doc_, meshes_, world, selection_);
        Document after = with_copies(doc_, copies);
        const std::set<int> selected = selection_;
        const int last = last_selected_;
        if (!perform(std::make_unique<ReplaceDocumentEdit>("duplicate models", doc_, std::move(after)), &error)) {
            message = "cannot duplicate: " + error;
            return false;
        }
        // The copies of the selected models are selected, the last one's copy last.
        selection_.clear();
        last_selected_ = -1;
        for (const ModelCopy &c : copies)
            if (selected.count(c.original)) selection_.insert(doc_.find_model(c.name));
        for (const ModelCopy &c : copies)
            if (c.original == last) last_selected_ = doc_.find_model(c.name);
        if (last_selected_ < 0 && !selection_.empty()) last_selected_ = *selection_.rbegin();
        if (selected.size() == 1) {
            const std::string original = doc_.models()[static_cast<size_t>(*selected.begin())].name;
            message = "duplicated '" + original + "' as '" + copies.front().name + "'";
            if (copies.size() > 1)
                message += copies.size() == 2 ? " with the model under it" : " with the " + std::to_string(copies.size() - 1) + " models under it";
        } else {
            message = "duplicated " + std::to_string(selected.size()) + " models (" + std::to_string(copies.size()) + " copies)";
        }
        return true;
    } catch (const std::exception &e) {
        message = std::string("cannot duplicate: ") + e.what();
        return false;
    }
}

std::set<int> EditorSession::models_to_delete() const { return with_descendants(doc_, selection_); }

bool EditorSession::delete_selected(std::string &message) {
    if (drag_) {
        message = "cannot delete during a drag";
        return false;
    }
    if (selection_.empty()) {
        message = "nothing selected to delete";
        return false;
    }
    const std::set<int> deleted = models_to_delete();
    const std::string phrase = deletion_phrase(doc_, selection_, deleted);
    std::string error;
    try {
        Document after = without_models(doc_, deleted);
        if (!perform(std::make_unique<ReplaceDocumentEdit>("delete models", doc_, std::move(after)), &error)) {
            message = "cannot delete " + phrase + ": " + error;
            return false;
        }
    } catch (const std::exception &e) {
        message = "cannot delete " + phrase + ": " + e.what();
        return false;
    }
    message = "deleted " + phrase;
    return true;
}

void EditorSession::follow_document() {
    changed();
    // The document went back to a state the timeline accepted before; should a plugin it names
    // have gone since, the document is still kept and the bake says why it cannot follow.
    try {
        timeline_->edit(doc_);
    } catch (const std::exception &e) {
        bake_error_ = e.what();
    }
}

bool EditorSession::use_backend(const std::string &id, std::string &error) {
    try {
        timeline_->use_backend(id);
    } catch (const std::exception &e) {
        error = e.what();
        return false;
    }
    bake_error_.clear();
    chunk_ = 0.25;
    return true;
}

EditorSession::ExportResult EditorSession::export_animation() {
    ExportResult r;
    fs::path target = path_;
    std::string note;
    if (!export_to_path_) {
        // Never over a file the user did not open: animations/new.ani, or a fresh name beside it.
        const fs::path folder = "animations";
        target = folder / "new.ani";
        std::error_code ec;
        for (int n = 1; fs::exists(target, ec); ++n) target = folder / ("new-" + std::to_string(n) + ".ani");
        if (target.filename() != "new.ani") note = " (animations/new.ani exists and was not opened here, so a fresh name was chosen)";
        fs::create_directories(folder, ec);
    }
    r.path = target;
    try {
        save_document(env_.plugins, doc_, target);
    } catch (const std::exception &e) {
        r.message = std::string("export failed, the old file is unchanged: ") + e.what();
        return r;
    }
    r.ok = true;
    r.message = "exported to " + target.string() + note;
    path_ = target;
    export_to_path_ = true;
    saved_ = doc_;
    dirty_ = false;
    return r;
}

EditorSession::ExportResult EditorSession::save_as(const fs::path &target) {
    ExportResult r;
    r.path = target;
    try {
        save_document(env_.plugins, doc_, target); // a temporary file beside it, renamed over it
    } catch (const std::exception &e) {
        r.message = std::string("save failed (a file there is left as it was): ") + e.what();
        return r;
    }
    r.ok = true;
    r.message = "saved as " + target.string();
    path_ = target;
    export_to_path_ = true;
    saved_ = doc_;
    dirty_ = false;
    return r;
}

bool EditorSession::new_from_scene(const fs::path &scene, std::string &error) {
    // Read as the scene (its meshes found beside it), then a document with no file of its own.
    if (!load(scene, scene, error)) return false;
    path_.clear();
    export_to_path_ = false;
    return true;
}

std::string EditorSession::title() const {
    const std::string name = path_.empty() ? "untitled" : path_.filename().string();
    return "animator - " + name + (dirty_ ? " *" : "");
}

} // namespace animator
