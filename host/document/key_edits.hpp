// Edits of keys, as the Timeline (dope sheet, editor/dope_sheet.hpp) makes them: a key is one
// model's (or the camera's) state at one keyframe, and a keyframe keys some models and perhaps
// the camera (document.hpp). Retiming, deleting and pasting keys moves states between
// keyframes: keyframes are made where keys land and removed when their last key leaves (never
// the one at t = 0, which keys everything and stays). Each is one edit of the whole document,
// so `u` takes it back wherever the user is in time.
#pragma once

#include "document/edits.hpp"

#include <cstdint>
#include <optional>
#include <vector>

namespace animator {

// A key: the keyframe's time and the model keyed there (kCameraKey: the camera).
struct KeyRef {
    static constexpr int kCamera = -1;
    std::int64_t time_ms = 0;
    int model = kCamera;
    bool operator==(const KeyRef &o) const { return time_ms == o.time_ms && model == o.model; }
    bool operator!=(const KeyRef &o) const { return !(*this == o); }
    bool operator<(const KeyRef &o) const { return time_ms != o.time_ms ? time_ms < o.time_ms : model < o.model; }
};

// What a key holds: a model's state, or the camera's (for a camera key).
struct KeyValue {
    int model = KeyRef::kCamera;
    ModelState state;
    CameraState camera;
    bool operator==(const KeyValue &o) const {
        return model == o.model && (model == KeyRef::kCamera ? camera == o.camera : state == o.state);
    }
};

// Whether the document has this key.
bool has_key(const Document &doc, const KeyRef &key);
// Every key of the document, in time order (the camera's first at each time, then the models').
std::vector<KeyRef> all_keys(const Document &doc);
// The value of a key the document has (throws DocumentError for one it has not).
KeyValue key_value(const Document &doc, const KeyRef &key);

// Copied keys (CTRL+C): their values with times relative to the earliest of them.
struct CopiedKey {
    std::int64_t offset_ms = 0; // after the earliest copied key
    KeyValue value;
};
std::vector<CopiedKey> copy_keys(const Document &doc, const std::vector<KeyRef> &keys);

// The common base: keeps the keyframes an edit touches as they were, and puts them back.
class KeysEdit : public Edit {
  public:
    void revert(Document &doc) override;
    std::vector<std::int64_t> creates_keyframes() const override { return created_; }
    // Where the edited keys are after apply() (the dope sheet selects them).
    const std::vector<KeyRef> &result() const { return result_; }

  protected:
    // Unkeys `remove`, then sets `place` (making keyframes where none is), then removes the
    // keyframes of `remove` left keying nothing (not t = 0). All or nothing: a problem throws
    // DocumentError with the document unchanged.
    void change(Document &doc, const std::vector<KeyRef> &remove, const std::vector<std::pair<std::int64_t, KeyValue>> &place);

    std::vector<KeyRef> result_;

  private:
    std::vector<Keyframe> before_;       // the touched keyframes that existed, as they were
    std::vector<std::int64_t> created_;  // keyframes the edit made
};

// Moves keys by `offset_ms` (the Timeline's drag). A key landing where its model (or the camera)
// has a key not moved replaces it. Keys at t = 0 do not move (the initial placement stays);
// throws when one is asked to, or when a key would land before 0 or past the max time.
class RetimeKeysEdit final : public KeysEdit {
  public:
    RetimeKeysEdit(std::vector<KeyRef> keys, std::int64_t offset_ms) : keys_(std::move(keys)), offset_ms_(offset_ms) {}
    void apply(Document &doc) override;
    std::string label() const override { return "retime keys"; }

  private:
    std::vector<KeyRef> keys_;
    std::int64_t offset_ms_;
};

// Deletes keys (DELETE in the Timeline); throws for a key at t = 0 or one the document has not.
class DeleteKeysEdit final : public KeysEdit {
  public:
    explicit DeleteKeysEdit(std::vector<KeyRef> keys) : keys_(std::move(keys)) {}
    void apply(Document &doc) override;
    std::string label() const override { return "delete keys"; }

  private:
    std::vector<KeyRef> keys_;
};

// Pastes copied keys with the earliest at `at_ms` (CTRL+V at the playhead), replacing keys the
// models already have at those times; throws when one would land past the max time or names a
// model the document has not.
class PasteKeysEdit final : public KeysEdit {
  public:
    PasteKeysEdit(std::vector<CopiedKey> keys, std::int64_t at_ms) : keys_(std::move(keys)), at_ms_(at_ms) {}
    void apply(Document &doc) override;
    std::string label() const override { return "paste keys"; }

  private:
    std::vector<CopiedKey> keys_;
    std::int64_t at_ms_;
};

} // namespace animator
