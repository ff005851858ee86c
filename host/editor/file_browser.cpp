#include "editor/file_browser.hpp"

#include <algorithm>
#include <cctype>
#include <cstdlib>

namespace fs = std::filesystem;

namespace animator {

namespace {

std::string lower(std::string s) {
    for (char &c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return s;
}

// "~" and "~/x" are the home folder, as a shell reads them.
fs::path expand_home(const std::string &text) {
    if (text == "~" || text.rfind("~/", 0) == 0) {
        const char *home = std::getenv("HOME");
        if (home && *home) return fs::path(home) / text.substr(text.size() > 1 ? 2 : 1);
    }
    return fs::path(text);
}

bool natural_less(const std::string &a, const std::string &b) {
    // Case-insensitive first, so "Ball.ani" sits beside "ball2.ani"; then by bytes, for ties.
    const std::string la = lower(a), lb = lower(b);
    return la != lb ? la < lb : a < b;
}

} // namespace

fs::path with_extension(const fs::path &path, const std::string &extension) {
    if (lower(path.extension().string()) == lower(extension)) return path;
    return fs::path(path.string() + extension);
}

void FileBrowser::start(Purpose purpose, const fs::path &folder, std::vector<std::string> extensions,
                        const std::string &name) {
    purpose_ = purpose;
    extensions_ = std::move(extensions);
    for (std::string &e : extensions_) e = lower(e);
    entries_.clear();
    selected_ = -1;
    name_ = name;
    error_.clear();
    std::error_code ec;
    fs::path start = folder.empty() ? fs::current_path(ec) : fs::absolute(folder, ec);
    if (ec) start = folder;
    folder_ = start.lexically_normal();
    if (folder_.has_relative_path() && folder_.filename().empty()) folder_ = folder_.parent_path(); // "a/b/"
    list(folder_);
}

std::string FileBrowser::filter_text() const {
    std::string out;
    for (const std::string &e : extensions_) out += (out.empty() ? "*" : " *") + e;
    return out.empty() ? "*" : out;
}

bool FileBrowser::matches(const fs::path &file) const {
    if (extensions_.empty()) return true;
    const std::string ext = lower(file.extension().string());
    return std::find(extensions_.begin(), extensions_.end(), ext) != extensions_.end();
}

bool FileBrowser::list(const fs::path &folder) {
    std::vector<BrowserEntry> folders, files;
    std::error_code ec;
    fs::directory_iterator it(folder, fs::directory_options::skip_permission_denied, ec);
    if (ec) {
        error_ = "cannot read the folder " + folder.string() + ": " + ec.message();
        return false;
    }
    for (; it != fs::directory_iterator(); it.increment(ec)) {
        if (ec) {
            error_ = "cannot read the whole folder " + folder.string() + ": " + ec.message();
            break;
        }
        const std::string name = it->path().filename().string();
        if (name.empty() || name[0] == '.') continue; // hidden, as file managers show them
        std::error_code type_ec;
        // A link counts as what it points to; a broken one is left out.
        if (it->is_directory(type_ec)) folders.push_back({name, true});
        else if (it->is_regular_file(type_ec) && matches(it->path())) files.push_back({name, false});
    }
    const auto by_name = [](const BrowserEntry &a, const BrowserEntry &b) { return natural_less(a.name, b.name); };
    std::sort(folders.begin(), folders.end(), by_name);
    std::sort(files.begin(), files.end(), by_name);
    entries_ = std::move(folders);
    entries_.insert(entries_.end(), files.begin(), files.end());
    folder_ = folder;
    selected_ = -1;
    return true;
}

void FileBrowser::select(int index) {
    if (index < -1 || index >= static_cast<int>(entries_.size())) return;
    selected_ = index;
    if (index >= 0 && !entries_[static_cast<size_t>(index)].folder) name_ = entries_[static_cast<size_t>(index)].name;
}

void FileBrowser::move(int delta) {
    if (entries_.empty()) return;
    const int last = static_cast<int>(entries_.size()) - 1;
    // From no selection, Down starts at the top and Up at the bottom.
    const int from = selected_ < 0 ? (delta > 0 ? -1 : last + 1) : selected_;
    select(std::clamp(from + delta, 0, last));
}

void FileBrowser::set_name(const std::string &name) {
    if (name == name_) return;
    name_ = name;
    selected_ = -1; // what is typed is what Enter takes
}

bool FileBrowser::go_to(const fs::path &folder) {
    fs::path target = folder.is_absolute() ? folder : folder_ / folder;
    target = target.lexically_normal();
    if (target.has_relative_path() && target.filename().empty()) target = target.parent_path();
    error_.clear();
    std::error_code ec;
    if (!fs::is_directory(target, ec)) {
        error_ = "no folder " + target.string();
        return false;
    }
    return list(target);
}

bool FileBrowser::go_to_typed(const std::string &text) { return go_to(expand_home(text)); }

bool FileBrowser::go_up() {
    if (!folder_.has_relative_path()) return false; // at the root
    const std::string left = folder_.filename().string();
    if (!go_to(folder_.parent_path())) return false;
    for (size_t i = 0; i < entries_.size(); ++i)
        if (entries_[i].folder && entries_[i].name == left) selected_ = static_cast<int>(i);
    return true;
}

void FileBrowser::refresh() {
    const int keep = selected_;
    error_.clear();
    if (list(folder_) && keep < static_cast<int>(entries_.size())) selected_ = keep;
}

std::optional<fs::path> FileBrowser::enter() {
    if (selected_ >= 0 && selected_ < static_cast<int>(entries_.size())) {
        const BrowserEntry e = entries_[static_cast<size_t>(selected_)];
        error_.clear();
        if (e.folder) {
            go_to(folder_ / e.name);
            return std::nullopt;
        }
        return folder_ / e.name;
    }
    return choose_typed(name_);
}

std::optional<fs::path> FileBrowser::choose_typed(const std::string &text) {
    error_.clear();
    if (text.empty()) {
        error_ = purpose_ == Purpose::Save ? "type a name to save as" : "choose a file, or type its name";
        return std::nullopt;
    }
    fs::path typed = expand_home(text);
    if (!typed.is_absolute()) typed = folder_ / typed;
    typed = typed.lexically_normal();
    std::error_code ec;
    if (fs::is_directory(typed, ec)) {
        if (go_to(typed)) name_.clear();
        return std::nullopt;
    }
    if (purpose_ == Purpose::Open) {
        if (!fs::is_regular_file(typed, ec)) {
            error_ = "no file " + typed.string();
            return std::nullopt;
        }
        return typed;
    }
    if (typed.filename().empty()) {
        error_ = "type a file name to save as";
        return std::nullopt;
    }
    if (!extensions_.empty()) typed = with_extension(typed, extensions_.front());
    if (!fs::is_directory(typed.parent_path(), ec)) {
        error_ = "no folder " + typed.parent_path().string() + " to save in";
        return std::nullopt;
    }
    if (fs::is_directory(typed, ec)) {
        error_ = typed.string() + " is a folder";
        return std::nullopt;
    }
    return typed;
}

} // namespace animator
