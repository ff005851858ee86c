#include "editor/help.hpp"

#include <imgui.h>

#include <algorithm>

namespace animator {

const std::vector<HelpSection> &help_sections() {
    static const std::vector<HelpSection> sections = {
        {"Keys",
         {
             {"SPACE", "play / pause from the current time (real time: frames are dropped, never slowed)"},
             {"Left, Right", "one frame back or on (30 frames a second); pauses playback"},
             {"Up, Down", "the previous or next keyframe; pauses playback"},
             {"`c`, Numpad 0", "free view on or off"},
             {"Home, F, Numpad .", "frame all, frame the selection (in the free view)"},
             {"`p`", "motion paths of the selected models on or off"},
             {"`u`, CTRL+Z", "undo the last transformation or change at this keyframe"},
             {"`r`, CTRL+SHIFT+Z, CTRL+Y", "redo"},
             {"`x`", "export to the open .ani (or animations/new.ani)"},
             {"CTRL+S", "save to the open .ani (as `x`); with none (a .lua scene, New) it asks where, as Save As"},
             {"CTRL+SHIFT+S", "save as: a new .ani, which becomes the open file"},
             {"CTRL+O, CTRL+N", "open an .ani or .lua; a new untitled animation from a .lua scene (File menu)"},
             {"CTRL+F12", "render the animation to PNG frames or a video"},
             {"CTRL+SHIFT+E", "export the trace (CSV) and the soundtrack (WAV)"},
             {"DELETE", "delete the keys selected in the Timeline (not those at t = 0); with none, the selected models and what hangs under them, after asking (Enter deletes, ESC keeps)"},
             {"SHIFT+A", "add a model: a mesh on the asset path or any mesh file, where the view looks"},
             {"SHIFT+D", "duplicate the selected models (with their keys) beside them"},
             {"CTRL+C, CTRL+V", "copy the keys selected in the Timeline; paste them at the playhead"},
             {"`i`", "key the selected models where they are now, at the current time (nothing selected: the camera)"},
             {"ALT+I", "delete the selected models' keys (or the camera's) at the current time"},
             {"`a`, ALT+A", "select every shown model; select none"},
             {"`h`, ALT+H", "hide the selected models from the view; show every model"},
             {"SHIFT+Left, SHIFT+Right", "jump to the start or the end; pauses playback"},
             {"F1", "this overlay (F1 or ESC closes it)"},
             {"F2", "rename the last selected model in the Outliner"},
             {"`q`, CTRL+Q", "quit; with unsaved changes it asks first"},
             {"ESC", "cancel a drag (also a look-around drag: the view goes back)"},
             {"`w`, `e`, `s`", "Translate, Rotate, Scale mode (the gizmo's handles)"},
         }},
        {"Mouse in the 3D view (choose a mode in the Animator Interface)",
         {
             {"left click", "select a model (CTRL: add or remove it); empty space: select none"},
             {"Camera: left / middle / right drag", "move the camera on its x/y / roll it / turn it"},
             {"Camera: scroll", "move the camera along its view"},
             {"Rotate: middle / right drag", "turn the selected models about y / about x and z"},
             {"Translate: middle / right drag", "move them along z / on x and y with the cursor"},
             {"Scale: middle / right drag", "scale z / scale x and y (right and up grow)"},
             {"Translate: left drag an arrow / square / centre", "move along that axis / in that plane / in the view's plane"},
             {"Rotate: left drag a ring", "turn that one Euler angle, following the cursor round"},
             {"Scale: left drag a box / the centre box", "scale that axis / all three"},
             {"CTRL during a gizmo drag", "snap: 0.1 m, 15 degrees, scale factors 0.1"},
             {"any drag at a time with no keyframe", "makes a keyframe there, keying what moved"},
         }},
        {"Free view (looking around: never an edit)",
         {
             {"Alt + left drag", "orbit about the pivot (the distance to it stays)"},
             {"Alt + middle drag", "pan: the scene at the pivot's depth follows the cursor"},
             {"Alt + right drag, wheel", "zoom towards the pivot"},
             {"Home", "frame all: every model fits the view"},
             {"F", "frame the selected models"},
             {"`c`, Numpad 0, the *Free view* checkbox", "switch between the free view and the animated camera"},
         }},
        {"Coming from Blender or Maya (these keys say where to look)",
         {
             {"`g`", "Blender's grab: choose Translate and drag with the right button"},
             {"`k`", "Blender's keying sets: `i` keys the selected models"},
             {"TAB", "Blender's Edit Mode: meshes are not edited here; a scene file or a mesh file defines them"},
             {"`n`", "Blender's sidebar: the Model Interface (right) shows the selected model"},
         }},
        {"Timeline (the dope sheet along the bottom)",
         {
             {"click or drag on the ruler", "move the playhead there, to the nearest frame (pauses playback; not an edit)"},
             {"click a key", "select it; CTRL+click adds or removes it, SHIFT+click adds it"},
             {"drag on empty space", "select the keys in the box (CTRL toggles them, SHIFT adds them); a click there selects none"},
             {"click a row's name", "select all the keys of that row"},
             {"drag a selected key", "retime the selected keys together, the one held landing on a frame (one edit)"},
             {"DELETE", "delete the selected keys"},
             {"CTRL+C, CTRL+V", "copy the selected keys; paste them at the playhead, spaced as they were"},
             {"wheel", "zoom in or out about the pointer (out to the whole animation, in to a frame every 120 px)"},
             {"SHIFT+wheel, middle drag", "pan along time"},
             {"wheel over the names", "scroll the rows, when there are more than fit"},
             {"ESC", "cancel a drag of keys or a box"},
             {"double-click the title bar", "collapse it to its title bar (the 3D view takes the window's height) or open it"},
         }},
    };
    return sections;
}

std::optional<std::string> familiar_key_hint(const std::string &key) {
    for (const HelpSection &section : help_sections()) {
        if (section.title.rfind("Coming from Blender or Maya", 0) != 0) continue;
        for (const HelpRow &row : section.rows) {
            std::string keys;
            for (char c : row.keys)
                if (c != '`') keys += c;
            if (keys == key) {
                std::string action;
                for (char c : row.action)
                    if (c != '`') action += c;
                return keys + ": " + action;
            }
        }
    }
    return std::nullopt;
}

namespace {

// The manual's markdown (`c`, *Free view*) as plain text.
std::string plain(const std::string &text) {
    std::string out;
    for (char c : text)
        if (c != '`' && c != '*') out += c;
    return out;
}

} // namespace

namespace {

void draw_section(const HelpSection &section, float keys_width) {
    ImGui::TextColored(ImVec4(1.0f, 0.78f, 0.25f, 1.0f), "%s", section.title.c_str());
    if (ImGui::BeginTable(section.title.c_str(), 2, ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV)) {
        ImGui::TableSetupColumn("keys", ImGuiTableColumnFlags_WidthFixed, keys_width);
        ImGui::TableSetupColumn("action", ImGuiTableColumnFlags_WidthStretch);
        for (const HelpRow &row : section.rows) {
            ImGui::TableNextRow();
            ImGui::TableSetColumnIndex(0);
            ImGui::TextWrapped("%s", plain(row.keys).c_str());
            ImGui::TableSetColumnIndex(1);
            ImGui::TextWrapped("%s", plain(row.action).c_str());
        }
        ImGui::EndTable();
    }
    ImGui::Spacing();
}

} // namespace

// Two columns, each scrolling on its own: the keys on the left, the mouse (the view, the free
// view, the Timeline) and the keys of other programs on the right, so that most of it shows at
// once in a 1280x720 window.
void draw_help_overlay(bool *open, float width, float height) {
    if (!*open) return;
    const ImVec2 size(std::min(width - 40.0f, 1180.0f), std::min(height - 40.0f, 660.0f));
    ImGui::SetNextWindowPos(ImVec2((width - size.x) / 2.0f, (height - size.y) / 2.0f), ImGuiCond_Always);
    ImGui::SetNextWindowSize(size, ImGuiCond_Always);
    ImGui::SetNextWindowBgAlpha(0.94f);
    ImGui::SetNextWindowFocus();
    if (ImGui::Begin("Keys and mouse (F1)", open, ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings)) {
        const auto &sections = help_sections();
        const float footer = ImGui::GetTextLineHeightWithSpacing();
        if (ImGui::BeginTable("help columns", 2, ImGuiTableFlags_BordersInnerV | ImGuiTableFlags_SizingStretchSame,
                              ImVec2(0.0f, ImGui::GetContentRegionAvail().y - footer))) {
            ImGui::TableNextRow();
            ImGui::TableSetColumnIndex(0);
            ImGui::BeginChild("keys column");
            if (!sections.empty()) draw_section(sections.front(), 150.0f);
            ImGui::EndChild();
            ImGui::TableSetColumnIndex(1);
            ImGui::BeginChild("mouse column");
            for (size_t i = 1; i < sections.size(); ++i) draw_section(sections[i], 200.0f);
            ImGui::EndChild();
            ImGui::EndTable();
        }
        ImGui::TextDisabled("docs/manual.md says more. Close: F1, ESC or the x above.");
    }
    ImGui::End();
}

} // namespace animator
