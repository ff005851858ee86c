#include "document/edits.hpp"

namespace animator {

void SetStateEdit::apply(Document &doc) {
    const Keyframe &k = doc.keyframe_at(keyframe_ms_);
    if (model_ < 0 || model_ >= static_cast<int>(k.states.size()))
        throw DocumentError("no model " + std::to_string(model_));
    before_ = k.states[static_cast<size_t>(model_)];
    doc.set_state(keyframe_ms_, model_, after_);
}

void SetStateEdit::revert(Document &doc) { doc.set_state(keyframe_ms_, model_, before_); }

void MoveKeyEdit::apply(Document &doc) {
    const Keyframe &k = doc.keyframe_at(keyframe_ms_);
    if (model_ < 0 || model_ >= static_cast<int>(k.states.size()) || !k.states[static_cast<size_t>(model_)])
        throw DocumentError("model " + std::to_string(model_) + " has no key at " + std::to_string(keyframe_ms_) + " ms");
    before_ = *k.states[static_cast<size_t>(model_)];
    ModelState after = before_;
    after.center += offset_;
    doc.set_state(keyframe_ms_, model_, after);
}

void SetCameraEdit::apply(Document &doc) {
    before_ = doc.keyframe_at(keyframe_ms_).camera;
    doc.set_camera(keyframe_ms_, after_);
}

void SetCameraEdit::revert(Document &doc) { doc.set_camera(keyframe_ms_, before_); }

void SetModelEdit::apply(Document &doc) {
    if (index_ < 0 || index_ >= static_cast<int>(doc.models().size()))
        throw DocumentError("no model " + std::to_string(index_));
    before_ = doc.models()[static_cast<size_t>(index_)];
    doc.set_model(index_, after_);
}

void SetSettingsEdit::apply(Document &doc) {
    before_ = doc.settings();
    removed_ = doc.set_settings(after_);
}

void SetSettingsEdit::revert(Document &doc) {
    doc.set_settings(before_);
    for (const auto &k : removed_) doc.insert_keyframe(k);
    removed_.clear();
}

void CompositeEdit::apply(Document &doc) {
    std::size_t applied = 0;
    try {
        for (; applied < edits_.size(); ++applied) edits_[applied]->apply(doc);
    } catch (...) {
        while (applied > 0) edits_[--applied]->revert(doc);
        throw;
    }
}

void CompositeEdit::revert(Document &doc) {
    for (auto it = edits_.rbegin(); it != edits_.rend(); ++it) (*it)->revert(doc);
}

} // namespace animator
