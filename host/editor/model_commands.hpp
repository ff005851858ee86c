// The editor's Add model, Duplicate and Delete (docs/manual.md, "Adding, duplicating and
// deleting models"): SHIFT+A and the Add model button open a dialog listing the meshes on the
// asset path with a field for any mesh file; SHIFT+D duplicates the selected models; DELETE
// (when no keys are selected in the Timeline) and the Delete button ask first, naming what goes,
// Enter deleting and ESC keeping them. The buttons sit on the Outliner's header line. Everything
// goes through the session (editor_session.hpp), each one undoable edit.
#pragma once

#include "editor/editor_session.hpp"

#include <functional>
#include <string>
#include <vector>

namespace animator {

class ModelCommands {
  public:
    // What happened, for the status line (true: an error).
    using Say = std::function<void(const std::string &, bool)>;

    void ask_add() { add_asked_ = true; }
    void duplicate(EditorSession &session, const Say &say);
    // Asks "Delete 'cube' and the 2 models under it?"; with nothing selected says so.
    void ask_delete(const EditorSession &session, const Say &say);

    // The buttons, on the line of the item drawn last (the Outliner's header), at its right.
    void buttons(EditorSession &session, const Say &say);
    // The Add model and Delete dialogs, when asked for (modal: the editor's keys wait).
    // The asset path is listed when the Add model dialog opens.
    void dialogs(EditorSession &session, const AssetPaths &assets, const Say &say);

  private:
    bool add_asked_ = false, delete_asked_ = false;
    std::string add_text_;
    std::vector<std::string> mesh_ids_;
    int add_frames_ = 0;
    std::string delete_question_;
};

// What the Add model dialog adds for `text` (typed, the ids listed `ids`): the first id
// containing it, or, for text that names a file (a '/' or a mesh extension in it), that file.
struct AddChoice {
    enum Kind { None, Asset, File } kind = None;
    std::string value;
};
AddChoice add_choice(const std::string &text, const std::vector<std::string> &ids);
// The ids listed for `text`: those containing it (all for "").
std::vector<std::string> matching_ids(const std::string &text, const std::vector<std::string> &ids);

} // namespace animator
