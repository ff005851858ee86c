#include "editor/file_menu.hpp"

#include "editor/recovery.hpp" // home_path

#include <imgui.h>

#include <cctype>

namespace fs = std::filesystem;

namespace animator {

namespace {

// Animations and scenes open; meshes are added to the open animation as models.
const std::vector<std::string> kOpenable = {".ani", ".lua", ".obj", ".ply", ".stl", ".glb", ".gltf"};

bool is_mesh(const fs::path &path) {
    std::string ext = path.extension().string();
    for (char &c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return ext != ".ani" && ext != ".lua";
}
const std::vector<std::string> kScenes = {".lua"};
const std::vector<std::string> kAnimations = {".ani"};

void tooltip(const char *text) {
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", text);
}

bool escape_pressed() { return ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape), false); }

bool any_popup_open() { return ImGui::IsPopupOpen("", ImGuiPopupFlags_AnyPopupId | ImGuiPopupFlags_AnyPopupLevel); }

} // namespace

FileMenu::FileMenu(std::function<void(const std::string &, bool)> say,
                   std::function<void(const std::string &, const std::string &)> show_error)
    : say_(std::move(say)), show_error_(std::move(show_error)), recent_(recent_files_path()) {
    recent_.load(&recent_error_);
}

fs::path FileMenu::start_folder(const EditorSession &session) const {
    // The open document's folder, else the working folder.
    if (!session.path().empty()) {
        std::error_code ec;
        const fs::path folder = fs::absolute(session.path(), ec).parent_path();
        if (!ec && fs::is_directory(folder, ec)) return folder;
    }
    std::error_code ec;
    return fs::current_path(ec);
}

void FileMenu::new_file(EditorSession &session) {
    browsing_ = Browse::New;
    browser_.open("New animation from a scene", "New", FileBrowser::Purpose::Open, start_folder(session), kScenes);
}

void FileMenu::open_file(EditorSession &session) {
    browsing_ = Browse::Open;
    browser_.open("Open", "Open", FileBrowser::Purpose::Open, start_folder(session), kOpenable);
}

void FileMenu::save(EditorSession &session) {
    if (!session.saves_to_path()) {
        save_as(session); // nowhere to write yet: ask where, as Blender does
        return;
    }
    const auto r = session.export_animation();
    say_(r.message, !r.ok);
    if (r.ok) {
        recent_.add(r.path);
        store_recent();
    }
}

void FileMenu::save_as(EditorSession &session) {
    browsing_ = Browse::SaveAs;
    const std::string name = session.path().empty() ? "untitled.ani" : session.path().stem().string() + ".ani";
    browser_.open("Save As", "Save", FileBrowser::Purpose::Save, start_folder(session), kAnimations, name);
}

void FileMenu::open_path(EditorSession &session, const fs::path &path) { request_load(session, {path, false}); }

void FileMenu::remember(const fs::path &path) {
    recent_.add(path);
    store_recent();
}

bool FileMenu::take_quit_request() {
    const bool q = quit_requested_;
    quit_requested_ = false;
    return q;
}

std::optional<fs::path> FileMenu::take_opened() {
    auto o = opened_;
    opened_.reset();
    return o;
}

void FileMenu::store_recent() {
    std::string error;
    if (!recent_.save(&error)) say_(error, true);
}

void FileMenu::request_load(EditorSession &session, const Load &load) {
    if (session.dirty()) {
        pending_load_ = load;
        ask_save_ = true;
        return;
    }
    this->load(session, load);
}

std::string opened_message(const std::string &done, const std::vector<std::string> &warnings) {
    if (warnings.empty()) return done;
    std::string message = done + ", with " + std::to_string(warnings.size()) +
                          (warnings.size() == 1 ? " warning: " : " warnings: ");
    for (size_t k = 0; k < warnings.size(); ++k) message += (k ? " | " : "") + warnings[k];
    return message;
}

void FileMenu::load(EditorSession &session, const Load &l) {
    std::string error;
    const bool ok = l.as_new ? session.new_from_scene(l.path, error) : session.open(l.path, error);
    if (!ok) {
        // The document stays as it was; a recent file that is gone leaves the list.
        std::error_code ec;
        if (!fs::exists(l.path, ec)) {
            recent_.remove(l.path);
            store_recent();
        }
        show_error_("Could not open " + l.path.string(), error);
        return;
    }
    const bool warned = !session.warnings().empty();
    if (l.as_new) {
        say_(opened_message("new animation from " + l.path.string() + " (Save asks where to write it)",
                            session.warnings()),
             warned);
        return;
    }
    say_(opened_message("opened " + l.path.filename().string(), session.warnings()), warned); // its folder is in Open Recent
    recent_.add(l.path);
    store_recent();
    opened_ = l.path;
}

void FileMenu::write_as(EditorSession &session, const fs::path &target) {
    const auto r = session.save_as(target);
    say_(r.message, !r.ok);
    if (!r.ok) {
        after_save_.reset();
        return;
    }
    recent_.add(target);
    store_recent();
    if (after_save_) {
        const Load next = *after_save_;
        after_save_.reset();
        load(session, next);
    }
}

void FileMenu::menu(EditorSession &session, const std::function<void()> &more) {
    if (!recent_error_.empty()) {
        say_(recent_error_, true);
        recent_error_.clear();
    }
    if (!ImGui::BeginMenu("File")) return;
    if (ImGui::MenuItem("New...", "CTRL+N")) new_file(session);
    tooltip("A new, untitled animation from a .lua scene (Save then asks where to write it)");
    if (ImGui::MenuItem("Open...", "CTRL+O")) open_file(session);
    tooltip("Open an .ani animation or a .lua scene; a mesh file (OBJ, PLY, STL, glTF) is added to this\n"
            "animation as a model");
    const bool recent_open = ImGui::BeginMenu("Open Recent");
    // Not over the submenu it opens.
    if (!recent_open) tooltip("The last 10 files opened or saved, newest first");
    if (recent_open) {
        const auto paths = recent_.paths(); // a copy: choosing one changes the list
        if (paths.empty()) ImGui::TextDisabled("(none yet)");
        for (size_t i = 0; i < paths.size(); ++i) {
            std::error_code ec;
            const bool there = fs::is_regular_file(paths[i], ec);
            ImGui::PushID(static_cast<int>(i));
            // A file that is gone stays listed, greyed out, until Clear Recent.
            // The name, and its folder dimmed at the right (two ball.ani in two folders differ).
            const std::string folder = home_path(paths[i].parent_path());
            if (ImGui::MenuItem(paths[i].filename().string().c_str(), folder.c_str(), false, there))
                open_path(session, paths[i]);
            if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
                ImGui::SetTooltip(there ? "%s" : "%s\nno longer exists", paths[i].string().c_str());
            ImGui::PopID();
        }
        ImGui::Separator();
        if (ImGui::MenuItem("Clear Recent", nullptr, false, !paths.empty())) {
            recent_.clear();
            store_recent();
            say_("the recent files list is empty", false);
        }
        tooltip("Forget the files listed here (the files themselves stay)");
        ImGui::EndMenu();
    }
    ImGui::Separator();
    if (ImGui::MenuItem("Save", "CTRL+S")) save(session);
    tooltip(session.saves_to_path() ? "Write the animation to the open .ani (as x does)"
                                    : "No .ani to write to yet: asks where (Save As)");
    if (ImGui::MenuItem("Save As...", "CTRL+SHIFT+S")) save_as(session);
    tooltip("Write the animation to a new .ani, which becomes the open file");
    if (more) {
        ImGui::Separator();
        more();
    }
    ImGui::Separator();
    if (ImGui::MenuItem("Quit", "q, CTRL+Q")) quit_requested_ = true;
    tooltip("Quit; with unsaved changes it asks first");
    ImGui::EndMenu();
}

void FileMenu::dialogs(EditorSession &session) {
    switch (browser_.draw()) {
    case FileBrowserPopup::Answer::None: break;
    case FileBrowserPopup::Answer::Cancelled: after_save_.reset(); break;
    case FileBrowserPopup::Answer::Chosen: {
        const fs::path chosen = browser_.chosen();
        if (browsing_ == Browse::SaveAs) {
            std::error_code ec;
            if (fs::exists(chosen, ec)) {
                confirm_replace_ = chosen;
                ask_replace_ = true;
            } else {
                write_as(session, chosen);
            }
        } else if (browsing_ == Browse::Open && is_mesh(chosen)) {
            // A mesh is added to the animation as a model (one undoable edit), as Add Model does.
            std::string message;
            const bool added = session.add_model_from_file(chosen, message);
            say_(message, !added);
        } else {
            request_load(session, {chosen, browsing_ == Browse::New});
        }
        break;
    }
    }

    // One modal at a time, each opened once the one before has gone.
    if (ask_replace_ && !any_popup_open()) {
        ImGui::OpenPopup("Replace file?");
        ask_replace_ = false;
    }
    if (ImGui::BeginPopupModal("Replace file?", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
        const std::string name = confirm_replace_ ? confirm_replace_->string() : "";
        ImGui::Text("%s already exists.", name.c_str());
        ImGui::TextUnformatted("Replace it with this animation?");
        // Esc cancels; Enter does nothing: replacing a file is not a default.
        if (ImGui::Button("Replace")) {
            ImGui::CloseCurrentPopup();
            if (confirm_replace_) write_as(session, *confirm_replace_);
            confirm_replace_.reset();
        }
        tooltip("Write over the file (atomically: a failure leaves it as it was)");
        ImGui::SameLine();
        if (ImGui::Button("Cancel") || escape_pressed()) {
            ImGui::CloseCurrentPopup();
            confirm_replace_.reset();
            after_save_.reset();
        }
        tooltip("Keep the file; nothing is written (Esc)");
        ImGui::EndPopup();
    }

    if (ask_save_ && !any_popup_open()) {
        ImGui::OpenPopup("Save changes?");
        ask_save_ = false;
    }
    if (ImGui::BeginPopupModal("Save changes?", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
        const std::string next = pending_load_ ? pending_load_->path.filename().string() : "";
        ImGui::TextUnformatted("The animation has changes that were not saved.");
        ImGui::Text("Save them before opening %s?", next.c_str());
        // Esc cancels; Enter does nothing here: both other answers lose or write work.
        if (ImGui::Button("Save")) {
            ImGui::CloseCurrentPopup();
            const Load next_load = *pending_load_;
            pending_load_.reset();
            if (session.saves_to_path()) {
                const auto r = session.export_animation();
                say_(r.message, !r.ok);
                if (r.ok) {
                    recent_.add(r.path);
                    store_recent();
                    load(session, next_load);
                }
            } else {
                after_save_ = next_load; // Save As first, then open it
                save_as(session);
            }
        }
        tooltip("Save the animation (to its .ani, or asks where), then open the other file");
        ImGui::SameLine();
        if (ImGui::Button("Don't Save")) {
            ImGui::CloseCurrentPopup();
            const Load next_load = *pending_load_;
            pending_load_.reset();
            load(session, next_load);
        }
        tooltip("Drop the changes and open the other file");
        ImGui::SameLine();
        if (ImGui::Button("Cancel") || escape_pressed()) {
            ImGui::CloseCurrentPopup();
            pending_load_.reset();
        }
        tooltip("Keep working on this animation (Esc)");
        ImGui::EndPopup();
    }
}

} // namespace animator
