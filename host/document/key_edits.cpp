#include "document/key_edits.hpp"

#include <algorithm>
#include <set>

namespace animator {

namespace {

std::string describe(const Document &doc, const KeyRef &key) {
    const std::string what = key.model == KeyRef::kCamera ? std::string("the camera")
                             : key.model >= 0 && key.model < static_cast<int>(doc.models().size())
                                 ? "model '" + doc.models()[static_cast<size_t>(key.model)].name + "'"
                                 : "model " + std::to_string(key.model);
    return what + " at " + std::to_string(key.time_ms) + " ms";
}

std::vector<KeyRef> unique_keys(std::vector<KeyRef> keys) {
    std::sort(keys.begin(), keys.end());
    keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
    return keys;
}

bool keys_nothing(const Keyframe &k) {
    return !k.camera && std::none_of(k.states.begin(), k.states.end(), [](const auto &s) { return s.has_value(); });
}

void set_key(Document &doc, std::int64_t time_ms, const KeyValue &value) {
    if (value.model == KeyRef::kCamera) doc.set_camera(time_ms, value.camera);
    else doc.set_state(time_ms, value.model, value.state);
}

void unset_key(Document &doc, const KeyRef &key) {
    if (key.model == KeyRef::kCamera) doc.set_camera(key.time_ms, std::nullopt);
    else doc.set_state(key.time_ms, key.model, std::nullopt);
}

} // namespace

bool has_key(const Document &doc, const KeyRef &key) {
    const int i = doc.find_keyframe(key.time_ms);
    if (i < 0) return false;
    const Keyframe &k = doc.keyframes()[static_cast<size_t>(i)];
    if (key.model == KeyRef::kCamera) return k.camera.has_value();
    return key.model >= 0 && key.model < static_cast<int>(k.states.size()) && k.states[static_cast<size_t>(key.model)].has_value();
}

std::vector<KeyRef> all_keys(const Document &doc) {
    std::vector<KeyRef> out;
    for (const Keyframe &k : doc.keyframes()) {
        if (k.camera) out.push_back({k.time_ms, KeyRef::kCamera});
        for (size_t m = 0; m < k.states.size(); ++m)
            if (k.states[m]) out.push_back({k.time_ms, static_cast<int>(m)});
    }
    return out;
}

KeyValue key_value(const Document &doc, const KeyRef &key) {
    if (!has_key(doc, key)) throw DocumentError("there is no key of " + describe(doc, key));
    const Keyframe &k = doc.keyframe_at(key.time_ms);
    KeyValue v;
    v.model = key.model;
    if (key.model == KeyRef::kCamera) v.camera = *k.camera;
    else v.state = *k.states[static_cast<size_t>(key.model)];
    return v;
}

std::vector<CopiedKey> copy_keys(const Document &doc, const std::vector<KeyRef> &keys) {
    std::vector<CopiedKey> out;
    const std::vector<KeyRef> sorted = unique_keys(keys);
    std::optional<std::int64_t> first;
    for (const KeyRef &k : sorted) {
        if (!has_key(doc, k)) continue;
        if (!first) first = k.time_ms;
        out.push_back({k.time_ms - *first, key_value(doc, k)});
    }
    return out;
}

void KeysEdit::change(Document &doc, const std::vector<KeyRef> &remove_in,
                      const std::vector<std::pair<std::int64_t, KeyValue>> &place) {
    const std::vector<KeyRef> remove = unique_keys(remove_in);
    std::set<std::int64_t> touched;
    for (const KeyRef &k : remove) touched.insert(k.time_ms);
    for (const auto &[t, v] : place) touched.insert(t);

    // Done on a copy, so that a problem half-way leaves the document as it was.
    Document trial = doc;
    std::vector<Keyframe> before;
    std::vector<std::int64_t> created;
    for (std::int64_t t : touched)
        if (doc.find_keyframe(t) >= 0) before.push_back(doc.keyframe_at(t));
    for (const KeyRef &k : remove) {
        if (!has_key(trial, k)) throw DocumentError("there is no key of " + describe(doc, k));
        if (k.time_ms == 0) throw DocumentError("the key of " + describe(doc, k) + " is the initial placement: it stays");
        unset_key(trial, k);
    }
    const std::int64_t max_ms = doc.settings().max_time_ms;
    for (const auto &[t, v] : place) {
        if (v.model != KeyRef::kCamera && (v.model < 0 || v.model >= static_cast<int>(doc.models().size())))
            throw DocumentError("there is no model " + std::to_string(v.model));
        if (t < 0 || t > max_ms)
            throw DocumentError("a key of " + describe(doc, {t, v.model}) + " would be outside 0 .. " +
                                std::to_string(max_ms) + " ms");
        if (trial.find_keyframe(t) < 0) {
            Keyframe k;
            k.time_ms = t;
            k.states.resize(doc.models().size());
            trial.insert_keyframe(k);
            created.push_back(t);
        }
        set_key(trial, t, v);
    }
    for (const KeyRef &k : remove) {
        const int i = trial.find_keyframe(k.time_ms);
        if (k.time_ms != 0 && i >= 0 && keys_nothing(trial.keyframes()[static_cast<size_t>(i)])) trial.delete_keyframe(k.time_ms);
    }
    doc = std::move(trial);
    before_ = std::move(before);
    created_ = std::move(created);
    result_.clear();
    for (const auto &[t, v] : place) result_.push_back({t, v.model});
    result_ = unique_keys(result_);
}

void KeysEdit::revert(Document &doc) {
    for (std::int64_t t : created_)
        if (doc.find_keyframe(t) >= 0) doc.delete_keyframe(t);
    for (const Keyframe &k : before_) {
        if (k.time_ms == 0) {
            // The initial keyframe is never removed: its keys go back one by one.
            for (size_t m = 0; m < k.states.size(); ++m) doc.set_state(0, static_cast<int>(m), k.states[m]);
            doc.set_camera(0, k.camera);
            continue;
        }
        if (doc.find_keyframe(k.time_ms) >= 0) doc.delete_keyframe(k.time_ms);
        doc.insert_keyframe(k);
    }
}

void RetimeKeysEdit::apply(Document &doc) {
    const std::vector<KeyRef> keys = unique_keys(keys_);
    std::vector<std::pair<std::int64_t, KeyValue>> place;
    for (const KeyRef &k : keys) {
        if (k.time_ms == 0) throw DocumentError("the key of " + describe(doc, k) + " is the initial placement: it cannot move");
        place.emplace_back(k.time_ms + offset_ms_, key_value(doc, k));
    }
    change(doc, keys, place);
}

void DeleteKeysEdit::apply(Document &doc) { change(doc, keys_, {}); }

void PasteKeysEdit::apply(Document &doc) {
    std::vector<std::pair<std::int64_t, KeyValue>> place;
    for (const CopiedKey &k : keys_) {
        const std::int64_t t = at_ms_ + k.offset_ms;
        if (t > doc.settings().max_time_ms)
            throw DocumentError("the pasted keys would reach " + std::to_string(t) + " ms, past the max time (" +
                                std::to_string(doc.settings().max_time_ms) + " ms)");
        place.emplace_back(t, k.value);
    }
    change(doc, {}, place);
}

} // namespace animator
