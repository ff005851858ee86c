// Documents with models copied or removed as a whole: what the editor's Duplicate and Delete
// make (docs/manual.md, "Adding, duplicating and deleting models"). Each is one undoable edit,
// a snapshot of the document before and after, on the document's undo stack.
#pragma once

#include "document/edits.hpp"

#include <set>
#include <string>
#include <vector>

namespace animator {

// `models` and every model under one of them in the scene tree.
std::set<int> with_descendants(const Document &doc, const std::set<int> &models);

// `doc` without the models in `removed`, which must hold every model under one it holds (else
// DocumentError): the others keep their order, properties and keys; parents are renumbered.
Document without_models(const Document &doc, const std::set<int> &removed);

// A copy of model `original` named `name`, its center moved by `offset` (in its parent's
// frame) at every key of it.
struct ModelCopy {
    int original = -1;
    std::string name;
    glm::dvec3 offset{0.0};
};

// `doc` with the copies appended in order, each with its original's properties and keys. A copy
// whose original's parent is copied too (earlier in `copies`) hangs under that parent's copy,
// else under the original's parent. Throws DocumentError for a taken name or a bad index.
Document with_copies(const Document &doc, const std::vector<ModelCopy> &copies);

// A name not taken in `doc`, in Blender's style: `base` when free, else base.001, base.002...
// A base that already ends in .NNN counts on from its stem ("cube.001" -> "cube.002").
std::string unique_model_name(const Document &doc, const std::string &base,
                              const std::set<std::string> &also_taken = {});

// Takes the document from `before` to `after` whole (and back). Applied to another document
// than `before` it throws, changing nothing: a snapshot only undoes what it saw.
class ReplaceDocumentEdit final : public Edit {
  public:
    ReplaceDocumentEdit(std::string label, Document before, Document after)
        : label_(std::move(label)), before_(std::move(before)), after_(std::move(after)) {}
    void apply(Document &doc) override;
    void revert(Document &doc) override { doc = before_; }
    std::string label() const override { return label_; }

  private:
    std::string label_;
    Document before_, after_;
};

} // namespace animator
