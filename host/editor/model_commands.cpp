#include "editor/model_commands.hpp"

#include "assets/mesh_format_scan.hpp"
#include "editor/model_edits.hpp"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>

namespace animator {

namespace {

bool key_pressed(ImGuiKey key) { return ImGui::IsKeyPressed(ImGui::GetKeyIndex(key), false); }
bool enter_pressed() { return key_pressed(ImGuiKey_Enter) || key_pressed(ImGuiKey_KeyPadEnter); }
bool escape_pressed() { return key_pressed(ImGuiKey_Escape); }

void tooltip(const char *text) {
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", text);
}

bool names_file(const std::string &text) {
    return text.find('/') != std::string::npos || mesh_format_of(text) != MeshFormat::Obj ||
           (text.size() > 4 && text.compare(text.size() - 4, 4, ".obj") == 0);
}

} // namespace

std::vector<std::string> matching_ids(const std::string &text, const std::vector<std::string> &ids) {
    std::vector<std::string> out;
    for (const std::string &id : ids)
        if (id.find(text) != std::string::npos) out.push_back(id);
    // The id that is the text itself first, then those starting with it.
    std::stable_sort(out.begin(), out.end(), [&](const std::string &a, const std::string &b) {
        const auto rank = [&](const std::string &id) { return id == text ? 0 : id.rfind(text, 0) == 0 ? 1 : 2; };
        return rank(a) < rank(b);
    });
    return out;
}

AddChoice add_choice(const std::string &text, const std::vector<std::string> &ids) {
    if (text.empty()) return {};
    if (names_file(text)) return {AddChoice::File, text};
    const auto found = matching_ids(text, ids);
    if (found.empty()) return {};
    return {AddChoice::Asset, found.front()};
}

void ModelCommands::duplicate(EditorSession &session, const Say &say) {
    std::string message;
    const bool ok = session.duplicate_selected(message);
    say(message, !ok);
}

void ModelCommands::ask_delete(const EditorSession &session, const Say &say) {
    if (session.selection().empty()) {
        say("nothing selected to delete", false);
        return;
    }
    delete_question_ = "Delete " + deletion_phrase(session.document(), session.selection(), session.models_to_delete()) + "?";
    delete_asked_ = true;
}

void ModelCommands::buttons(EditorSession &session, const Say &say) {
    // Small, right-aligned on the line of the header they follow.
    const ImGuiStyle &style = ImGui::GetStyle();
    const float width = ImGui::CalcTextSize("Add modelDuplicateDelete").x + 6.0f * style.FramePadding.x +
                        2.0f * style.ItemSpacing.x;
    ImGui::SameLine(ImGui::GetWindowContentRegionMax().x - width - style.FramePadding.x);
    if (ImGui::SmallButton("Add model")) ask_add();
    tooltip("Add a model of a mesh on the asset path or of any mesh file (OBJ, PLY, STL, glTF),\n"
            "where the view looks, keyed at t = 0 (SHIFT+A). One edit: u undoes it.");
    ImGui::SameLine();
    if (ImGui::SmallButton("Duplicate")) duplicate(session, say);
    tooltip("Copy the selected models (and what hangs under them) with their keys, beside them\n"
            "along +x by their size (SHIFT+D). One edit: u undoes it.");
    ImGui::SameLine();
    if (ImGui::SmallButton("Delete")) ask_delete(session, say);
    tooltip("Delete the selected models and what hangs under them, after asking (DELETE, when no\n"
            "keys are selected in the Timeline). One edit: u undoes it.");
}

void ModelCommands::dialogs(EditorSession &session, const AssetPaths &assets, const Say &say) {
    if (add_asked_ && !ImGui::IsPopupOpen("", ImGuiPopupFlags_AnyPopupId | ImGuiPopupFlags_AnyPopupLevel)) {
        ImGui::OpenPopup("Add model");
        add_asked_ = false;
        add_text_.clear();
        add_frames_ = 0;
        mesh_ids_ = assets.list(ANI_ASSET_MESH);
    }
    ImGui::SetNextWindowSize(ImVec2(420.0f, 0.0f));
    if (ImGui::BeginPopupModal("Add model", nullptr, ImGuiWindowFlags_NoResize)) {
        ImGui::TextUnformatted("A mesh on the asset path, or a mesh file by its path\n(OBJ, PLY, STL, .glb, or .gltf with its buffers inside):");
        if (add_frames_++ == 0) ImGui::SetKeyboardFocusHere();
        ImGui::SetNextItemWidth(-1.0f);
        const bool entered = ImGui::InputTextWithHint("##mesh", "type to search, or a path such as meshes/rock.ply",
                                                      &add_text_, ImGuiInputTextFlags_EnterReturnsTrue);
        tooltip("Typing narrows the list; Enter adds the first mesh listed, or the file named\n"
                "(a path, absolute or from the working folder). ESC closes.");
        const auto listed = matching_ids(add_text_, mesh_ids_);
        const AddChoice typed = add_choice(add_text_, mesh_ids_);
        AddChoice chosen;
        ImGui::BeginChild("meshes", ImVec2(0.0f, 180.0f), true);
        if (typed.kind == AddChoice::File) {
            if (ImGui::Selectable(("file: " + typed.value).c_str(), true)) chosen = typed;
        }
        for (size_t i = 0; i < listed.size(); ++i) {
            const bool first = typed.kind == AddChoice::Asset && i == 0;
            if (ImGui::Selectable(listed[i].c_str(), first)) chosen = {AddChoice::Asset, listed[i]};
        }
        if (listed.empty() && typed.kind != AddChoice::File) ImGui::TextDisabled("no mesh on the asset path matches");
        ImGui::EndChild();
        if (entered) chosen = typed;
        const bool add_button = ImGui::Button("Add");
        tooltip("Add the mesh highlighted above (Enter)");
        if (add_button) chosen = typed;
        ImGui::SameLine();
        const bool cancel = ImGui::Button("Cancel") || escape_pressed();
        tooltip("Close without adding (ESC)");
        if (chosen.kind != AddChoice::None) {
            std::string message;
            const bool ok = chosen.kind == AddChoice::Asset ? session.add_model_from_asset(chosen.value, message)
                                                            : session.add_model_from_file(chosen.value, message);
            say(message, !ok);
            ImGui::CloseCurrentPopup();
        } else if (cancel) {
            ImGui::CloseCurrentPopup();
        }
        ImGui::EndPopup();
    }

    if (delete_asked_ && !ImGui::IsPopupOpen("", ImGuiPopupFlags_AnyPopupId | ImGuiPopupFlags_AnyPopupLevel)) {
        ImGui::OpenPopup("Delete models");
        delete_asked_ = false;
    }
    if (ImGui::BeginPopupModal("Delete models", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
        ImGui::TextUnformatted(delete_question_.c_str());
        ImGui::TextDisabled("One edit: u (or CTRL+Z) brings them back.");
        // Enter deletes, as Blender's X asks and deletes: nothing is lost, undo brings it back.
        const bool yes = ImGui::Button("Delete") || enter_pressed();
        tooltip("Delete them (Enter)");
        ImGui::SameLine();
        const bool no = ImGui::Button("Cancel") || escape_pressed();
        tooltip("Keep them (ESC)");
        if (yes) {
            std::string message;
            const bool ok = session.delete_selected(message);
            say(message, !ok);
            ImGui::CloseCurrentPopup();
        } else if (no) {
            ImGui::CloseCurrentPopup();
        }
        ImGui::EndPopup();
    }
}

} // namespace animator
