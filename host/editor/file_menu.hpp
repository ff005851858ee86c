// The File menu of the Animator Interface's menu bar, and its keys: New (CTRL+N: a .lua scene as
// a new untitled animation), Open (CTRL+O: an .ani or a .lua), Open Recent, Save (CTRL+S: the
// open .ani, as `x`; with none, Save As), Save As (CTRL+SHIFT+S), Quit (CTRL+Q, as `q`). Files
// are chosen in the browser (file_browser_popup.hpp); New and Open over unsaved changes ask
// Save / Don't Save / Cancel first, and Save As asks before replacing a file.
#pragma once

#include "editor/editor_session.hpp"
#include "editor/file_browser_popup.hpp"
#include "editor/recent_files.hpp"

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace animator {

// The message line after a file is opened: `done` ("opened scene.lua"), and, when reading it
// warned (a renamed node, a dropped shear, a mesh read leniently), every warning after it: the
// message line shows one message, so they are not said one over another.
std::string opened_message(const std::string &done, const std::vector<std::string> &warnings);

class FileMenu {
  public:
    // `say` puts a line in the status line (error: in red); `show_error` opens the error dialog.
    FileMenu(std::function<void(const std::string &, bool)> say,
             std::function<void(const std::string &, const std::string &)> show_error);

    // The menu, inside the menu bar being drawn; `more` draws the items of other stages
    // (Render, Export) between Save As and Quit.
    void menu(EditorSession &session, const std::function<void()> &more = {});
    // Its dialogs, at the top level, once a frame.
    void dialogs(EditorSession &session);

    // The keys (and the menu's items).
    void new_file(EditorSession &session);
    void open_file(EditorSession &session);
    void save(EditorSession &session);
    void save_as(EditorSession &session);
    // Opens `path` (asking first over unsaved changes), as Open Recent does.
    void open_path(EditorSession &session, const std::filesystem::path &path);

    // A file the editor opened by itself (the command line's), for Open Recent.
    void remember(const std::filesystem::path &path);
    const RecentFiles &recent() const { return recent_; }

    // File > Quit: the window's quit path (it asks over unsaved changes) takes it, once.
    bool take_quit_request();
    // A document just opened from the menu, once: the window offers its autosave, if any.
    std::optional<std::filesystem::path> take_opened();

  private:
    struct Load {
        std::filesystem::path path;
        bool as_new = false; // New: the scene as an untitled animation
    };
    void request_load(EditorSession &session, const Load &load);
    void load(EditorSession &session, const Load &load);
    void write_as(EditorSession &session, const std::filesystem::path &target);
    void store_recent();
    std::filesystem::path start_folder(const EditorSession &session) const;

    std::function<void(const std::string &, bool)> say_;
    std::function<void(const std::string &, const std::string &)> show_error_;
    RecentFiles recent_;
    std::string recent_error_; // said once, at the first frame

    enum class Browse { Open, New, SaveAs };
    Browse browsing_ = Browse::Open;
    FileBrowserPopup browser_;
    std::optional<Load> pending_load_;    // waiting for the Save / Don't Save answer
    std::optional<Load> after_save_;      // to open once Save As has written the document
    std::optional<std::filesystem::path> confirm_replace_; // Save As over an existing file
    bool ask_save_ = false, ask_replace_ = false;
    bool quit_requested_ = false;
    std::optional<std::filesystem::path> opened_;
};

} // namespace animator
