// The file browser's model (Dear ImGui has none): a folder's listing (folders first, then the
// files whose extension is in the filter, each sorted, hidden ones left out), the selection that
// Up/Down move, going into a folder and up, and the name or path typed, which either goes to a
// folder or chooses a file. No window: file_browser_popup.hpp draws it, tests drive it directly.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace animator {

struct BrowserEntry {
    std::string name;
    bool folder = false;
};

class FileBrowser {
  public:
    // Open chooses a file that exists; Save a name to write (the first extension of the filter
    // appended when it has none of them; an existing file is the caller's to ask about).
    enum class Purpose { Open, Save };

    // Starts in `folder` (made absolute), listing files whose extension (".ani", lower case) is
    // in `extensions`; `name` fills the name field (Save As: the document's name).
    void start(Purpose purpose, const std::filesystem::path &folder, std::vector<std::string> extensions,
               const std::string &name = "");

    Purpose purpose() const { return purpose_; }
    const std::filesystem::path &folder() const { return folder_; }
    const std::vector<BrowserEntry> &entries() const { return entries_; }
    const std::vector<std::string> &extensions() const { return extensions_; }
    // "*.ani *.lua", for the browser to show.
    std::string filter_text() const;
    // Why the last step failed (a folder that cannot be read, no such file...), or "".
    const std::string &error() const { return error_; }

    // The selected entry (-1: none). Up/Down: move() by -1/+1, kept within the list.
    int selected() const { return selected_; }
    void select(int index);
    void move(int delta);

    // The name field. Selecting a file puts its name there; typing there clears the selection.
    const std::string &name() const { return name_; }
    void set_name(const std::string &name);

    // Lists `folder` (relative to the current one). False, with error(), when it cannot be read;
    // then the listing stays that of the folder before.
    bool go_to(const std::filesystem::path &folder);
    // The path line: `text` (absolute, relative to the folder, "~/...") when it is a folder.
    bool go_to_typed(const std::string &text);
    // The parent folder (Backspace with an empty name field). The selection is the folder left.
    bool go_up();
    // Lists the current folder again (a file written since).
    void refresh();

    // Enter: the selected entry if any (a folder is entered; a file is chosen), else the name
    // field (typed_path()). Returns the chosen file; nothing when a folder was entered or the
    // name does not make a file (error() says why).
    std::optional<std::filesystem::path> enter();
    // A name or path typed (absolute, relative to the folder, "~/..."): a folder is entered; a
    // file is chosen (Open: if it exists; Save: with the extension added when missing).
    std::optional<std::filesystem::path> choose_typed(const std::string &text);

  private:
    bool list(const std::filesystem::path &folder);
    bool matches(const std::filesystem::path &file) const;

    Purpose purpose_ = Purpose::Open;
    std::filesystem::path folder_;
    std::vector<std::string> extensions_;
    std::vector<BrowserEntry> entries_;
    int selected_ = -1;
    std::string name_, error_;
};

// `path` with `extension` (".ani") appended unless it already ends with it (any case).
std::filesystem::path with_extension(const std::filesystem::path &path, const std::string &extension);

} // namespace animator
