// The session's answers to keys familiar from Blender and Maya (editor_session.hpp): I and
// ALT+I key and unkey the selection at the current time; A / ALT+A select all or none; H / ALT+H
// hide the selection or show everything.
#include "editor/editor_session.hpp"

#include "document/key_edits.hpp"

#include <cstdio>

namespace animator {

namespace {

std::string seconds(double t) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3f s", t);
    return text;
}

std::string said(bool *ok, bool good, std::string text) {
    if (ok) *ok = good;
    return text;
}

// How far a segment turns an axis from `from` to `to` with the next key's `turn`
// (docs/interpolation.md: 0 the shorter way, < 0 counter-clockwise, > 0 clockwise).
double segment_delta(double from, double to, double turn) {
    double d = to - from;
    if (turn == 0.0) {
        if (d > 180.0) d -= 360.0;
        else if (d < -180.0) d += 360.0;
    } else if (turn < 0.0) {
        if (d < 0.0) d += 360.0;
    } else if (d > 0.0) {
        d -= 360.0;
    }
    return d;
}

// A key put inside a segment turns each axis the way the segment did, so the motion after it
// goes on as before (without a direction, a turn of more than half a circle would go back the
// shorter way).
glm::dvec3 turn_inside(const Document &doc, int model, std::int64_t time_ms) {
    const Keyframe *before = nullptr, *after = nullptr;
    for (const Keyframe *k : doc.keys_of(model)) {
        if (k->time_ms < time_ms) before = k;
        else if (k->time_ms > time_ms && !after) after = k;
    }
    glm::dvec3 turn(0.0);
    if (!before || !after) return turn; // after the last key the keys no longer turn it
    const ModelState &a = *before->states[static_cast<size_t>(model)], &b = *after->states[static_cast<size_t>(model)];
    for (int i = 0; i < 3; ++i) {
        const double d = segment_delta(a.angles[i], b.angles[i], b.turn[i]);
        turn[i] = d > 0.0 ? -1.0 : d < 0.0 ? 1.0 : 0.0;
    }
    return turn;
}

} // namespace

std::string EditorSession::insert_keys(bool *ok) {
    if (drag_) return said(ok, false, "let go of the drag first");
    playing_ = false;
    const bool camera = selection_.empty();
    // Where the models are now: as the view shows them once the bake has reached this time.
    if (timeline_->baked_until() < time()) {
        try {
            timeline_->bake(time());
        } catch (const std::exception &e) {
            return said(ok, false, std::string("cannot key: the bake failed: ") + e.what());
        }
    }
    const Frame f = frame();
    const int k = keyframe_here();
    const Keyframe *here = k >= 0 ? &doc_.keyframes()[static_cast<size_t>(k)] : nullptr;
    std::vector<std::pair<int, ModelState>> models;
    std::optional<CameraState> cam;
    std::string names;
    if (camera) {
        if (here && here->camera) return said(ok, true, "the camera is already keyed at " + seconds(time()));
        cam = f.camera;
        names = "the camera";
    } else {
        for (int m : selection_) {
            if (here && here->states[static_cast<size_t>(m)]) continue; // keyed here already
            ModelState state = state_now(m, f);
            state.turn = turn_inside(doc_, m, time_ms_);
            models.emplace_back(m, state);
            names += (names.empty() ? "'" : ", '") + doc_.models()[static_cast<size_t>(m)].name + "'";
        }
        if (models.empty())
            return said(ok, true, std::string(selection_.size() == 1 ? "it is" : "they are") + " already keyed at " +
                                      seconds(time()));
    }
    std::string error;
    if (!perform(transform_edit(models, cam), &error)) return said(ok, false, "cannot key: " + error);
    return said(ok, true, "keyed " + names + " at " + seconds(time()) + " (u undoes it)");
}

std::string EditorSession::delete_keys_here(bool *ok) {
    if (drag_) return said(ok, false, "let go of the drag first");
    playing_ = false;
    const int k = keyframe_here();
    if (k < 0) return said(ok, true, "no keyframe at " + seconds(time()));
    if (time_ms_ == 0) return said(ok, false, "the keys at 0 s are the initial placement: they stay");
    const Keyframe &here = doc_.keyframes()[static_cast<size_t>(k)];
    std::vector<KeyRef> keys;
    std::string names;
    if (selection_.empty()) {
        if (here.camera) {
            keys.push_back({time_ms_, KeyRef::kCamera});
            names = "the camera's key";
        }
    } else {
        for (int m : selection_)
            if (here.states[static_cast<size_t>(m)]) {
                keys.push_back({time_ms_, m});
                names += (names.empty() ? "'" : ", '") + doc_.models()[static_cast<size_t>(m)].name + "'";
            }
        if (!keys.empty()) names += keys.size() == 1 ? "'s key" : "'s keys";
    }
    if (keys.empty()) return said(ok, true, "nothing selected is keyed at " + seconds(time()));
    std::string error;
    if (!perform(std::make_unique<DeleteKeysEdit>(std::move(keys)), &error))
        return said(ok, false, "cannot delete the keys: " + error);
    return said(ok, true, "deleted " + names + " at " + seconds(time()) + " (u undoes it)");
}

void EditorSession::select_all() {
    selection_.clear();
    for (int m = 0; m < static_cast<int>(doc_.models().size()); ++m)
        if (shown(m)) selection_.insert(m);
    if (!selection_.count(last_selected_)) last_selected_ = selection_.empty() ? -1 : *selection_.rbegin();
}

int EditorSession::hide_selected() {
    const std::set<int> chosen = selection_;
    for (int m : chosen) set_hidden(m, true);
    return static_cast<int>(chosen.size());
}

int EditorSession::show_all() {
    const int n = static_cast<int>(hidden_.size());
    hidden_.clear();
    return n;
}

} // namespace animator
