// The Timeline (dope sheet) docked along the bottom of the editor (docs/manual.md, "The
// Timeline"): a ruler in seconds and frames with the playhead (click or drag on it to scrub),
// a row for the camera and one per model with a diamond per key, the spans a model is released
// from its keys (free flight or at rest, from the backend's bake) shaded, and its collisions
// ticked. Keys are selected with clicks (CTRL toggles, SHIFT adds), a box, or a row's name;
// dragging selected keys retimes them (one undoable edit, landing on frames), DELETE removes
// them, CTRL+C and CTRL+V copy them to the playhead. The wheel zooms about the pointer, SHIFT+wheel
// or a middle drag pans, the wheel over the names scrolls the rows. Drawn with Dear ImGui's draw
// lists; its geometry is dope_sheet_layout.hpp's, which is tested without a window.
#pragma once

#include "document/key_edits.hpp"
#include "editor/dope_sheet_layout.hpp"
#include "editor/editor_session.hpp"
#include "editor/view_layout.hpp"

#include <filesystem>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace animator {

class DopeSheet {
  public:
    // Draws the Timeline in `rect` (window coordinates; collapsed, its title bar at the bottom of
    // it) and handles the mouse over it. Returns where it was drawn, for the view to leave it.
    PanelPlace draw(EditorSession &session, const ScreenRect &rect);

    // What a key or a mouse action did, for the status line.
    struct Result {
        bool ok = true;
        std::string message;
    };
    // DELETE, CTRL+C, CTRL+V (editor_app.cpp's keys).
    Result delete_selected(EditorSession &session);
    Result copy(EditorSession &session);
    Result paste(EditorSession &session);
    // ESC: a drag in the Timeline (of keys, a box) stops where it began.
    void cancel_drag() { gesture_ = Gesture::None; }

    const std::set<KeyRef> &selection() const { return selection_; }
    bool has_selection() const { return !selection_.empty(); }
    bool collapsed() const { return collapsed_; }
    // A message from the mouse (a retime refused, keys moved) since the last call, if any.
    std::optional<Result> take_message();

  private:
    enum class Gesture { None, Scrub, PressKey, MoveKeys, Box, Pan };

    void handle_mouse(EditorSession &session, const DopeSheetLayout &layout);
    void tooltip(const EditorSession &session, const DopeSheetLayout &layout) const;
    void retime(EditorSession &session);
    // The selected keys a drag moves: all but those at t = 0.
    std::vector<KeyRef> moving() const;
    void refresh(const EditorSession &session);

    bool collapsed_ = false;
    bool fitted_ = true; // showing the whole animation until the user zooms or pans
    TimeView view_;
    double scroll_ = 0.0;

    std::set<KeyRef> selection_;
    std::vector<CopiedKey> clipboard_;

    Gesture gesture_ = Gesture::None;
    KeyRef grabbed_;
    double press_x_ = 0.0, press_y_ = 0.0;
    TimeView press_view_;
    std::int64_t offset_ms_ = 0; // of the keys being dragged
    bool press_add_ = false, press_toggle_ = false;

    std::optional<Result> message_;
    std::filesystem::path path_; // the file shown: another one starts afresh

    // What the document and the bake hold, found again only when they change.
    std::uint64_t keys_version_ = ~std::uint64_t{0};
    std::vector<KeyRef> keys_;
    std::size_t keys_models_ = 0; // how many models the document had then
    std::uint64_t spans_version_ = ~std::uint64_t{0};
    double spans_baked_ = -1.0;
    std::string spans_backend_;
    std::vector<std::vector<ReleasedSpan>> spans_; // per model
};

} // namespace animator
