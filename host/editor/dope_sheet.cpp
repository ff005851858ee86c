#include "editor/dope_sheet.hpp"

#include "editor/time_steps.hpp"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>

namespace animator {

namespace {

// Opaque colours, so the end-to-end tests can find them (tests/editor/cases_dope_sheet.py).
const ImU32 kRulerBg = IM_COL32(28, 30, 36, 255);
const ImU32 kRowBg[2] = {IM_COL32(36, 38, 46, 255), IM_COL32(44, 46, 55, 255)};
const ImU32 kPastEnd = IM_COL32(18, 18, 22, 255);
const ImU32 kTick = IM_COL32(140, 142, 152, 255);
const ImU32 kTickText = IM_COL32(190, 192, 200, 255);
const ImU32 kFree = IM_COL32(50, 100, 160, 255);     // released, flying
const ImU32 kRest = IM_COL32(60, 78, 98, 255);       // released, at rest
const ImU32 kCarried = IM_COL32(70, 130, 110, 255);  // released, carried by another model
const ImU32 kCollision = IM_COL32(240, 60, 200, 255); // the motion paths' colour for collisions
const ImU32 kKey = IM_COL32(215, 215, 215, 255);
const ImU32 kKeyMoving = IM_COL32(255, 165, 30, 110); // where dragged keys were
const ImU32 kKeySelected = IM_COL32(255, 165, 30, 255);
const ImU32 kKeyOutline = IM_COL32(10, 10, 12, 255);
const ImU32 kPlayhead = IM_COL32(235, 70, 50, 255);
const ImU32 kBoxFill = IM_COL32(255, 165, 30, 40);
const ImU32 kBoxEdge = IM_COL32(255, 165, 30, 220);
const ImU32 kSelectedName = IM_COL32(255, 220, 110, 255);

ImVec2 v2(double x, double y) { return ImVec2(static_cast<float>(x), static_cast<float>(y)); }

void diamond(ImDrawList *dl, double x, double y, double r, ImU32 fill) {
    const ImVec2 top = v2(x, y - r), right = v2(x + r, y), bottom = v2(x, y + r), left = v2(x - r, y);
    dl->AddQuadFilled(top, right, bottom, left, fill);
    dl->AddQuad(top, right, bottom, left, kKeyOutline, 1.0f);
}

std::string count_keys(std::size_t n) { return std::to_string(n) + (n == 1 ? " key" : " keys"); }

std::string signed_seconds(std::int64_t ms) {
    char text[48];
    std::snprintf(text, sizeof text, "%+.3f s", static_cast<double>(ms) / 1000.0);
    return text;
}

} // namespace

std::optional<DopeSheet::Result> DopeSheet::take_message() {
    std::optional<Result> m = std::move(message_);
    message_.reset();
    return m;
}

std::vector<KeyRef> DopeSheet::moving() const {
    std::vector<KeyRef> out;
    for (const KeyRef &k : selection_)
        if (k.time_ms != 0) out.push_back(k);
    return out;
}

void DopeSheet::refresh(const EditorSession &session) {
    if (session.path() != path_) {
        // Another file: its keys are others, and its length may differ.
        path_ = session.path();
        selection_.clear();
        fitted_ = true;
        scroll_ = 0.0;
    }
    if (keys_version_ != session.version()) {
        keys_version_ = session.version();
        // Models added, copied or deleted: a key's model index may now be another model's.
        if (session.document().models().size() != keys_models_) selection_.clear();
        keys_models_ = session.document().models().size();
        keys_ = all_keys(session.document());
        // Keys that went (deleted, undone) leave the selection.
        for (auto it = selection_.begin(); it != selection_.end();)
            it = has_key(session.document(), *it) ? std::next(it) : selection_.erase(it);
    }
    const Timeline &timeline = session.timeline();
    if (spans_version_ != session.version() || spans_baked_ != timeline.baked_until() ||
        spans_backend_ != timeline.backend_id()) {
        spans_version_ = session.version();
        spans_baked_ = timeline.baked_until();
        spans_backend_ = timeline.backend_id();
        const int models = static_cast<int>(session.document().models().size());
        spans_.assign(static_cast<size_t>(models), {});
        for (int m = 0; m < models; ++m) spans_[static_cast<size_t>(m)] = released_spans(timeline.segments(m));
    }
}

PanelPlace DopeSheet::draw(EditorSession &session, const ScreenRect &rect) {
    // Docked: across the bottom, or collapsed to its title bar at the window's bottom edge.
    const double title = ImGui::GetFrameHeight();
    const double top = collapsed_ ? rect.y + rect.height - title : rect.y;
    ImGui::SetNextWindowPos(v2(rect.x, top), ImGuiCond_Always);
    ImGui::SetNextWindowSize(v2(rect.width, rect.height), ImGuiCond_Always);
    const ImGuiWindowFlags flags = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoScrollbar |
                                   ImGuiWindowFlags_NoScrollWithMouse;
    const bool open = ImGui::Begin("Timeline", nullptr, flags);
    const ImVec2 pos = ImGui::GetWindowPos(), size = ImGui::GetWindowSize();
    PanelPlace place{{pos.x, pos.y, size.x, size.y}, ImGui::IsWindowCollapsed(), true};
    collapsed_ = place.collapsed;
    if (!open) {
        gesture_ = Gesture::None;
        ImGui::End();
        return place;
    }
    refresh(session);

    const Document &doc = session.document();
    const double fps = kStepFramesPerSecond, max_s = session.max_time();
    const ImVec2 p0 = ImGui::GetCursorScreenPos(), avail = ImGui::GetContentRegionAvail();
    const ScreenRect content{p0.x, p0.y, std::max(1.0f, avail.x), std::max(1.0f, avail.y)};
    const int rows = static_cast<int>(doc.models().size()) + 1;
    {
        const DopeSheetLayout probe(content, rows, view_);
        view_ = fitted_ ? fit_view(max_s, probe.track_width()) : clamp_view(view_, max_s, probe.track_width(), fps);
        // Playing past what is shown turns the page.
        const DopeSheetLayout now(content, rows, view_);
        const double x = now.x_of(session.time());
        if (!fitted_ && session.playing() && (x > now.track_x1() || x < now.track_x0())) {
            view_.start_s = session.time() - 0.1 * now.track_width() / view_.pixels_per_second;
            view_ = clamp_view(view_, max_s, now.track_width(), fps);
        }
        scroll_ = std::clamp(scroll_, 0.0, DopeSheetLayout(content, rows, view_).max_scroll());
    }
    ImGui::InvisibleButton("##timeline", v2(content.width, content.height),
                           ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonMiddle);
    handle_mouse(session, DopeSheetLayout(content, rows, view_, scroll_));
    const DopeSheetLayout layout(content, rows, view_, scroll_);
    tooltip(session, layout);
    const DopeSheetMetrics &m = layout.metrics();

    ImDrawList *dl = ImGui::GetWindowDrawList();
    const ScreenRect area = layout.rows_area(), tracks = layout.tracks(), ruler = layout.ruler();
    const double right = content.x + content.width, bottom = area.y + area.height;
    const double names_right = content.x + m.label_width;
    const double row_h = m.row_height;
    dl->PushClipRect(v2(content.x, content.y), v2(right, content.y + content.height), true);

    // The rows: their backgrounds, then in the tracks what the bake says, then the keys.
    dl->PushClipRect(v2(area.x, area.y), v2(right, bottom), true);
    for (int r = 0; r < rows; ++r) {
        const double y = layout.row_top(r);
        if (y + row_h < area.y || y > bottom) continue;
        dl->AddRectFilled(v2(content.x, y), v2(right, y + row_h), kRowBg[r % 2]);
    }
    dl->PopClipRect();
    dl->PushClipRect(v2(tracks.x, tracks.y), v2(right, bottom), true);
    const double end_x = layout.x_of(max_s);
    if (end_x < right) dl->AddRectFilled(v2(std::max(tracks.x, end_x), area.y), v2(right, bottom), kPastEnd);
    for (size_t model = 0; model < spans_.size(); ++model) {
        const double y = layout.row_top(DopeSheetLayout::row_of(static_cast<int>(model)));
        if (y + row_h < area.y || y > bottom) continue;
        for (const ReleasedSpan &s : spans_[model]) {
            const double x0 = std::max(tracks.x, layout.x_of(s.t0)), x1 = std::min(right, layout.x_of(s.t1));
            if (x1 <= x0) continue;
            dl->AddRectFilled(v2(x0, y + 2), v2(std::max(x1, x0 + 1), y + row_h - 2), s.motion == ANI_MOTION_FREE      ? kFree
                                                                                       : s.motion == ANI_MOTION_CARRIED ? kCarried
                                                                                                                        : kRest);
        }
    }
    for (const EventTick &t : event_ticks(layout, session.timeline().events(), static_cast<int>(doc.models().size()))) {
        const double y = layout.row_top(t.row);
        dl->AddLine(v2(t.x, y + 1), v2(t.x, y + row_h - 1), kCollision, 2.0f);
    }
    // The playhead's line under the keys (they stay readable at the current time).
    const double px = layout.x_of(session.time());
    const bool playhead = px >= tracks.x && px <= right;
    if (playhead) dl->AddLine(v2(px, area.y), v2(px, bottom), kPlayhead, 2.0f);
    const bool dragging = gesture_ == Gesture::MoveKeys && grabbed_.time_ms != 0;
    const double r = layout.diamond_radius();
    for (const KeyRef &k : keys_) {
        const bool selected = selection_.count(k) > 0;
        const double y = layout.key_y(k);
        if (y + r < area.y || y - r > bottom) continue;
        if (dragging && selected && k.time_ms != 0) {
            diamond(dl, layout.key_x(k), y, r, kKeyMoving);
            continue; // drawn where it goes, below
        }
        diamond(dl, layout.key_x(k), y, r, selected ? kKeySelected : kKey);
    }
    if (dragging)
        for (const KeyRef &k : moving())
            diamond(dl, layout.key_x({k.time_ms + offset_ms_, k.model}), layout.key_y(k), r, kKeySelected);
    dl->PopClipRect();

    // The names, the selected models' brighter.
    dl->PushClipRect(v2(content.x, area.y), v2(names_right - 4, bottom), true);
    const std::set<int> &chosen = session.selection();
    for (int row = 0; row < rows; ++row) {
        const double y = layout.row_top(row);
        if (y + row_h < area.y || y > bottom) continue;
        const int model = DopeSheetLayout::model_of(row);
        const std::string &name = model < 0 ? std::string("Camera") : doc.models()[static_cast<size_t>(model)].name;
        const ImU32 colour = model >= 0 && chosen.count(model) ? kSelectedName : ImGui::GetColorU32(ImGuiCol_Text);
        dl->AddText(v2(content.x + 4, y + (row_h - ImGui::GetFontSize()) / 2), colour, name.c_str());
    }
    dl->PopClipRect();
    dl->AddLine(v2(names_right, content.y), v2(names_right, bottom), kTick, 1.0f);

    // The ruler: frames and seconds; over the names, the current time.
    dl->AddRectFilled(v2(ruler.x, ruler.y), v2(right, ruler.y + ruler.height), kRulerBg);
    dl->PushClipRect(v2(ruler.x, ruler.y), v2(right, ruler.y + ruler.height), true);
    for (RulerTick t : ruler_ticks(layout, max_s, fps)) {
        t.x = std::floor(t.x + 0.5); // on a whole pixel (ImGui centres 1 px lines on its middle)
        if (t.major) {
            dl->AddLine(v2(t.x, ruler.y), v2(t.x, ruler.y + ruler.height), kTick, 1.0f);
            // A label that would be cut at the right end is left out.
            if (t.x + 3 + ImGui::CalcTextSize(t.label.c_str()).x <= right)
                dl->AddText(v2(t.x + 3, ruler.y + 3), kTickText, t.label.c_str());
        } else {
            dl->AddLine(v2(t.x, ruler.y + ruler.height - 5), v2(t.x, ruler.y + ruler.height), kTick, 1.0f);
        }
    }
    dl->PopClipRect();
    {
        char now[64];
        const std::int64_t ms = session.time_ms();
        const double frame = static_cast<double>(ms) * fps / 1000.0;
        if (std::abs(frame - std::round(frame)) < 1e-6)
            std::snprintf(now, sizeof now, "%.3f s  f%lld", static_cast<double>(ms) / 1000.0, std::llround(frame));
        else
            std::snprintf(now, sizeof now, "%.3f s", static_cast<double>(ms) / 1000.0);
        dl->AddText(v2(content.x + 4, ruler.y + 3), kTickText, now);
    }

    // The playhead's handle on the ruler.
    if (playhead) {
        dl->PushClipRect(v2(tracks.x, content.y), v2(right, bottom), true);
        dl->AddLine(v2(px, ruler.y), v2(px, ruler.y + ruler.height), kPlayhead, 2.0f);
        dl->AddTriangleFilled(v2(px - 6, ruler.y), v2(px + 6, ruler.y), v2(px, ruler.y + 8), kPlayhead);
        dl->PopClipRect();
    }
    if (gesture_ == Gesture::Box) {
        const ImVec2 mouse = ImGui::GetIO().MousePos;
        const ImVec2 a = v2(std::min<double>(press_x_, mouse.x), std::min<double>(press_y_, mouse.y));
        const ImVec2 b = v2(std::max<double>(press_x_, mouse.x), std::max<double>(press_y_, mouse.y));
        dl->AddRectFilled(a, b, kBoxFill);
        dl->AddRect(a, b, kBoxEdge);
    }
    dl->PopClipRect();
    ImGui::End();
    return place;
}

// What the part under the mouse does, while no gesture is under way: a key (whose, when, and
// how to move it), the ruler (scrub), a row's name (select its keys), the tracks (box-select).
void DopeSheet::tooltip(const EditorSession &session, const DopeSheetLayout &layout) const {
    if (!ImGui::IsItemHovered() || ImGui::IsItemActive()) return;
    const ImGuiIO &io = ImGui::GetIO();
    const double mx = io.MousePos.x, my = io.MousePos.y;
    const ScreenRect ruler = layout.ruler();
    const auto name_of = [&](int model) {
        return model == KeyRef::kCamera ? std::string("the camera")
                                        : "'" + session.document().models()[static_cast<size_t>(model)].name + "'";
    };
    if (my < ruler.y + ruler.height) {
        if (mx >= ruler.x)
            ImGui::SetTooltip("The ruler, in seconds and frames: click or drag to move the playhead (scrub).");
        else
            ImGui::SetTooltip("The Timeline: a row per model (the camera's first), a diamond per key.\n"
                              "Wheel zooms, SHIFT+wheel or a middle drag pans; over the names the wheel scrolls the rows.");
    } else if (auto key = layout.key_at(keys_, mx, my)) {
        ImGui::SetTooltip("%s's key at %.3f s: click selects it (SHIFT adds, CTRL toggles), a drag retimes the\n"
                          "selected keys (one edit), DELETE removes them, CTRL+C / CTRL+V copy them to the playhead.",
                          name_of(key->model).c_str(), static_cast<double>(key->time_ms) / 1000.0);
    } else if (mx < ruler.x) {
        const int row = layout.row_at(my);
        if (row >= 0 && row < layout.rows())
            ImGui::SetTooltip("%s: click selects all its keys (SHIFT adds, CTRL toggles).",
                              name_of(DopeSheetLayout::model_of(row)).c_str());
        else
            ImGui::SetTooltip("The Timeline's rows: the wheel scrolls them.");
    } else {
        ImGui::SetTooltip("Drag a box to select keys (SHIFT adds); wheel zooms, SHIFT+wheel or a middle drag pans.\n"
                          "Shaded: where a model is free of its keys (physics). Ticks: its collisions.");
    }
}

void DopeSheet::handle_mouse(EditorSession &session, const DopeSheetLayout &layout) {
    const ImGuiIO &io = ImGui::GetIO();
    const double mx = io.MousePos.x, my = io.MousePos.y;
    const double fps = kStepFramesPerSecond, max_s = session.max_time();
    const std::int64_t max_ms = session.document().settings().max_time_ms;
    const double names_right = layout.rect().x + layout.metrics().label_width;

    // The wheel: zooms about the pointer; with SHIFT (or sideways) it pans; over the names it
    // scrolls the rows.
    if (ImGui::IsItemHovered() && (io.MouseWheel != 0.0f || io.MouseWheelH != 0.0f)) {
        if (mx < names_right && io.MouseWheel != 0.0f) {
            scroll_ = std::clamp(scroll_ - io.MouseWheel * layout.metrics().row_height, 0.0, layout.max_scroll());
        } else if (io.KeyShift || io.MouseWheelH != 0.0f) {
            const double notches = io.KeyShift ? -io.MouseWheel : -io.MouseWheelH;
            view_ = pan_view(layout, notches * 0.1 * layout.track_width(), max_s, fps);
            fitted_ = false;
        } else {
            view_ = zoom_view(layout, mx, io.MouseWheel, max_s, fps);
            fitted_ = false;
        }
        fitted_ = fitted_ || view_.pixels_per_second <= fit_view(max_s, layout.track_width()).pixels_per_second * (1 + 1e-9);
    }

    if (ImGui::IsItemActivated()) {
        press_x_ = mx;
        press_y_ = my;
        press_view_ = view_;
        press_toggle_ = io.KeyCtrl;
        press_add_ = io.KeyShift;
        offset_ms_ = 0;
        gesture_ = Gesture::None;
        const ScreenRect ruler = layout.ruler();
        if (ImGui::IsMouseClicked(ImGuiMouseButton_Middle)) {
            gesture_ = Gesture::Pan;
        } else if (my < ruler.y + ruler.height) {
            if (mx >= ruler.x) gesture_ = Gesture::Scrub;
        } else if (auto key = layout.key_at(keys_, mx, my)) {
            grabbed_ = *key;
            if (press_toggle_) {
                if (!selection_.erase(*key)) selection_.insert(*key);
            } else {
                if (press_add_) selection_.insert(*key);
                else if (!selection_.count(*key)) selection_ = {*key};
                gesture_ = Gesture::PressKey;
            }
        } else if (mx < names_right) {
            // A row's name selects its keys.
            const int row = layout.row_at(my);
            if (!press_toggle_ && !press_add_) selection_.clear();
            for (const KeyRef &k : keys_)
                if (row >= 0 && DopeSheetLayout::row_of(k.model) == row) selection_.insert(k);
        } else {
            gesture_ = Gesture::Box;
        }
    }

    if (ImGui::IsItemActive()) {
        switch (gesture_) {
        case Gesture::Scrub:
            if (!session.dragging()) {
                session.pause();
                const double x = std::clamp(mx, layout.track_x0(), layout.track_x1());
                session.set_time_ms(snap_to_frame(layout.time_at(x), fps, max_ms));
            }
            break;
        case Gesture::PressKey:
            if (std::abs(mx - press_x_) < 3.0) break;
            gesture_ = Gesture::MoveKeys;
            [[fallthrough]];
        case Gesture::MoveKeys:
            offset_ms_ = retime_offset(layout, grabbed_, moving(), press_x_, mx, fps, max_ms);
            break;
        case Gesture::Pan:
            view_ = pan_view(DopeSheetLayout(layout.rect(), layout.rows(), press_view_, scroll_), press_x_ - mx, max_s, fps);
            fitted_ = false;
            break;
        default: break;
        }
    }

    if (ImGui::IsItemDeactivated()) {
        switch (gesture_) {
        case Gesture::MoveKeys: retime(session); break;
        case Gesture::PressKey:
            if (!press_add_) selection_ = {grabbed_}; // a click on one of several selected keys
            break;
        case Gesture::Box: {
            if (!press_toggle_ && !press_add_) selection_.clear();
            if (std::abs(mx - press_x_) < 3.0 && std::abs(my - press_y_) < 3.0) break; // a click on nothing
            for (const KeyRef &k : layout.keys_in_box(keys_, press_x_, press_y_, mx, my))
                if (press_toggle_ && selection_.count(k)) selection_.erase(k);
                else selection_.insert(k);
            break;
        }
        default: break;
        }
        gesture_ = Gesture::None;
    }
}

void DopeSheet::retime(EditorSession &session) {
    const std::vector<KeyRef> keys = moving();
    if (grabbed_.time_ms == 0) {
        message_ = Result{false, "the keys at t = 0 are the initial placement: they stay"};
        return;
    }
    if (keys.empty() || offset_ms_ == 0) return;
    auto edit = std::make_unique<RetimeKeysEdit>(keys, offset_ms_);
    const RetimeKeysEdit *done = edit.get();
    std::string error;
    if (!session.perform(std::move(edit), &error)) {
        message_ = Result{false, "could not retime the keys: " + error};
        return;
    }
    std::set<KeyRef> now;
    for (const KeyRef &k : selection_)
        if (k.time_ms == 0) now.insert(k);
    for (const KeyRef &k : done->result()) now.insert(k); // the history keeps the edit
    selection_ = now;
    message_ = Result{true, "retimed " + count_keys(keys.size()) + " by " + signed_seconds(offset_ms_)};
}

DopeSheet::Result DopeSheet::delete_selected(EditorSession &session) {
    std::vector<KeyRef> keys = moving();
    const bool initial = keys.size() < selection_.size();
    if (keys.empty())
        return {false, initial ? "the keys at t = 0 are the initial placement: they cannot be deleted" : "no keys selected"};
    std::string error;
    if (!session.perform(std::make_unique<DeleteKeysEdit>(keys), &error)) return {false, "could not delete the keys: " + error};
    for (const KeyRef &k : keys) selection_.erase(k);
    return {true, "deleted " + count_keys(keys.size()) + (initial ? " (those at t = 0 stay)" : "")};
}

DopeSheet::Result DopeSheet::copy(EditorSession &session) {
    if (selection_.empty()) return {false, "no keys selected to copy"};
    clipboard_ = copy_keys(session.document(), std::vector<KeyRef>(selection_.begin(), selection_.end()));
    return {true, "copied " + count_keys(clipboard_.size()) + " (CTRL+V pastes them at the playhead)"};
}

DopeSheet::Result DopeSheet::paste(EditorSession &session) {
    if (clipboard_.empty()) return {false, "no keys copied to paste"};
    if (session.dragging()) return {false, "not while dragging"};
    auto edit = std::make_unique<PasteKeysEdit>(clipboard_, session.time_ms());
    const PasteKeysEdit *done = edit.get();
    std::string error;
    if (!session.perform(std::move(edit), &error)) return {false, "could not paste the keys: " + error};
    selection_ = std::set<KeyRef>(done->result().begin(), done->result().end());
    return {true, "pasted " + count_keys(clipboard_.size()) + " at " + std::to_string(session.time_ms()) + " ms"};
}

} // namespace animator
