#include "editor/file_browser_popup.hpp"

#include <imgui.h>
#include <imgui_internal.h> // ClearActiveID: the name field shows a name chosen with the keys
#include <imgui_stdlib.h>

namespace fs = std::filesystem;

namespace animator {

namespace {

// Read from ImGui, which gets keys one change a frame (editor_app.cpp), so a quick press is seen.
bool pressed(ImGuiKey key) { return ImGui::IsKeyPressed(ImGui::GetKeyIndex(key), true); }
bool pressed_once(ImGuiKey key) { return ImGui::IsKeyPressed(ImGui::GetKeyIndex(key), false); }
bool enter_pressed() { return pressed_once(ImGuiKey_Enter) || pressed_once(ImGuiKey_KeyPadEnter); }

constexpr const char *kPopupId = "###file browser";

} // namespace

void FileBrowserPopup::open(const std::string &title, const std::string &ok, FileBrowser::Purpose purpose,
                            const fs::path &folder, std::vector<std::string> extensions, const std::string &name) {
    browser_.start(purpose, folder, std::move(extensions), name);
    title_ = title;
    ok_ = ok;
    requested_ = true;
    chosen_.clear();
}

FileBrowserPopup::Answer FileBrowserPopup::draw() {
    // One modal at a time: it waits for another dialog (an error) to be answered.
    if (requested_ && !ImGui::IsPopupOpen("", ImGuiPopupFlags_AnyPopupId | ImGuiPopupFlags_AnyPopupLevel)) {
        ImGui::OpenPopup(kPopupId);
        requested_ = false;
        open_ = true;
        frames_ = 0;
        path_active_ = false;
        scroll_to_selected_ = true;
    }
    if (!open_) return Answer::None;
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    const ImVec2 size(std::min(620.0f, display.x - 40.0f), std::min(420.0f, display.y - 40.0f));
    ImGui::SetNextWindowSize(size, ImGuiCond_Appearing);
    ImGui::SetNextWindowPos(ImVec2(display.x * 0.5f, display.y * 0.5f), ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
    const std::string id = title_ + kPopupId;
    if (!ImGui::BeginPopupModal(id.c_str(), nullptr, ImGuiWindowFlags_NoSavedSettings)) {
        open_ = false; // closed from elsewhere
        return Answer::Cancelled;
    }
    Answer answer = Answer::None;
    const auto choose = [&](const std::optional<fs::path> &file) {
        if (!file) {
            scroll_to_selected_ = true;
            return;
        }
        chosen_ = *file;
        answer = Answer::Chosen;
    };

    // The keys that move through the list, before the name field is drawn, so it shows the name
    // they select (while it has the keyboard, a field keeps its own copy of the text).
    if (!path_active_) {
        const int before = browser_.selected();
        if (pressed(ImGuiKey_UpArrow)) browser_.move(-1);
        if (pressed(ImGuiKey_DownArrow)) browser_.move(1);
        if (browser_.selected() != before) {
            ImGui::ClearActiveID();
            scroll_to_selected_ = true;
        }
    }

    // The folder: a path line to type into (Enter goes there).
    if (!path_active_) path_text_ = browser_.folder().string();
    ImGui::TextUnformatted("Folder");
    ImGui::SameLine();
    ImGui::SetNextItemWidth(-1.0f);
    const bool path_entered = ImGui::InputText("##folder", &path_text_, ImGuiInputTextFlags_EnterReturnsTrue);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("The folder shown: type a path and Enter to go there (~ is your home).");
    path_active_ = ImGui::IsItemActive();
    if (path_entered) {
        if (browser_.go_to_typed(path_text_)) scroll_to_selected_ = true;
        path_text_ = browser_.folder().string();
    }

    // The listing: folders first (with a "/"), then the files the filter lets through.
    const float footer = ImGui::GetFrameHeightWithSpacing() * 2.0f + ImGui::GetTextLineHeightWithSpacing() * 2.0f;
    ImGui::BeginChild("##entries", ImVec2(0, -footer), true);
    if (browser_.folder().has_relative_path()) {
        if (ImGui::Selectable("../", false, ImGuiSelectableFlags_AllowDoubleClick) && ImGui::IsMouseDoubleClicked(0))
            browser_.go_up();
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("The folder above (Backspace)");
    }
    const std::vector<BrowserEntry> entries = browser_.entries(); // a copy: a double-click lists another folder
    for (int i = 0; i < static_cast<int>(entries.size()); ++i) {
        const BrowserEntry &e = entries[static_cast<size_t>(i)];
        const std::string label = e.folder ? e.name + "/" : e.name;
        ImGui::PushID(i);
        if (ImGui::Selectable(label.c_str(), i == browser_.selected(), ImGuiSelectableFlags_AllowDoubleClick)) {
            browser_.select(i);
            ImGui::ClearActiveID();
            if (ImGui::IsMouseDoubleClicked(0)) choose(browser_.enter());
        }
        if (i == browser_.selected() && scroll_to_selected_) ImGui::SetScrollHereY();
        ImGui::PopID();
        if (answer != Answer::None) break;
    }
    if (entries.empty() && browser_.error().empty()) ImGui::TextDisabled("no folders, and no %s files here", browser_.filter_text().c_str());
    scroll_to_selected_ = false;
    ImGui::EndChild();

    // The name field: typing goes here; Enter chooses what it names.
    const bool name_was_empty = browser_.name().empty();
    ImGui::TextUnformatted("File name");
    ImGui::SameLine();
    ImGui::SetNextItemWidth(-1.0f);
    if (!path_active_ && (frames_ < 2 || !ImGui::IsAnyItemActive())) ImGui::SetKeyboardFocusHere();
    std::string name = browser_.name();
    if (ImGui::InputText("##name", &name, ImGuiInputTextFlags_AutoSelectAll)) browser_.set_name(name);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Type a file name (or a path, or a folder to go to) and press Enter.\n"
                          "Up/Down move through the list, Backspace goes up, Esc cancels.");

    if (!browser_.error().empty()) {
        ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.45f, 0.4f, 1.0f));
        ImGui::TextWrapped("%s", browser_.error().c_str());
        ImGui::PopStyleColor();
    } else {
        ImGui::TextDisabled("Shown: folders and %s files", browser_.filter_text().c_str());
    }

    bool ok = ImGui::Button(ok_.c_str());
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s the file named above (Enter)", ok_.c_str());
    ImGui::SameLine();
    const bool cancel = ImGui::Button("Cancel");
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Close without choosing (Esc)");

    if (answer == Answer::None && !path_active_ && !path_entered) {
        if (enter_pressed()) ok = true;
        else if (pressed(ImGuiKey_Backspace) && name_was_empty && browser_.go_up()) scroll_to_selected_ = true;
    }
    if (answer == Answer::None && ok) choose(browser_.enter());
    if (answer == Answer::None && (cancel || pressed_once(ImGuiKey_Escape))) answer = Answer::Cancelled;
    if (answer != Answer::None) {
        ImGui::CloseCurrentPopup();
        open_ = false;
    }
    ++frames_;
    ImGui::EndPopup();
    return answer;
}

} // namespace animator
