// The Model Interface's fields, one by one, so that a change of one field can go to every
// selected model and leave each model's other properties its own (docs/manual.md, "The Model
// Interface"): which fields differ among the selected ("mixed"), and the one undoable edit that
// sets a field on all of them. Pure, tested without a window (tests/session/model_fields_test.cpp).
#pragma once

#include "document/edits.hpp"

#include <memory>
#include <set>
#include <string>

namespace animator {

// A property the Model Interface edits (the name is the Outliner's: a rename is of one model).
enum class ModelField {
    Dynamics,
    Gravity,
    Mass,
    Velocity, // the initial velocity, at t = 0
    Kd,
    Ks,
    Texture,
    Tint,
    Shininess,
    Reflectivity,
    Transparency,
    RefractiveIndex,
    CollisionSound,
    MovingSound,
    // Rigid body (issue 18), after the others so that the earlier keep their values.
    Restitution,
    Friction,
    Rotates,
    AngularVelocity, // at t = 0, rad/s about world axes
};

// Copies `field` of `from` into `to`, and nothing else.
void copy_field(ModelField field, const Model &from, Model &to);
bool same_field(ModelField field, const Model &a, const Model &b);

// True when the models in `models` (indices into doc) do not all hold the same value of `field`.
bool field_mixed(const Document &doc, const std::set<int> &models, ModelField field);

// One edit that sets `field` of every model in `models` to its value in `from`, the models'
// other properties untouched: a SetModelEdit for each model it changes, several as one
// CompositeEdit (one undo). Null when no model would change. Throws DocumentError for an index
// that is not a model's.
std::unique_ptr<Edit> field_edit(const Document &doc, const std::set<int> &models, ModelField field, const Model &from);

// Why `name` cannot be model `index`'s new name ("" when it can): empty, or another model's.
// Surrounding spaces are not part of a name: trim_name() takes them off first.
std::string check_rename(const Document &doc, int index, const std::string &name);
std::string trim_name(const std::string &name);

} // namespace animator
