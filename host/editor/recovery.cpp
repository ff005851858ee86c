#include "editor/recovery.hpp"

#include "editor/editor_session.hpp"
#include "editor/state_folder.hpp"
#include "io/document_io.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace fs = std::filesystem;

namespace animator {

namespace {

// FNV-1a, 64 bits: a stable name for a path, the same in every run and build.
std::uint64_t fnv1a(const std::string &s) {
    std::uint64_t h = 14695981039346656037ull;
    for (unsigned char c : s) {
        h ^= c;
        h *= 1099511628211ull;
    }
    return h;
}

// The file's name as far as it reads well in a folder listing: letters, digits, '-', '_' and
// '.', at most 40 of them, never a hidden file.
std::string readable_stem(const fs::path &document) {
    std::string out;
    for (unsigned char c : document.stem().string()) {
        if (out.size() >= 40) break;
        const bool plain = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                           c == '-' || c == '_' || c == '.';
        out += plain ? static_cast<char>(c) : '_';
    }
    if (out.empty()) out = "document";
    if (out[0] == '.') out[0] = '_';
    return out;
}

bool newer(const struct stat &a, const struct stat &b) {
    if (a.st_mtim.tv_sec != b.st_mtim.tv_sec) return a.st_mtim.tv_sec > b.st_mtim.tv_sec;
    return a.st_mtim.tv_nsec > b.st_mtim.tv_nsec;
}

} // namespace

double autosave_interval(std::string *warning) {
    const char *v = std::getenv("ANIMATOR_AUTOSAVE_SECONDS");
    if (!v || !*v) return kDefaultAutosaveSeconds;
    char *end = nullptr;
    const double seconds = std::strtod(v, &end);
    if (end == v || *end != '\0' || !std::isfinite(seconds) || seconds < 0.0) {
        if (warning)
            *warning = std::string("ANIMATOR_AUTOSAVE_SECONDS=") + v +
                       " is not a number of seconds (0 turns autosave off); autosaving every 120 s";
        return kDefaultAutosaveSeconds;
    }
    return seconds;
}

fs::path recovery_folder() { return state_path("recovery"); }

fs::path recovery_file(const fs::path &folder, const fs::path &document) {
    if (document.empty()) return folder / "untitled.ani";
    // The same document by any name (relative, through a link) is the same recovery file.
    std::error_code ec;
    fs::path full = fs::absolute(document, ec);
    if (ec) full = document;
    fs::path canonical = fs::weakly_canonical(full, ec);
    if (ec || canonical.empty()) canonical = full.lexically_normal();
    char hash[17];
    std::snprintf(hash, sizeof hash, "%016llx", static_cast<unsigned long long>(fnv1a(canonical.string())));
    return folder / (readable_stem(document) + "-" + hash + ".ani");
}

bool write_recovery(PluginRegistry &plugins, const Document &doc, const fs::path &file, std::string &error) {
    const fs::path folder = file.parent_path();
    std::error_code ec;
    // The work is the user's own: the folder is theirs alone (0700), as ~/.local/state should be.
    if (fs::create_directories(folder, ec) && !ec) fs::permissions(folder, fs::perms::owner_all, ec);
    if (ec || !fs::is_directory(folder)) {
        error = "cannot make the folder " + folder.string() + (ec ? ": " + ec.message() : "");
        return false;
    }
    try {
        save_document(plugins, doc, file); // a temporary file beside it, fsync'ed, renamed over it
    } catch (const std::exception &e) {
        error = e.what();
        return false;
    }
    // The rename is on the disk once the folder is.
    const int fd = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd >= 0) {
        ::fsync(fd);
        ::close(fd);
    }
    return true;
}

void AutosaveClock::update(double now, bool dirty, std::uint64_t version) {
    if (pending_) counted_ += std::max(0.0, now - last_);
    last_ = now;
    if (!dirty) counted_ = 0.0; // nothing unsaved: the next change starts from 0
    pending_ = interval_ > 0.0 && dirty && version != written_version_;
}

bool AutosaveClock::due(double now) const { return pending_ && counted(now) >= interval_; }

std::optional<double> AutosaveClock::seconds_to_wait(double now) const {
    if (!pending_) return std::nullopt;
    return std::max(0.0, interval_ - counted(now));
}

void AutosaveClock::written(std::uint64_t version) {
    written_version_ = version;
    pending_ = false;
    counted_ = 0.0;
}

void AutosaveClock::failed(double now) {
    counted_ = 0.0;
    last_ = now;
}

std::optional<Autosaver::Offer> Autosaver::offer(const fs::path &document) {
    offer_.reset();
    if (folder_.empty()) return std::nullopt;
    const fs::path file = recovery_file(folder_, document);
    struct stat rs {};
    if (::stat(file.c_str(), &rs) != 0 || !S_ISREG(rs.st_mode)) return std::nullopt;
    struct stat ds {};
    // Older than the document: the document was saved after it (by another run, another tool).
    // Not offered; this run's first autosave replaces it.
    if (!document.empty() && ::stat(document.c_str(), &ds) == 0 && !newer(rs, ds)) return std::nullopt;
    offer_ = Offer{file, document, rs.st_mtim.tv_sec};
    return offer_;
}

bool Autosaver::recover(EditorSession &session, std::string &message) {
    if (!offer_) return false;
    const Offer o = *offer_;
    offer_.reset();
    std::string error;
    if (!session.recover(o.file, o.document, error)) {
        message = "could not recover the unsaved work (it stays in " + o.file.string() + "): " + error;
        return false;
    }
    // The recovered work is in that file already: no autosave until it changes.
    current_ = o.file;
    key_of_ = session.path();
    key_ = o.file;
    clock_.written(session.version());
    message = "recovered the unsaved work from " + local_time_label(o.written) + "; export (x) to keep it";
    return true;
}

bool Autosaver::discard(std::string &message) {
    if (!offer_) return false;
    const Offer o = *offer_;
    offer_.reset();
    // Set aside rather than deleted: a reflex Esc loses nothing until the next discard.
    const fs::path aside = folder_ / "discarded.ani";
    std::error_code ec;
    fs::rename(o.file, aside, ec);
    if (ec) {
        std::error_code removed;
        fs::remove(o.file, removed);
        if (removed) {
            message = "could not discard " + o.file.string() + ": " + removed.message();
            return false;
        }
        message = "discarded the unsaved work from " + local_time_label(o.written);
        return true;
    }
    message = "discarded the unsaved work from " + local_time_label(o.written) + " (set aside as " +
              aside.string() + " until the next discard)";
    return true;
}

const fs::path &Autosaver::key(const EditorSession &session) {
    if (!key_ || key_of_ != session.path()) {
        key_of_ = session.path();
        key_ = recovery_file(folder_, key_of_);
    }
    return *key_;
}

void Autosaver::remove_current() {
    if (!current_) return;
    std::error_code ec;
    fs::remove(*current_, ec);
    current_.reset();
}

std::string Autosaver::tick(const EditorSession &session, double now, bool *failed) {
    if (failed) *failed = false;
    if (folder_.empty()) return "";
    // Exported (or undone to what was saved): the work is in the document's own file now. A
    // document saved under a new name (a scene's first export) is a new document to recover.
    if (current_ && (!session.dirty() || *current_ != key(session))) remove_current();
    clock_.update(now, session.dirty(), session.version());
    if (!on_ || offer_ || !clock_.due(now)) return "";
    std::string error;
    const fs::path file = key(session);
    if (!write_recovery(plugins_, session.document(), file, error)) {
        clock_.failed(now);
        if (failed) *failed = true;
        return "autosave failed (the work is still here; export it with x): " + error;
    }
    clock_.written(session.version());
    current_ = file;
    return "autosaved";
}

std::optional<double> Autosaver::seconds_to_wait(double now) const {
    if (!on_ || offer_) return std::nullopt;
    return clock_.seconds_to_wait(now);
}

std::string Autosaver::quit(const EditorSession &session, bool *failed) {
    if (failed) *failed = false;
    if (!session.dirty() || folder_.empty()) {
        remove_current();
        return "";
    }
    // Quit without exporting: as Blender's quit.blend, the last unsaved work is kept (never
    // offered at a start; open or copy it by hand), and the document's recovery file goes.
    const fs::path file = folder_ / "quit.ani";
    std::string error;
    if (!write_recovery(plugins_, session.document(), file, error)) {
        if (failed) *failed = true; // the document's recovery file stays, offered at the next start
        return "could not keep the unsaved work in " + file.string() + ": " + error;
    }
    remove_current();
    return "the unsaved work is kept in " + file.string();
}

std::string local_time_label(std::time_t t) {
    std::tm tm{};
    localtime_r(&t, &tm);
    char text[64];
    std::strftime(text, sizeof text, "%Y-%m-%d %H:%M:%S", &tm);
    return text;
}

std::string home_path(const fs::path &path) {
    const char *home = std::getenv("HOME");
    const std::string p = path.string();
    if (!home || !*home) return p;
    std::string h = home;
    while (h.size() > 1 && h.back() == '/') h.pop_back();
    if (p.size() > h.size() && p.compare(0, h.size(), h) == 0 && p[h.size()] == '/') return "~" + p.substr(h.size());
    return p;
}

} // namespace animator
