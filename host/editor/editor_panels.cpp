#include "editor/editor_panels.hpp"

#include "editor/help.hpp"
#include "editor/model_fields.hpp"
#include "editor/overlap_fix.hpp"
#include "editor/status_line.hpp"
#include "render/renderer.hpp"

#include <animator/interpolator.h>
#include <animator/shading.h>

#include <imgui.h>
#include <imgui_internal.h> // ImGuiItemFlags_MixedValue, GetActiveID
#include <imgui_stdlib.h>

#include <glm/common.hpp>

#include <algorithm>
#include <cstdarg>
#include <cstdio>
#include <iostream>

namespace animator {

namespace {

// A value widget commits when let go (a slider, a colour, a typed number) or at once (a
// checkbox, a radio button), so one gesture is one edit.
bool let_go(bool changed) { return (changed && !ImGui::IsItemActive()) || ImGui::IsItemDeactivatedAfterEdit(); }

// Where a field's values differ among the selected models (a "mixed" field), its widget says
// "(mixed)" instead of a value until it is changed; the label keeps its ID ("###").
std::string mixed_label(const char *label, bool mixed) {
    return mixed ? std::string(label) + " (mixed)###" + label : std::string(label);
}

// While a mixed slider is held (or typed into), it shows the value being set.
bool item_active(const char *label) { return ImGui::GetActiveID() == ImGui::GetID(label); }

// A dropdown of asset ids with "(none)" first; true when the choice changed.
bool asset_combo(const char *label, std::string &value, const std::vector<std::string> &ids, bool mixed = false) {
    bool changed = false;
    if (ImGui::BeginCombo(label, mixed ? "(mixed)" : value.empty() ? "(none)" : value.c_str())) {
        // Mixed, any choice is a change: it goes to every selected model.
        if (ImGui::Selectable("(none)", !mixed && value.empty())) {
            changed = mixed || !value.empty();
            value.clear();
        }
        for (const std::string &id : ids)
            if (ImGui::Selectable(id.c_str(), !mixed && id == value)) {
                changed = mixed || id != value;
                value = id;
            }
        ImGui::EndCombo();
    }
    return changed;
}

// A colour as three numbers and a swatch. Colours may exceed 1 (a bright light, a material that
// takes more than the light gives): the numbers are not clamped to 1 (HDR), only kept >= 0.
bool colour(const char *label, glm::dvec3 &c, bool mixed = false) {
    float rgb[3] = {static_cast<float>(c.x), static_cast<float>(c.y), static_cast<float>(c.z)};
    const bool changed = ImGui::ColorEdit3(mixed_label(label, mixed).c_str(), rgb,
                                           ImGuiColorEditFlags_HDR | ImGuiColorEditFlags_Float);
    if (changed) c = glm::max(glm::dvec3(rgb[0], rgb[1], rgb[2]), glm::dvec3(0.0));
    return changed;
}

bool slider(const char *label, double &value, double lo, double hi, const char *format = "%.3f",
            ImGuiSliderFlags flags = 0, bool mixed = false) {
    if (mixed && !item_active(label)) format = "(mixed)";
    return ImGui::SliderScalar(label, ImGuiDataType_Double, &value, &lo, &hi, format, flags);
}

// Three numbers dragged (or CTRL+clicked and typed), as Blender's vector fields.
bool vector3(const char *label, glm::dvec3 &v, bool mixed = false) {
    double xyz[3] = {v.x, v.y, v.z};
    const char *format = mixed && !item_active(label) ? "(mixed)" : "%.3f";
    const bool changed = ImGui::DragScalarN(label, ImGuiDataType_Double, xyz, 3, 0.05f, nullptr, nullptr, format);
    if (changed) v = glm::dvec3(xyz[0], xyz[1], xyz[2]);
    return changed;
}

// A checkbox that shows a dash when its value differs among the selected models; clicked then,
// it ticks (for all of them).
bool mixed_checkbox(const char *label, bool &value, bool mixed) {
    ImGui::PushItemFlag(ImGuiItemFlags_MixedValue, mixed);
    const bool changed = ImGui::Checkbox(label, &value);
    ImGui::PopItemFlag();
    if (changed && mixed) value = true;
    return changed;
}

// A dialog's keys: Enter confirms (only where that is harmless), Esc cancels. Read from ImGui,
// which gets keys one change a frame (editor_app.cpp), so a quick press is still seen.
bool enter_pressed() {
    return ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Enter), false) ||
           ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_KeyPadEnter), false);
}
bool escape_pressed() { return ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape), false); }

// What the control just drawn does, and its key, shown while the mouse rests on it (also when
// it is disabled, so it can say why). Every control has one: tests/session/tooltips_test.cpp
// sweeps the panels for a control without.
void tip(const char *format, ...) IM_FMTARGS(1);
void tip(const char *format, ...) {
    if (!ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled)) return;
    va_list args;
    va_start(args, format);
    ImGui::SetTooltipV(format, args);
    va_end(args);
}

// The window being drawn: where it is, and whether only its title bar shows.
PanelPlace current_place() {
    const ImVec2 pos = ImGui::GetWindowPos(), size = ImGui::GetWindowSize();
    return {{pos.x, pos.y, size.x, size.y}, ImGui::IsWindowCollapsed()};
}

std::string time_label(std::int64_t ms) {
    char text[64];
    std::snprintf(text, sizeof text, "t = %lld ms", static_cast<long long>(ms));
    return text;
}

} // namespace

void Panels::say(const std::string &message, bool error) {
    message_ = message;
    message_error_ = error;
    (error ? std::cerr : std::cout) << "animator: " << message << std::endl; // a test reads it
}

void Panels::show_error(const std::string &title, const std::string &message) {
    error_title_ = title;
    error_text_ = message;
    error_pending_ = true;
    say(title + ": " + message, true);
}

void Panels::ask_to_recover(const std::string &when, const std::string &detail) {
    recover_when_ = when;
    recover_detail_ = detail;
    recover_asked_ = true;
    std::string line = detail;
    std::replace(line.begin(), line.end(), '\n', ' ');
    std::cout << "animator: Recover unsaved work from " << when << "? " << line << std::endl; // a test reads it
}

std::optional<bool> Panels::take_recover_answer() {
    auto answer = recover_answer_;
    recover_answer_.reset();
    return answer;
}

void Panels::commit(bool ok, const std::string &error) {
    if (!ok) say(error, true);
    else message_.clear(); // the last action went well: an older message no longer applies
}

void Panels::undo(EditorSession &session) {
    if (session.undo()) say("undone");
    else say("nothing to undo here");
}

void Panels::redo(EditorSession &session) {
    if (session.redo()) say("redone");
    else say("nothing to redo here");
}

void Panels::draw(EditorSession &session, float width, float height, double wall) {
    // Drafts follow the document unless the user is in the middle of changing one.
    if (!ImGui::IsAnyItemActive() || draft_version_ != session.version()) {
        settings_draft_ = session.document().settings();
        model_draft_.reset();
        draft_version_ = session.version();
    }
    places_.clear();
    animator_panel(session, height, wall);
    timeline(session, width, height);
    // The Model Interface stays above the Timeline.
    const PanelPlace &bottom = places_.back();
    const float above = bottom.collapsed ? height : static_cast<float>(bottom.rect.y);
    if (session.last_selected() >= 0) model_panel(session, width, height, above);
    if (lights_open_) lights_window(session);
    dialogs(session);
    output_.draw(session);
    draw_help_overlay(&help_open_, width, height);
    // After the dialogs, so the frame a dialog opens in already counts.
    dialog_open_ = ImGui::IsPopupOpen("", ImGuiPopupFlags_AnyPopupId | ImGuiPopupFlags_AnyPopupLevel);
}

void Panels::timeline(EditorSession &session, float width, float height) {
    const ScreenRect rect = bottom_panel_rect(width, height, bottom_panel_height(height), places_);
    places_.push_back(dope_sheet_.draw(session, rect));
    if (auto m = dope_sheet_.take_message()) say(*m);
}

bool Panels::delete_keys(EditorSession &session) {
    if (!dope_sheet_.has_selection()) return false;
    say(dope_sheet_.delete_selected(session));
    return true;
}

void Panels::copy_keys(EditorSession &session) { say(dope_sheet_.copy(session)); }

void Panels::duplicate_models(EditorSession &session) {
    models_.duplicate(session, [this](const std::string &m, bool error) { say(m, error); });
}

void Panels::ask_delete_models(const EditorSession &session) {
    models_.ask_delete(session, [this](const std::string &m, bool error) { say(m, error); });
}

void Panels::paste_keys(EditorSession &session) { say(dope_sheet_.paste(session)); }

void Panels::load_view_settings() {
    std::string warning;
    view_ = animator::load_view_settings(view_settings_path(), &warning);
    if (!warning.empty()) say(warning, true);
}

void Panels::view_menu() {
    if (!ImGui::BeginMenu("View")) return;
    const ViewSettings before = view_;
    if (ImGui::MenuItem("Shadows", nullptr, view_.shadows)) view_.shadows = !view_.shadows;
    tip("Shadows cast by the scene's lights (shadow maps with soft edges); off draws faster");
    if (ImGui::MenuItem("Reflections of other models", nullptr, view_.reflections))
        view_.reflections = !view_.reflections;
    tip("Reflective and transparent models show the models around them (a cube map each, drawn "
        "every frame); off: the skybox only, and faster");
    // Each submenu's tip on its item only while it is closed (at the mouse it covered the
    // choices, as File > Open Recent's would), and on each of its choices.
    const char *const samples_tip =
        "Smooth edges in the 3D view: samples per pixel (multisampling); Off draws faster";
    const bool samples_open = ImGui::BeginMenu("Anti-aliasing");
    if (!samples_open) tip("%s", samples_tip);
    if (samples_open) {
        for (const int samples : {1, 2, 4, 8}) {
            const std::string label =
                samples == 1 ? std::string("Off") : std::to_string(samples) + "x";
            if (ImGui::MenuItem(label.c_str(), nullptr, view_.msaa == samples))
                view_.msaa = samples;
            tip("%s", samples_tip);
        }
        ImGui::EndMenu();
    }
    const char *const resolution_tip =
        "The share of the 3D view's pixels drawn along each side: below 100% the scene is drawn\n"
        "smaller and stretched onto the view, softer but faster (Blender's viewport resolution)";
    const bool resolution_open = ImGui::BeginMenu("Resolution");
    if (!resolution_open) tip("%s", resolution_tip);
    if (resolution_open) {
        for (const int percent : kResolutions) {
            const std::string label = std::to_string(percent) + "%";
            if (ImGui::MenuItem(label.c_str(), nullptr, view_.resolution == percent))
                view_.resolution = percent;
            tip("%s", resolution_tip);
        }
        ImGui::EndMenu();
    }
    ImGui::EndMenu();
    if (view_ != before) {
        std::string error;
        if (!save_view_settings(view_settings_path(), view_, &error)) say(error, true);
    }
}

void Panels::animator_panel(EditorSession &session, float height, double wall) {
    ImGui::SetNextWindowPos(ImVec2(10, 10), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(340, std::min(height - 20.0f, 760.0f)), ImGuiCond_FirstUseEver);
    // A menu bar where the title bar was: both are a line of text and the frame padding tall,
    // so every widget below stays where it was. The panel's name goes to the bar's right end.
    const bool open = ImGui::Begin("Animator Interface", nullptr, ImGuiWindowFlags_MenuBar | ImGuiWindowFlags_NoTitleBar);
    places_.push_back(current_place());
    if (!open) {
        ImGui::End();
        return;
    }
    if (ImGui::BeginMenuBar()) {
        files_.menu(session, [&] {
            if (ImGui::MenuItem("Add Model...", "SHIFT+A")) models_.ask_add();
            tip("Add a model from a mesh on the asset path or any mesh file (OBJ, PLY, STL, glTF);\n"
                "File > Open... with a mesh file adds it too");
            ImGui::Separator();
            if (ImGui::MenuItem("Render...", "CTRL+F12")) open_render();
            tip("Render the animation as it is now (unsaved changes too) to PNG frames or a video, with a\n"
                "progress bar and Cancel");
            if (ImGui::MenuItem("Export...", "CTRL+SHIFT+E")) open_export();
            tip("Export the motion trace (CSV), the soundtrack (WAV) or glTF (.glb) of the animation as it is now");
            if (ImGui::MenuItem("Export glTF (.glb)...")) output_.open_gltf_export();
            tip("Export the models, materials, camera, lights and motion as glTF 2.0 for Blender, game engines\n"
                "and web viewers (free flight and bounces exact: docs/export.md)");
        });
        if (ImGui::MenuItem("Lights", nullptr, lights_open_)) lights_open_ = !lights_open_;
        tip("The scene's lights and its ambient light (saved in the animation): opens or closes their window");
        view_menu();
        const char *name = "Animator Interface";
        const float right = ImGui::GetWindowContentRegionMax().x - ImGui::CalcTextSize(name).x;
        if (right > ImGui::GetCursorPosX() + 8.0f) {
            ImGui::SetCursorPosX(right);
            ImGui::TextDisabled("%s", name);
        }
        ImGui::EndMenuBar();
    }
    const Document &doc = session.document();
    Settings &s = *settings_draft_;

    int mode = static_cast<int>(session.mode());
    ImGui::TextUnformatted("Mode");
    ImGui::RadioButton("Camera", &mode, 0);
    tip("Mouse drags in the view move the animated camera and key it at the current time:\n"
        "left pans, middle turns it about its view axis, right turns it; the wheel moves it along its view.");
    ImGui::SameLine();
    ImGui::RadioButton("Rotate", &mode, 1);
    tip("Drags turn the selected models and key them at the current time: middle drag turns about y,\n"
        "right drag about x (up and down) and z (sideways). A left click selects.");
    ImGui::SameLine();
    ImGui::RadioButton("Translate", &mode, 2);
    tip("Drags move the selected models and key them at the current time: right drag moves them in x and y\n"
        "with the cursor, middle drag in z. A left click selects.");
    ImGui::SameLine();
    ImGui::RadioButton("Scale", &mode, 3);
    tip("Drags scale the selected models and key them at the current time: right drag scales x and y,\n"
        "middle drag z (right and up grow). A left click selects.");
    session.set_mode(static_cast<EditMode>(mode));

    // The Time slider scrubs: it moves the scene, it is not an edit.
    std::int64_t t = session.time_ms();
    const std::int64_t zero = 0, max_ms = doc.settings().max_time_ms;
    if (ImGui::SliderScalar("Time (ms)", ImGuiDataType_S64, &t, &zero, &max_ms, "%lld")) {
        session.pause();
        session.set_time_ms(t);
    }
    tip("The current time: drag to scrub (it pauses playback), CTRL+click to type a time.\n"
        "Left/Right step a frame, Up/Down jump to the previous/next keyframe. Not an edit.");
    if (ImGui::Button(session.playing() ? "Pause" : "Play")) session.toggle_play(wall);
    tip(session.playing() ? "Pause playback here (SPACE)" : "Play from the current time in real time, with sound (SPACE)");
    ImGui::SameLine();
    if (ImGui::Button("Stop")) {
        session.pause();
        session.set_time_ms(0);
    }
    tip("Stop playback and go back to 0 s");
    ImGui::SameLine();
    ImGui::TextDisabled("(SPACE)");
    // Which camera the view shows: the animated one, or the free view to look around with.
    ImGui::SameLine();
    bool free_view = session.free_view();
    if (ImGui::Checkbox("Free view (c)", &free_view)) session.set_free_view(free_view);
    tip("Look around without editing the animation: Alt+left drag orbits, Alt+middle pans,\n"
                          "Alt+right or the wheel zooms, Home frames everything, F the selection.\n"
                          "Off: the view shows the animated camera (Camera mode keys it).");

    // Max Time in seconds, 1 s .. 300000 s; shortening asks before deleting later keyframes.
    double max_s = static_cast<double>(s.max_time_ms) / 1000.0;
    if (slider("Max Time (s)", max_s, 1.0, 300000.0, "%.3f", ImGuiSliderFlags_Logarithmic))
        s.max_time_ms = std::clamp<std::int64_t>(static_cast<std::int64_t>(max_s * 1000.0 + 0.5),
                                                 Settings::kMinMaxTimeMs, Settings::kMaxMaxTimeMs);
    tip("The animation's length, 1 s to 300000 s (CTRL+click to type). Shortening it asks before\n"
        "deleting the keyframes past the new end. One undoable change.");
    if (ImGui::IsItemDeactivatedAfterEdit()) {
        const auto &keys = doc.keyframes();
        const bool loses = std::any_of(keys.begin(), keys.end(), [&](const Keyframe &k) { return k.time_ms > s.max_time_ms; });
        if (loses) {
            confirm_settings_ = s;
            ImGui::OpenPopup("Delete keyframes?");
        } else {
            std::string error;
            commit(session.set_settings(s, &error), error);
        }
    }
    if (ImGui::BeginPopupModal("Delete keyframes?", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
        int later = 0;
        for (const Keyframe &k : doc.keyframes()) later += confirm_settings_ && k.time_ms > confirm_settings_->max_time_ms;
        ImGui::Text("Shortening the animation deletes %d keyframe%s past the new max time.", later, later == 1 ? "" : "s");
        const bool delete_them = ImGui::Button("Delete them");
        tip("Shorten the animation and delete those keyframes (u undoes both)");
        if (delete_them) {
            std::string error;
            if (confirm_settings_) commit(session.set_settings(*confirm_settings_, &error), error);
            confirm_settings_.reset();
            ImGui::CloseCurrentPopup();
        }
        ImGui::SameLine();
        // Esc cancels; Enter does nothing here: deleting keyframes is not a default.
        const bool cancel = ImGui::Button("Cancel");
        tip("Keep the max time and the keyframes (Esc)");
        if (cancel || escape_pressed()) {
            confirm_settings_.reset();
            settings_draft_ = doc.settings();
            ImGui::CloseCurrentPopup();
        }
        ImGui::EndPopup();
    }

    ImGui::Separator();
    ImGui::TextUnformatted("Keyframes");
    ImGui::SameLine();
    interpolation(session);
    ImGui::BeginChild("keyframes", ImVec2(0, 140), true);
    std::optional<std::int64_t> to_delete;
    for (const Keyframe &k : doc.keyframes()) {
        ImGui::PushID(static_cast<int>(k.time_ms % 2147483647));
        if (ImGui::RadioButton(time_label(k.time_ms).c_str(), k.time_ms == session.time_ms())) {
            session.pause();
            session.set_time_ms(k.time_ms);
        }
        tip("Go to the keyframe at %.3f s (Up/Down jump between keyframes). A drag there edits it;\n"
            "it keys %d model%s%s.", static_cast<double>(k.time_ms) / 1000.0,
            static_cast<int>(std::count_if(k.states.begin(), k.states.end(), [](const auto &st) { return st.has_value(); })),
            std::count_if(k.states.begin(), k.states.end(), [](const auto &st) { return st.has_value(); }) == 1 ? "" : "s",
            k.camera ? " and the camera" : "");
        if (k.time_ms != 0) {
            ImGui::SameLine();
            if (ImGui::SmallButton("Delete")) to_delete = k.time_ms;
            tip("Delete the keyframe at %.3f s (u undoes it). The Timeline deletes single keys.",
                static_cast<double>(k.time_ms) / 1000.0);
        }
        ImGui::PopID();
    }
    ImGui::EndChild();
    if (to_delete) {
        std::string error;
        commit(session.delete_keyframe(*to_delete, &error), error);
    }

    ImGui::Separator();
    if (let_go(slider("Gravity (m/s^2)", s.gravity, 0.0, 50.0, "%.2f"))) {
        std::string error;
        commit(session.set_settings(s, &error), error);
    }
    tip("The acceleration of gravity for models with Gravity on, after their last key (9.81 on Earth).\n"
        "CTRL+click to type. One undoable change; the physics bakes again.");
    int axis = static_cast<int>(s.down_axis);
    ImGui::TextUnformatted("Down axis");
    ImGui::SameLine();
    bool axis_changed = ImGui::RadioButton("X", &axis, 0);
    tip("Models fall along -x");
    ImGui::SameLine();
    axis_changed |= ImGui::RadioButton("Y", &axis, 1);
    tip("Models fall along -y (the default: y is up)");
    ImGui::SameLine();
    axis_changed |= ImGui::RadioButton("Z", &axis, 2);
    tip("Models fall along -z");
    if (axis_changed) {
        s.down_axis = static_cast<Axis>(axis);
        std::string error;
        commit(session.set_settings(s, &error), error);
    }
    if (ImGui::Checkbox("Cel Shading", &s.cel_shading)) {
        std::string error;
        commit(session.set_settings(s, &error), error);
    }
    tip("Toon shading: a few bands of light instead of smooth Phong shading. Saved in the animation.");
    ImGui::SameLine();
    cel_outline(s, session);
    ImGui::SameLine();
    bool paths = session.paths_on(); // a view setting, not an edit
    if (ImGui::Checkbox("Paths (p)", &paths)) session.set_paths_on(paths);
    tip("Motion paths of the selected models: a dot per frame, white at keys, magenta at\n"
                          "collisions. They follow a drag as it happens. A model's own Path box keeps its\n"
                          "path shown when it is not selected.");
    if (asset_combo("Skybox", s.skybox, env_.assets.list(ANI_ASSET_SKYBOX))) {
        std::string error;
        commit(session.set_settings(s, &error), error);
    }
    tip("The environment drawn behind the scene, which reflective and transparent models reflect\n"
        "and refract (the skyboxes/ folders on the asset path). Saved in the animation.");

    ImGui::Separator();
    physics_backend(session);

    ImGui::Separator();
    if (ImGui::Button("Undo (u)")) undo(session);
    tip("Undo the last change made at the current keyframe, else the last change of the whole\n"
        "animation (u, CTRL+Z). Each keyframe keeps its own undo history, as in the seed.");
    ImGui::SameLine();
    if (ImGui::Button("Redo (r)")) redo(session);
    tip("Redo what was undone here (r, CTRL+Y, CTRL+SHIFT+Z)");
    ImGui::SameLine();
    if (ImGui::Button("Export (x)")) {
        const auto r = session.export_animation();
        say(r.message, !r.ok);
    }
    tip("Save the animation (x): to the .ani that was opened, else to animations/new.ani under the\n"
        "working folder (a fresh name, never over a file you did not open). A failed save keeps the old file.");
    // The status line: how fast the editor draws and how far the physics is baked.
    // The frame rate beside the bake status where the panel is wide enough, else under it.
    const std::string bake = bake_status(session), beside = "|  " + frame_rate_;
    ImGui::TextDisabled("%s", bake.c_str());
    const float room = ImGui::GetContentRegionAvail().x - ImGui::GetItemRectSize().x;
    if (room > ImGui::CalcTextSize(beside.c_str()).x + 12.0f) {
        ImGui::SameLine();
        ImGui::TextDisabled("%s", beside.c_str());
    } else {
        ImGui::TextDisabled("%s", frame_rate_.c_str());
    }
    if (!message_.empty()) {
        if (message_error_) ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.45f, 0.4f, 1.0f));
        ImGui::TextWrapped("%s", message_.c_str());
        if (message_error_) ImGui::PopStyleColor();
    }
    outliner(session);
    ImGui::End();
}

// The interpolator of keyed motion (Settings::interpolation, saved in the animation), on the
// Keyframes heading's line: it says how models and the camera go from key to key. Drawn no
// taller than the heading, so the list and everything under it stay where they were.
void Panels::interpolation(EditorSession &session) {
    Settings &s = *settings_draft_;
    const auto short_name = [](const std::string &id) {
        const std::string prefix = "interpolation.";
        return id.compare(0, prefix.size(), prefix) == 0 ? id.substr(prefix.size()) : id;
    };
    ImGui::TextDisabled("  between keys:");
    ImGui::SameLine();
    ImGui::PushStyleVar(ImGuiStyleVar_FramePadding, ImVec2(ImGui::GetStyle().FramePadding.x, 0.0f));
    ImGui::SetNextItemWidth(-1.0f);
    const std::string current = short_name(s.interpolation);
    if (ImGui::BeginCombo("##interpolation", current.c_str())) {
        // Those that handle every channel (not interpolation.kinematic: centers only, which
        // the models with Dynamics on use by themselves).
        uint32_t all = 0;
        for (int kind = ANI_CHANNEL_POSITION; kind <= ANI_CHANNEL_CAMERA_ROTATION; ++kind) all |= 1u << kind;
        for (const PluginInfo *p : env_.plugins.find_kind(ANI_KIND_INTERPOLATOR)) {
            const auto *api = p->descriptor ? static_cast<const ani_interpolator_api *>(p->descriptor->api) : nullptr;
            if (!api || (api->channel_mask & all) != all) continue;
            const std::string label = short_name(p->id) + "  (" + p->name + ")";
            if (ImGui::Selectable(label.c_str(), p->id == s.interpolation) && p->id != s.interpolation) {
                s.interpolation = p->id;
                std::string error;
                commit(session.set_settings(s, &error), error);
            }
            if (ImGui::IsItemHovered() && p->descriptor->description)
                ImGui::SetTooltip("%s", p->descriptor->description);
        }
        ImGui::EndCombo();
    }
    ImGui::PopStyleVar();
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("How keyed motion goes from key to key (%s), saved in the animation.\n"
                          "A model with Dynamics on moves its center by the kinematic equations.",
                          s.interpolation.c_str());
}

void Panels::start_rename(int model) {
    renaming_ = model;
    rename_frames_ = 0;
    rename_active_ = false;
    if (model >= 0) outliner_seen_ = -1; // scrolled to, should the row be out of sight
}

// The Outliner (beyond the seed, as Blender's and Maya's): the scene tree, joints and parents
// included, at the end of the Animator Interface, its top kept at one place so the rows do not
// move with the status message above (only a longer message, or the overlap list, pushes it
// down). A row's box shows or hides the model (a view, not an edit); a click selects it as a
// click in the view does (CTRL+click toggles); a double-click (or F2) renames it.
void Panels::outliner(EditorSession &session) {
    constexpr float kTop = 540.0f; // in the window, below a one-line status message
    if (ImGui::GetCursorPosY() < kTop) ImGui::SetCursorPosY(kTop);
    const bool shown = ImGui::CollapsingHeader("Outliner", ImGuiTreeNodeFlags_DefaultOpen | ImGuiTreeNodeFlags_AllowItemOverlap);
    tip("The scene's tree, joints and parents included: click a row to select, CTRL+click to add,\n"
        "double-click or F2 to rename, the box to hide a model from the view. Click here to fold it.");
    // Add model, Duplicate and Delete on the header's line: under the list they would push
    // the panel past the window's height at 1280x720.
    models_.buttons(session, [this](const std::string &m, bool error) { say(m, error); });
    if (!shown) {
        renaming_ = -1;
        return;
    }
    const Document &doc = session.document();
    const int count = static_cast<int>(doc.models().size());
    if (renaming_ >= count) renaming_ = -1;
    std::vector<std::vector<int>> children(static_cast<size_t>(count) + 1); // [count]: the root's
    for (int m = 0; m < count; ++m) {
        const int parent = doc.models()[static_cast<size_t>(m)].parent;
        children[parent >= 0 && parent < count ? static_cast<size_t>(parent) : static_cast<size_t>(count)].push_back(m);
    }
    // A model selected elsewhere (in the view) is brought into sight: its parents open.
    std::set<int> reveal;
    const int last = session.last_selected();
    if (last != outliner_seen_ && last >= 0 && last < count && !outliner_clicked_)
        for (int p = last; p >= 0; p = doc.models()[static_cast<size_t>(p)].parent) reveal.insert(p);
    outliner_seen_ = last;
    outliner_clicked_ = false;

    const std::set<int> hidden = session.hidden_models();
    // Compact rows (a 15 px box, 2 px apart), so the demo's six models and the puppet's seven
    // fit under the panel's other widgets at 1280x720; a longer list scrolls.
    const float row = ImGui::GetFontSize() + 4.0f, pad = 4.0f;
    const float rows = static_cast<float>(std::max(count, 1)) * row + 2.0f * pad;
    const float room = ImGui::GetContentRegionAvail().y;
    ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(8.0f, pad));
    ImGui::BeginChild("outliner", ImVec2(0, std::max(std::min(rows, room), 6.0f * row + 2.0f * pad)), true);
    ImGui::PopStyleVar();
    ImGui::PushStyleVar(ImGuiStyleVar_FramePadding, ImVec2(4.0f, 1.0f));
    ImGui::PushStyleVar(ImGuiStyleVar_ItemSpacing, ImVec2(4.0f, 2.0f));
    if (count == 0) ImGui::TextDisabled("no models");
    for (int m : children[static_cast<size_t>(count)]) outliner_row(session, m, children, hidden, reveal);
    ImGui::PopStyleVar(2);
    ImGui::EndChild();
}

void Panels::outliner_row(EditorSession &session, int model, const std::vector<std::vector<int>> &children,
                          const std::set<int> &hidden, const std::set<int> &reveal) {
    const Document &doc = session.document();
    const Model &m = doc.models()[static_cast<size_t>(model)];
    const auto &under = children[static_cast<size_t>(model)];
    ImGui::PushID(model);
    // The eye: the model's own visibility; a model under a hidden one shows dimmed.
    bool visible = !session.hidden(model);
    if (ImGui::Checkbox("##shown", &visible)) session.set_hidden(model, !visible);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip(visible ? "Shown in the view: untick to hide '%s'%s (not an edit)"
                                  : "Hidden from the view: tick to show '%s'%s",
                          m.name.c_str(), under.empty() ? "" : " and what hangs under it");
    ImGui::SameLine();
    ImGuiTreeNodeFlags flags = ImGuiTreeNodeFlags_OpenOnArrow | ImGuiTreeNodeFlags_DefaultOpen;
    if (under.empty()) flags |= ImGuiTreeNodeFlags_Leaf | ImGuiTreeNodeFlags_NoTreePushOnOpen;
    if (session.selection().count(model)) flags |= ImGuiTreeNodeFlags_Selected;
    if (reveal.count(model) && !under.empty() && model != session.last_selected()) ImGui::SetNextItemOpen(true);
    const bool dim = hidden.count(model) > 0;
    if (dim) ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
    bool open = false;
    if (renaming_ == model) {
        // The name as a text field: Enter (or a click elsewhere) renames, ESC keeps the name.
        open = ImGui::TreeNodeEx("##node", flags | ImGuiTreeNodeFlags_AllowItemOverlap);
        ImGui::SameLine();
        if (rename_frames_++ == 0) {
            rename_text_ = m.name;
            ImGui::SetKeyboardFocusHere();
        }
        ImGui::SetNextItemWidth(-1.0f);
        const bool enter = ImGui::InputText("##name", &rename_text_,
                                            ImGuiInputTextFlags_EnterReturnsTrue | ImGuiInputTextFlags_AutoSelectAll);
        rename_active_ |= ImGui::IsItemActive();
        const bool escaped = ImGui::IsItemDeactivated() && escape_pressed();
        if (enter || (rename_active_ && ImGui::IsItemDeactivated() && !escaped)) {
            const std::string old = m.name;
            std::string error;
            if (trim_name(rename_text_) == old) {
                // unchanged: nothing to say
            } else if (session.rename_model(model, rename_text_, &error)) {
                say("renamed '" + old + "' to '" + trim_name(rename_text_) + "'");
            } else {
                say(error, true);
            }
            renaming_ = -1;
        } else if (escaped || (!rename_active_ && rename_frames_ > 3)) {
            renaming_ = -1; // ESC, or the field never took the keyboard
        }
    } else {
        flags |= ImGuiTreeNodeFlags_SpanAvailWidth;
        open = ImGui::TreeNodeEx("##node", flags, "%s", m.name.c_str());
        const bool toggled = ImGui::IsItemToggledOpen();
        if (ImGui::IsItemClicked(ImGuiMouseButton_Left) && !toggled) {
            session.click(model, ImGui::GetIO().KeyCtrl);
            outliner_clicked_ = true;
            if (ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left) && !ImGui::GetIO().KeyCtrl) {
                session.click(model, false); // the model renamed is the one selected
                start_rename(model);
                outliner_seen_ = session.last_selected();
            }
        }
        if (ImGui::IsItemHovered() && !ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
            const std::string kind = m.mesh.empty() ? "an empty (a joint or a group)" : "mesh '" + m.mesh + "'";
            ImGui::SetTooltip("%s: %s%s\nClick selects it, CTRL+click adds or removes it, double-click (or F2) renames it.",
                              m.name.c_str(), kind.c_str(), dim ? "; hidden from the view" : "");
        }
        ImGui::SameLine();
        ImGui::TextDisabled("%s", m.mesh.empty() ? "empty" : m.mesh.c_str());
    }
    // Selected in the view (or renamed with F2): the row comes into sight.
    if (reveal.count(model) && model == session.last_selected() && !ImGui::IsItemVisible()) ImGui::SetScrollHereY(0.5f);
    if (dim) ImGui::PopStyleColor();
    if (open && !under.empty()) {
        for (int child : under) outliner_row(session, child, children, hidden, reveal);
        ImGui::TreePop();
    }
    ImGui::PopID();
}

// The shading plugin's cel outline (a parameter saved in the document like the backend's), as
// a checkbox beside Cel Shading: the manual promises outlines, and a parameter hidden in no
// panel could not be turned on. It only draws with cel shading, so it waits for it.
void Panels::cel_outline(Settings &s, EditorSession &session) {
    const std::string plugin = RenderOptions{}.shading;
    bool on = false;
    if (auto p = s.params.find(plugin); p != s.params.end())
        if (auto v = p->second.find("cel_outline"); v != p->second.end()) on = v->second[0] != 0.0;
    ImGui::BeginDisabled(!s.cel_shading);
    const bool clicked = ImGui::Checkbox("Outlines", &on);
    tip(s.cel_shading ? "A line along the models' silhouettes (the shading plugin's cel_outline). Saved in the animation."
                      : "A line along the models' silhouettes: drawn with Cel Shading only, so tick Cel Shading first.");
    if (clicked) {
        if (on) s.params[plugin]["cel_outline"] = ParamValue{1.0, 0.0, 0.0, 0.0};
        else {
            // Off is the default: dropping the entry lets turning it on and off again leave
            // the document as it was (no " *" in the title).
            s.params[plugin].erase("cel_outline");
            if (s.params[plugin].empty()) s.params.erase(plugin);
        }
        std::string error;
        commit(session.set_settings(s, &error), error);
    }
    ImGui::EndDisabled();
}

// The pairs the backend found overlapping (the view rings them in red), each with its fix.
void Panels::overlaps(EditorSession &session) {
    const auto &found = session.overlaps();
    const std::size_t shown = std::min<std::size_t>(found.size(), 3);
    for (std::size_t i = 0; i < shown; ++i) {
        ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.45f, 0.4f, 1.0f));
        ImGui::TextWrapped("%s", describe_overlap(session.document(), found[i]).c_str());
        ImGui::PopStyleColor();
        std::string why;
        const auto lift = plan_lift_out(session.document(), session.meshes(), found[i], &why);
        if (!lift) {
            ImGui::TextDisabled("%s", why.c_str());
            continue;
        }
        const std::string name = session.document().models()[static_cast<size_t>(lift->moved)].name;
        ImGui::PushID(static_cast<int>(i));
        const bool clicked = ImGui::SmallButton(("Lift '" + name + "' out").c_str());
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("Moves '%s' %.3g m the shortest way out (its key at %.3f s): one edit, u undoes it.",
                              name.c_str(), glm::length(lift->offset), static_cast<double>(lift->keyframe_ms) / 1000.0);
        ImGui::PopID();
        if (clicked) {
            // The edit re-bakes: the list is found again, so this frame shows no more of it.
            std::string error;
            char distance[32];
            std::snprintf(distance, sizeof distance, "%.3g", glm::length(lift->offset));
            const std::string other = session.document().models()[static_cast<size_t>(lift->other)].name;
            if (session.lift_out(i, &error))
                say("lifted '" + name + "' " + distance + " m out of '" + other + "' (u undoes it)");
            else
                say("could not " + lift->label + ": " + error, true);
            return;
        }
    }
    if (found.size() > shown) ImGui::TextDisabled("and %zu more overlapping pairs", found.size() - shown);
}

void Panels::physics_backend(EditorSession &session) {
    const std::string current = session.backend();
    if (ImGui::BeginCombo("Physics", current.c_str())) {
        for (const PluginInfo *p : env_.plugins.find_kind(ANI_KIND_PHYSICS)) {
            const std::string label = p->id + "  (" + p->name + ")";
            if (ImGui::Selectable(label.c_str(), p->id == current) && p->id != current) {
                std::string error;
                if (session.use_backend(p->id, error)) say("physics backend: " + p->id);
                else say("could not switch to " + p->id + ": " + error, true);
            }
        }
        ImGui::EndCombo();
    }
    tip("The physics backend that bakes the motion after each model's last key. Switching bakes again\n"
        "with the other one (to compare them); it is not an edit: the file keeps its own choice.");
    if (session.baking()) {
        char text[64];
        std::snprintf(text, sizeof text, "baking %.0f%%", 100.0 * session.bake_progress());
        ImGui::ProgressBar(static_cast<float>(session.bake_progress()), ImVec2(-1, 0), text);
    } else if (!session.bake_error().empty()) {
        ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.45f, 0.4f, 1.0f));
        ImGui::TextWrapped("bake failed: %s", session.bake_error().c_str());
        ImGui::PopStyleColor();
    } else {
        ImGui::ProgressBar(1.0f, ImVec2(-1, 0), "baked");
    }
    overlaps(session);

    // The backend's parameters, saved in the document (settings.params[backend]).
    const PluginInfo *info = env_.plugins.find(current);
    if (!info || !info->descriptor || info->descriptor->param_count == 0) return;
    const bool params_open = ImGui::TreeNode("Backend parameters");
    tip("%s's own settings, saved in the animation; each change is one undoable edit and bakes again.",
        current.c_str());
    if (!params_open) return;
    Settings &s = *settings_draft_;
    for (uint32_t i = 0; i < info->descriptor->param_count; ++i) {
        const ani_param_descriptor &d = info->descriptor->params[i];
        // A value the document does not hold shows the default, and is not written back unless
        // changed (an empty entry would count as a change of parameters and re-bake).
        ParamValue value{d.default_value.value[0], d.default_value.value[1], d.default_value.value[2],
                         d.default_value.value[3]};
        if (auto plugin = s.params.find(current); plugin != s.params.end())
            if (auto saved = plugin->second.find(d.id); saved != plugin->second.end()) value = saved->second;
        bool changed = false;
        switch (d.kind) {
        case ANI_PARAM_BOOL: {
            bool b = value[0] != 0.0;
            changed = ImGui::Checkbox(d.name, &b);
            value[0] = b ? 1.0 : 0.0;
            break;
        }
        case ANI_PARAM_ENUM: {
            int index = static_cast<int>(value[0]);
            const char *preview = index >= 0 && static_cast<uint32_t>(index) < d.enum_count ? d.enum_labels[index] : "?";
            if (ImGui::BeginCombo(d.name, preview)) {
                for (uint32_t e = 0; e < d.enum_count; ++e)
                    if (ImGui::Selectable(d.enum_labels[e], static_cast<int>(e) == index)) {
                        changed = static_cast<int>(e) != index;
                        value[0] = e;
                    }
                ImGui::EndCombo();
            }
            break;
        }
        case ANI_PARAM_INT: {
            long long v = static_cast<long long>(value[0]);
            const long long lo = static_cast<long long>(d.min_value), hi = static_cast<long long>(d.max_value);
            changed = ImGui::SliderScalar(d.name, ImGuiDataType_S64, &v, &lo, &hi, "%lld");
            value[0] = static_cast<double>(v);
            break;
        }
        case ANI_PARAM_COLOUR: {
            float rgba[4] = {static_cast<float>(value[0]), static_cast<float>(value[1]), static_cast<float>(value[2]),
                             static_cast<float>(value[3])};
            changed = ImGui::ColorEdit4(d.name, rgba);
            value = {rgba[0], rgba[1], rgba[2], rgba[3]};
            break;
        }
        default: { // float, angle, time
            const bool wide = d.min_value > 0.0 && d.max_value / d.min_value > 1000.0;
            changed = slider(d.name, value[0], d.min_value, d.max_value, "%.6g", wide ? ImGuiSliderFlags_Logarithmic : 0);
            break;
        }
        }
        if (d.description) tip("%s", d.description);
        else tip("%s: a parameter of %s", d.name, current.c_str());
        if (changed) s.params[current][d.id] = value;
        if (let_go(changed)) {
            std::string error;
            commit(session.set_settings(s, &error), error);
        }
    }
    ImGui::TreePop();
}

void Panels::lights_window(EditorSession &session) {
    ImGui::SetNextWindowPos(ImVec2(360, 40), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(400, 420), ImGuiCond_FirstUseEver);
    const bool open = ImGui::Begin("Lights", &lights_open_);
    if (!open) {
        ImGui::End();
        return;
    }
    ImGui::PushItemWidth(-110.0f);
    Settings &s = *settings_draft_;
    std::string error;
    bool changed = false; // one change, one undoable edit of the settings
    if (s.lights.empty())
        ImGui::TextWrapped("No lights: the view is lit by a light that rides with the camera. Add one to light the "
                           "scene from where you put it.");
    else
        ImGui::TextWrapped("%zu of at most %zu lights; the camera's own light is off while there are any.",
                           s.lights.size(), Settings::kMaxLights);
    if (let_go(colour("Ambient", s.ambient))) changed = true;
    tip("The ambient light: lights every model evenly, shadowed or not (0.2 grey by default; may exceed 1).\n"
        "One undoable change.");
    std::optional<size_t> remove;
    for (size_t i = 0; i < s.lights.size(); ++i) {
        Light &l = s.lights[i];
        ImGui::PushID(static_cast<int>(i));
        ImGui::Separator();
        ImGui::InputText("Name", &l.name);
        if (ImGui::IsItemDeactivatedAfterEdit()) changed = true;
        tip("The light's name, as the scene file calls it (Enter or a click elsewhere sets it)");
        if (let_go(vector3("Position (m)", l.position))) changed = true;
        tip("Where the point light is, in the world (drag a number, or CTRL+click to type)");
        if (let_go(colour("Colour", l.colour))) changed = true;
        tip("Its colour and brightness: each number may exceed 1 (a brighter light), >= 0");
        double falloff[3] = {l.falloff.x, l.falloff.y, l.falloff.z};
        const double zero = 0.0;
        const bool turned = ImGui::DragScalarN("Falloff", ImGuiDataType_Double, falloff, 3, 0.01f, &zero, nullptr,
                                               "%.3f", ImGuiSliderFlags_AlwaysClamp);
        if (turned) l.falloff = glm::dvec3(falloff[0], falloff[1], falloff[2]);
        if (let_go(turned)) changed = true;
        tip("c0 c1 c2: at distance d the light is its colour / (c0 + c1 d + c2 d^2); each >= 0, not all 0.\n"
            "1 0 0 does not fade; the course's scenes often use 1 0 0.");
        if (ImGui::SmallButton("Remove")) remove = i;
        tip("Remove the light '%s' (u undoes it)", l.name.c_str());
        ImGui::PopID();
    }
    ImGui::Separator();
    ImGui::BeginDisabled(s.lights.size() >= Settings::kMaxLights);
    const bool add = ImGui::Button("Add light");
    ImGui::EndDisabled();
    tip(s.lights.size() >= Settings::kMaxLights ? "A scene has at most 8 lights"
                                                : "Add a white point light where the camera is (one undoable change)");
    if (remove) {
        const std::string name = s.lights[*remove].name;
        s.lights.erase(s.lights.begin() + static_cast<std::ptrdiff_t>(*remove));
        if (session.set_settings(s, &error)) say("removed the light '" + name + "' (u undoes it)");
        else commit(false, error);
    } else if (add && s.lights.size() < Settings::kMaxLights) {
        Light l;
        for (int n = static_cast<int>(s.lights.size()) + 1;; ++n) {
            l.name = "light" + std::to_string(n);
            if (std::none_of(s.lights.begin(), s.lights.end(), [&](const Light &o) { return o.name == l.name; })) break;
        }
        l.position = session.frame().camera.position;
        s.lights.push_back(l);
        if (session.set_settings(s, &error)) say("added the light '" + l.name + "' (u undoes it)");
        else commit(false, error);
    } else if (changed) {
        commit(session.set_settings(s, &error), error);
    }
    ImGui::PopItemWidth();
    ImGui::End();
}

void Panels::model_panel(EditorSession &session, float width, float height, float bottom) {
    const int index = session.last_selected();
    if (!model_draft_ || model_draft_index_ != index) {
        model_draft_ = session.document().models()[static_cast<size_t>(index)];
        model_draft_index_ = index;
    }
    // At the right edge, and back there when the window's width changes. Narrower in a small
    // window (800 px: 240), so the view between the panels keeps some room.
    const float panel_width = std::clamp(width * 0.3f, 240.0f, 360.0f);
    // Above the Timeline (`bottom`, its top), and placed again when that moves.
    const ImGuiCond place = width != placed_at_width_ || bottom != placed_at_bottom_ ? ImGuiCond_Always : ImGuiCond_FirstUseEver;
    ImGui::SetNextWindowPos(ImVec2(width - panel_width - 10.0f, 10), place);
    ImGui::SetNextWindowSize(ImVec2(panel_width, std::max(100.0f, std::min({height - 20.0f, bottom - 20.0f, 560.0f}))), place);
    placed_at_width_ = width;
    placed_at_bottom_ = bottom;
    const bool open = ImGui::Begin("Model Interface");
    places_.push_back(current_place());
    if (!open) {
        ImGui::End();
        return;
    }
    ImGui::PushItemWidth(-130.0f); // room for the longest label
    // Every selected model is edited: a change of one field goes to all of them (one edit), and
    // their other fields stay their own. The widgets show the last selected model's values; a
    // field whose values differ among the selected says "(mixed)" until it is changed.
    const Document &doc = session.document();
    const std::set<int> &selected = session.selection();
    Model &m = *model_draft_;
    std::optional<ModelField> done; // a field to commit now
    auto mixed = [&](ModelField f) { return selected.size() > 1 && field_mixed(doc, selected, f); };
    if (selected.size() > 1) {
        ImGui::Text("%zu models selected", selected.size());
        if (ImGui::IsItemHovered()) {
            std::string names;
            for (int i : selected) names += (names.empty() ? "" : ", ") + doc.models()[static_cast<size_t>(i)].name;
            ImGui::SetTooltip("A change goes to every selected model: %s.\nThe values shown are '%s''s; "
                              "(mixed) marks a field whose values differ.",
                              names.c_str(), m.name.c_str());
        }
    } else {
        ImGui::TextUnformatted(m.name.c_str());
    }
    // The model's own motion path, shown also when it is not selected (a view, not an edit).
    // Drawn no taller than the name, so the fields below stay where they were.
    ImGui::SameLine();
    ImGui::PushStyleVar(ImGuiStyleVar_FramePadding, ImVec2(ImGui::GetStyle().FramePadding.x, 0.0f));
    const bool pinned = std::all_of(selected.begin(), selected.end(), [&](int i) { return session.path_pinned(i); });
    const bool some_pinned = std::any_of(selected.begin(), selected.end(), [&](int i) { return session.path_pinned(i); });
    bool pin = pinned;
    if (mixed_checkbox("Path", pin, some_pinned && !pinned))
        for (int i : selected) session.pin_path(i, pin);
    ImGui::PopStyleVar();
    tip("Keep the motion path of %s shown, selected or not (p shows the selected models' paths).\n"
        "A view: not saved, not an edit.", selected.size() > 1 ? "these models" : "this model");

    // The fields every physics backend reads of a model (the SDK's ani_model_desc): the SDK
    // has no per-model parameters of a backend's own, only the backend's document-wide ones
    // (the Animator Interface's "Backend parameters").
    const std::string physics = "Physics (" + session.backend() + ")###Physics";
    const bool physics_open = ImGui::CollapsingHeader(physics.c_str(), ImGuiTreeNodeFlags_DefaultOpen);
    tip("What the physics backend (%s) reads of the model. Click to fold.", session.backend().c_str());
    if (physics_open) {
        if (mixed_checkbox("Dynamics", m.dynamics, mixed(ModelField::Dynamics))) done = ModelField::Dynamics;
        tip("Between keys the center follows the kinematic equations instead of straight lines, it bounces\n"
            "in a collision instead of stopping, and it keeps moving after its last key.");
        if (mixed_checkbox("Gravity", m.gravity, mixed(ModelField::Gravity))) done = ModelField::Gravity;
        tip("After its last key the model falls along the down axis (the Animator Interface's Gravity).");
        if (let_go(slider("Mass (kg)", m.mass, 0.01, 1000.0, "%.3f", ImGuiSliderFlags_Logarithmic, mixed(ModelField::Mass))))
            done = ModelField::Mass;
        tip("How a collision shares momentum between the two models (CTRL+click to type).");
        if (let_go(vector3("Velocity (m/s)", m.initial_velocity, mixed(ModelField::Velocity)))) done = ModelField::Velocity;
        tip("The velocity of the model's center at t = 0, m/s (drag a number, or CTRL+click to type).");
    }
    const bool material_open = ImGui::CollapsingHeader("Material", ImGuiTreeNodeFlags_DefaultOpen);
    tip("How the model is shaded. Click to fold.");
    if (material_open) {
        if (let_go(colour("kd", m.material.kd, mixed(ModelField::Kd)))) done = ModelField::Kd;
        tip("The diffuse colour (drag a number, or click the swatch for a picker)");
        if (let_go(colour("ks", m.material.ks, mixed(ModelField::Ks)))) done = ModelField::Ks;
        tip("The specular colour: of the highlights (drag a number, or click the swatch for a picker)");
        if (asset_combo("Texture", m.texture, env_.assets.list(ANI_ASSET_TEXTURE), mixed(ModelField::Texture)))
            done = ModelField::Texture;
        tip("An image wrapped on the model by its UVs (the textures/ folders on the asset path)");
        const bool textured = std::any_of(selected.begin(), selected.end(), [&](int i) {
            return !doc.models()[static_cast<size_t>(i)].texture.empty();
        });
        if (textured) {
            if (let_go(slider("Tint", m.tint, 0.0, 1.0, "%.3f", 0, mixed(ModelField::Tint)))) done = ModelField::Tint;
            tip("How much kd colours the texture: 0 the texture alone, 1 fully tinted");
        }
        if (let_go(slider("Shininess", m.material.shininess, 0.0, ANI_SHININESS_MAX, "%.1f", 0, mixed(ModelField::Shininess))))
            done = ModelField::Shininess;
        tip("The Phong exponent: higher is a smaller, sharper highlight; at the maximum (%.0f) specular light is off",
            static_cast<double>(ANI_SHININESS_MAX));
        if (let_go(slider("Reflectivity", m.reflectivity, 0.0, 1.0, "%.3f", 0, mixed(ModelField::Reflectivity))))
            done = ModelField::Reflectivity;
        tip("How much of the skybox the model reflects, 0 to 1");
        if (let_go(slider("Transparency", m.transparency, 0.0, 1.0, "%.3f", 0, mixed(ModelField::Transparency))))
            done = ModelField::Transparency;
        tip("How much of the skybox shows through the model, refracted by its refractive index, 0 to 1");
        if (let_go(slider("Refractive index", m.refractive_index, 1.0, 3.0, "%.3f", 0, mixed(ModelField::RefractiveIndex))))
            done = ModelField::RefractiveIndex;
        tip("How much a transparent model bends light: 1 air, 1.33 water, 1.5 glass");
    }
    const bool sound_open = ImGui::CollapsingHeader("Sound", ImGuiTreeNodeFlags_DefaultOpen);
    tip("The model's sounds; their volume follows its kinetic energy and its distance to the camera. Click to fold.");
    if (sound_open) {
        const auto sounds = env_.assets.list(ANI_ASSET_SOUND);
        if (asset_combo("Collision", m.collision_sound, sounds, mixed(ModelField::CollisionSound)))
            done = ModelField::CollisionSound;
        tip("Played once by the model in each of its collisions (the sounds/ folders on the asset path)");
        if (asset_combo("Moving", m.moving_sound, sounds, mixed(ModelField::MovingSound))) done = ModelField::MovingSound;
        tip("Looped while the model moves");
    }
    std::string transform_error, transform_note;
    if (transform_panel_.draw(session, transform_error, transform_note) || !transform_error.empty())
        commit(transform_error.empty(), transform_error);
    if (!transform_note.empty() && transform_error.empty()) say(transform_note);
    // Last, so that the sections above keep their places.
    const bool body_open = ImGui::CollapsingHeader("Rigid body", ImGuiTreeNodeFlags_DefaultOpen);
    tip("How the model's contacts take energy and turn it (docs/physics.md). A contact uses the lower\n"
        "restitution and the higher friction of its two models. Click to fold.");
    if (body_open) {
        if (let_go(slider("Restitution", m.restitution, 0.0, 1.0, "%.3f", 0, mixed(ModelField::Restitution))))
            done = ModelField::Restitution;
        tip("The fraction of the normal speed a contact gives back, 0 to 1: 1 elastic (the default),\n"
            "0 plastic. A contact uses the lower restitution of its two models (CTRL+click to type).");
        if (let_go(slider("Friction", m.friction, 0.0, 2.0, "%.3f", ImGuiSliderFlags_Logarithmic, mixed(ModelField::Friction))))
            done = ModelField::Friction;
        tip("Coulomb's coefficient mu (no unit, >= 0; 0 frictionless, the default): the tangential force\n"
            "of a contact is at most mu times its normal force. A contact uses the higher friction of\n"
            "its two models (CTRL+click to type a value above 2).");
        if (mixed_checkbox("Rotates", m.rotates, mixed(ModelField::Rotates))) done = ModelField::Rotates;
        tip("Its contacts turn it (off: only its keys turn it, as in the seed).");
        if (let_go(vector3("Spin (rad/s)", m.angular_velocity, mixed(ModelField::AngularVelocity))))
            done = ModelField::AngularVelocity;
        tip("Angular velocity: how fast the model turns at t = 0, radians per second about the world\nX, Y and Z axes "
            "(6.28 is one turn a second; drag a number, or CTRL+click to type).");
    }
    ImGui::PopItemWidth();
    ImGui::End();
    if (done) {
        std::string error;
        commit(session.set_field(selected, *done, m, &error), error);
        model_draft_.reset();
    }
}

void Panels::dialogs(EditorSession &session) {
    models_.dialogs(session, env_.assets, [this](const std::string &m, bool error) { say(m, error); });
    if (error_pending_) {
        ImGui::OpenPopup("Error");
        error_pending_ = false;
    }
    if (ImGui::BeginPopupModal("Error", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
        ImGui::TextUnformatted(error_title_.c_str());
        ImGui::PushTextWrapPos(600.0f);
        ImGui::TextUnformatted(error_text_.c_str());
        ImGui::PopTextWrapPos();
        // Enter and Esc both close it: there is nothing to decide, only to read.
        const bool ok = ImGui::Button("OK");
        tip("Close this message (Enter or Esc)");
        if (ok || enter_pressed() || escape_pressed()) ImGui::CloseCurrentPopup();
        ImGui::EndPopup();
    }
    // After any other dialog (an error opening the file): one modal at a time, and not in the
    // frame that one closed, whose Enter or Esc would answer this one too.
    if (recover_asked_ && !dialog_open_ &&
        !ImGui::IsPopupOpen("", ImGuiPopupFlags_AnyPopupId | ImGuiPopupFlags_AnyPopupLevel)) {
        ImGui::OpenPopup("Recover unsaved work");
        recover_asked_ = false;
    }
    if (ImGui::BeginPopupModal("Recover unsaved work", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
        ImGui::Text("Recover unsaved work from %s?", recover_when_.c_str());
        ImGui::TextDisabled("%s", recover_detail_.c_str()); // its lines as they are: a path stays whole
        // Enter recovers: it loses nothing (the work opens as unsaved changes, the file on disk
        // is untouched until exported). Esc discards, setting the autosave aside (discarded.ani).
        const bool recover = ImGui::Button("Recover");
        tip("Open the autosaved work as unsaved changes (Enter); the file on disk stays as it is until saved");
        if (recover || enter_pressed()) {
            recover_answer_ = true;
            ImGui::CloseCurrentPopup();
        }
        ImGui::SameLine();
        const bool discard = ImGui::Button("Discard");
        tip("Set the autosave aside (kept as discarded.ani in the recovery folder) and go on (Esc)");
        if (discard || escape_pressed()) {
            recover_answer_ = false;
            ImGui::CloseCurrentPopup();
        }
        ImGui::EndPopup();
    }
    if (quit_asked_) {
        ImGui::OpenPopup("Unsaved changes");
        quit_asked_ = false;
    }
    if (ImGui::BeginPopupModal("Unsaved changes", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
        ImGui::TextUnformatted("The animation has changes that were not exported.");
        const bool export_quit = ImGui::Button("Export and quit");
        tip("Save the animation as x does, then quit (stays open if saving fails)");
        if (export_quit) {
            const auto r = session.export_animation();
            say(r.message, !r.ok);
            quit_confirmed_ = r.ok;
            ImGui::CloseCurrentPopup();
        }
        ImGui::SameLine();
        const bool quit = ImGui::Button("Quit without exporting");
        tip("Quit and lose the changes since the last save");
        if (quit) {
            quit_confirmed_ = true;
            ImGui::CloseCurrentPopup();
        }
        ImGui::SameLine();
        // Esc cancels; Enter does nothing here: both other answers lose or overwrite work.
        const bool cancel = ImGui::Button("Cancel");
        tip("Go back to the editor (Esc)");
        if (cancel || escape_pressed()) ImGui::CloseCurrentPopup();
        ImGui::EndPopup();
    }
    files_.dialogs(session);
}

} // namespace animator
