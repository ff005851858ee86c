// Edits: every change a user makes to a document, as an object that can apply and revert
// itself, so that the history (history.hpp) can undo and redo it.
#pragma once

#include "document/document.hpp"

#include <memory>
#include <optional>
#include <vector>

namespace animator {

class Edit {
  public:
    virtual ~Edit() = default;
    // Applies the edit. Throws DocumentError, leaving the document unchanged, when it cannot.
    virtual void apply(Document &doc) = 0;
    // Undoes a successful apply().
    virtual void revert(Document &doc) = 0;
    virtual std::string label() const = 0;
    // The keyframe whose undo stack records this edit (seed, "Keys": "each keyframe has its
    // own undo stack"), or none for edits of the whole document (settings, models, the list of
    // keyframes), which go on the document's stack.
    virtual std::optional<std::int64_t> keyframe() const { return std::nullopt; }
    // The time of the keyframe this edit creates, if it creates one: that keyframe starts with
    // a fresh undo stack.
    virtual std::optional<std::int64_t> creates_keyframe() const { return std::nullopt; }
    // Every keyframe this edit creates (an edit of keys can make several).
    virtual std::vector<std::int64_t> creates_keyframes() const {
        const auto one = creates_keyframe();
        return one ? std::vector<std::int64_t>{*one} : std::vector<std::int64_t>{};
    }
};

class SetStateEdit final : public Edit {
  public:
    // With nullopt: unkeys the model at that keyframe.
    SetStateEdit(std::int64_t keyframe_ms, int model, std::optional<ModelState> state)
        : keyframe_ms_(keyframe_ms), model_(model), after_(state) {}
    void apply(Document &doc) override;
    void revert(Document &doc) override;
    std::string label() const override { return "transform model"; }
    std::optional<std::int64_t> keyframe() const override { return keyframe_ms_; }

  private:
    std::int64_t keyframe_ms_;
    int model_;
    std::optional<ModelState> before_, after_;
};

// Moves a model's key by an offset, as an edit of the whole document (its undo is reachable at
// any keyframe, as it is made wherever the user is in time): the editor's fix of an overlap.
class MoveKeyEdit final : public Edit {
  public:
    MoveKeyEdit(std::string label, std::int64_t keyframe_ms, int model, glm::dvec3 offset)
        : label_(std::move(label)), keyframe_ms_(keyframe_ms), model_(model), offset_(offset) {}
    // Throws DocumentError when the model has no key at that keyframe.
    void apply(Document &doc) override;
    void revert(Document &doc) override { doc.set_state(keyframe_ms_, model_, before_); }
    std::string label() const override { return label_; }

  private:
    std::string label_;
    std::int64_t keyframe_ms_;
    int model_;
    glm::dvec3 offset_;
    ModelState before_;
};

class SetCameraEdit final : public Edit {
  public:
    SetCameraEdit(std::int64_t keyframe_ms, std::optional<CameraState> camera)
        : keyframe_ms_(keyframe_ms), after_(camera) {}
    void apply(Document &doc) override;
    void revert(Document &doc) override;
    std::string label() const override { return "move camera"; }
    std::optional<std::int64_t> keyframe() const override { return keyframe_ms_; }

  private:
    std::int64_t keyframe_ms_;
    std::optional<CameraState> before_, after_;
};

class AddKeyframeEdit final : public Edit {
  public:
    explicit AddKeyframeEdit(Keyframe keyframe) : keyframe_(std::move(keyframe)) {}
    void apply(Document &doc) override { doc.insert_keyframe(keyframe_); }
    void revert(Document &doc) override { doc.delete_keyframe(keyframe_.time_ms); }
    std::string label() const override { return "add keyframe"; }
    std::optional<std::int64_t> creates_keyframe() const override { return keyframe_.time_ms; }

  private:
    Keyframe keyframe_;
};

class DeleteKeyframeEdit final : public Edit {
  public:
    explicit DeleteKeyframeEdit(std::int64_t time_ms) : time_ms_(time_ms) {}
    void apply(Document &doc) override { removed_ = doc.delete_keyframe(time_ms_); }
    void revert(Document &doc) override { doc.insert_keyframe(removed_); }
    std::string label() const override { return "delete keyframe"; }

  private:
    std::int64_t time_ms_;
    Keyframe removed_;
};

class AddModelEdit final : public Edit {
  public:
    AddModelEdit(Model model, const ModelState &state) : model_(std::move(model)), state_(state) {}
    void apply(Document &doc) override { doc.add_model(model_, state_); }
    void revert(Document &doc) override { doc.remove_last_model(); }
    std::string label() const override { return "add model"; }

  private:
    Model model_;
    ModelState state_;
};

// Changes a model's properties (physics, material, sounds...).
class SetModelEdit final : public Edit {
  public:
    SetModelEdit(int index, Model model) : index_(index), after_(std::move(model)) {}
    void apply(Document &doc) override;
    void revert(Document &doc) override { doc.set_model(index_, before_); }
    std::string label() const override { return "change model"; }

  private:
    int index_;
    Model before_, after_;
};

// Changes the animation settings. A shorter max time deletes later keyframes; reverting puts
// them back.
class SetSettingsEdit final : public Edit {
  public:
    explicit SetSettingsEdit(Settings settings) : after_(std::move(settings)) {}
    void apply(Document &doc) override;
    void revert(Document &doc) override;
    std::string label() const override { return "change settings"; }

  private:
    Settings before_, after_;
    std::vector<Keyframe> removed_;
};

// Several edits undone and redone as one (a drag that moves every selected model). They go on
// the stack of the first one's keyframe.
class CompositeEdit final : public Edit {
  public:
    CompositeEdit(std::string label, std::vector<std::unique_ptr<Edit>> edits)
        : label_(std::move(label)), edits_(std::move(edits)) {}
    // Applies each in order; if one throws, those already applied are reverted first.
    void apply(Document &doc) override;
    void revert(Document &doc) override;
    std::string label() const override { return label_; }
    std::optional<std::int64_t> keyframe() const override {
        return edits_.empty() ? std::nullopt : edits_.front()->keyframe();
    }
    std::optional<std::int64_t> creates_keyframe() const override {
        return edits_.empty() ? std::nullopt : edits_.front()->creates_keyframe();
    }

  private:
    std::string label_;
    std::vector<std::unique_ptr<Edit>> edits_;
};

} // namespace animator
