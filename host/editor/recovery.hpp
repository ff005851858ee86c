// Autosave and recovery (docs/manual.md, "Autosave and recovery"): while a document has changes
// that are in no file, every ANIMATOR_AUTOSAVE_SECONDS (120 s) of such time the editor writes it
// to a recovery file of its own, atomically, with the .ani writer export uses. After a crash or
// a kill, the next start on the same document offers it back.
//
// Recovery files live in $XDG_STATE_HOME/animator/recovery/ (~/.local/state/animator/recovery/
// without it), never beside the user's file: one per document, named after the document's file
// and a hash of its full path ("ball-0123456789abcdef.ani"), or "untitled.ani" for a document
// with no file. Besides them, "quit.ani" holds what was last quit without exporting (Blender's
// quit.blend) and "discarded.ani" what was last discarded at a start; neither is ever offered.
#pragma once

#include "document/document.hpp"
#include "plugin/registry.hpp"

#include <cstdint>
#include <ctime>
#include <filesystem>
#include <optional>
#include <string>

namespace animator {

class EditorSession;

constexpr double kDefaultAutosaveSeconds = 120.0;

// ANIMATOR_AUTOSAVE_SECONDS when set (a number of seconds > 0; 0 turns autosave off), else 120.
// Something else there: the default, and `warning` says why.
double autosave_interval(std::string *warning = nullptr);

// $XDG_STATE_HOME/animator/recovery (an absolute XDG_STATE_HOME only, as the XDG spec says), else
// $HOME/.local/state/animator/recovery; empty without either.
std::filesystem::path recovery_folder();

// The recovery file of `document` (empty: a document with no file) in `folder`.
std::filesystem::path recovery_file(const std::filesystem::path &folder, const std::filesystem::path &document);

// Writes `doc` to `file` with the .ani writer (a temporary file beside it, flushed, renamed over
// it; then the folder is flushed too), making the folder (0700) first. On failure returns false
// with the reason in `error`, and any previous file there is unchanged.
bool write_recovery(PluginRegistry &plugins, const Document &doc, const std::filesystem::path &file,
                    std::string &error);

// How long a document has had changes that are in no file (not the document's, not a recovery
// file), in the seconds of a clock the caller passes: autosave is due after `interval` of it.
// Counting starts at the first change after a save or an autosave; a document back to its saved
// state stops and resets it. The editor sleeps until due() (seconds_to_wait()), no longer.
class AutosaveClock {
  public:
    explicit AutosaveClock(double interval) : interval_(interval) {}
    // Called with the document's state (EditorSession::dirty(), version()) as it goes.
    void update(double now, bool dirty, std::uint64_t version);
    bool due(double now) const;
    // Until due (0: now), or nothing when no unsaved change is waiting (or autosave is off).
    std::optional<double> seconds_to_wait(double now) const;
    // `version` is in the recovery file now; the next change starts counting again.
    void written(std::uint64_t version);
    // The write failed at `now`: tried again after another interval.
    void failed(double now);
    double counted(double now) const { return pending_ ? counted_ + (now - last_) : counted_; }

  private:
    double interval_;
    bool pending_ = false;
    double counted_ = 0.0, last_ = 0.0;
    std::uint64_t written_version_ = ~std::uint64_t{0};
};

// The editor's side of it all, with no window: keeps the clock, writes the recovery file when
// due, removes it when the work no longer needs it, and offers and answers recovery at a start.
class Autosaver {
  public:
    Autosaver(PluginRegistry &plugins, std::filesystem::path folder, double interval)
        : plugins_(plugins), folder_(std::move(folder)), clock_(interval), on_(interval > 0 && !folder_.empty()) {}

    const std::filesystem::path &folder() const { return folder_; }

    struct Offer {
        std::filesystem::path file;     // the recovery file
        std::filesystem::path document; // the document it recovers (empty: untitled)
        std::time_t written = 0;
    };
    // At a start on `document` (empty: untitled): its recovery file, when there is one newer than
    // the document (or the document has no file, or it is gone). Kept as the pending offer.
    std::optional<Offer> offer(const std::filesystem::path &document);
    bool offer_pending() const { return offer_.has_value(); }
    // The answers. Recover opens the offer in `session` as unsaved changes to the document
    // (EditorSession::recover); the file stays until the work is exported or quit. Discard
    // moves it to discarded.ani. Both say what they did in `message`; false on a failure.
    bool recover(EditorSession &session, std::string &message);
    bool discard(std::string &message);

    // Each pass of the editor's loop: removes the recovery file once the document is saved (or
    // back to its saved state), and writes the document when autosave is due. Returns what to
    // say: "" (nothing happened), "autosaved" or why autosave failed (`failed`).
    std::string tick(const EditorSession &session, double now, bool *failed = nullptr);
    std::optional<double> seconds_to_wait(double now) const;
    // Quitting: unsaved work goes to quit.ani, and the document's recovery file goes.
    // Returns what to say, or "" (`failed`: the unsaved work could not be kept).
    std::string quit(const EditorSession &session, bool *failed = nullptr);

    // The recovery file this session wrote or recovered from, while it has one.
    const std::optional<std::filesystem::path> &current() const { return current_; }

  private:
    void remove_current();
    // The recovery file of the session's document (recomputed when its path changes).
    const std::filesystem::path &key(const EditorSession &session);

    PluginRegistry &plugins_;
    std::filesystem::path folder_;
    AutosaveClock clock_;
    bool on_;
    std::optional<Offer> offer_;
    std::optional<std::filesystem::path> current_;
    std::filesystem::path key_of_;
    std::optional<std::filesystem::path> key_;
};

// "2024-05-02 14:03:12", in local time.
std::string local_time_label(std::time_t t);
// A path for people to read: under $HOME, as "~/...".
std::string home_path(const std::filesystem::path &path);

} // namespace animator
