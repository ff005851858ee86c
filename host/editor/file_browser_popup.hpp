// The file browser (file_browser.hpp) drawn as a Dear ImGui modal popup: the folder as an
// editable path line, the listing, the file name field, the filter, OK and Cancel. Keyboard
// first: Up/Down move the selection, Enter opens a folder or chooses a file (or what is typed in
// the name field), Backspace with an empty name field goes up, Esc cancels. Typing goes to the
// name field without a click.
#pragma once

#include "editor/file_browser.hpp"

#include <filesystem>
#include <optional>
#include <string>

namespace animator {

class FileBrowserPopup {
  public:
    // Shows the browser (from the next draw()), titled `title`, `ok` the button that chooses.
    void open(const std::string &title, const std::string &ok, FileBrowser::Purpose purpose,
              const std::filesystem::path &folder, std::vector<std::string> extensions, const std::string &name = "");
    bool shown() const { return open_ || requested_; }

    enum class Answer { None, Chosen, Cancelled };
    // Draws it (at the top level, between frames' windows) and says what the user did this frame;
    // the file chosen is chosen().
    Answer draw();
    const std::filesystem::path &chosen() const { return chosen_; }
    const FileBrowser &browser() const { return browser_; }

  private:
    FileBrowser browser_;
    std::string title_, ok_;
    bool requested_ = false, open_ = false;
    int frames_ = 0;             // drawn since it opened
    std::string path_text_;      // the path line, while edited
    bool path_active_ = false;   // the path line has the keyboard
    bool scroll_to_selected_ = false;
    std::filesystem::path chosen_;
};

} // namespace animator
