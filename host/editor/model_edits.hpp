// Add model, Duplicate and Delete (docs/manual.md, "Adding, duplicating and deleting models"),
// the parts that need no session: the name a new model gets, how its mesh is written in the
// document, how far a copy is moved, and what the status line and the question say. The
// session (editor_session.hpp) makes each one undoable edit from these.
#pragma once

#include "assets/mesh.hpp"
#include "document/model_list.hpp"

#include <glm/mat4x4.hpp>

#include <filesystem>
#include <memory>
#include <set>
#include <string>
#include <vector>

namespace animator {

// The mesh of a file as the document names it: relative to the document's folder when the file
// is under it and the document is saved there (`saved_there`), else the absolute path. A
// document not yet saved (or saved elsewhere, a scene exported to animations/) names it
// absolutely, so the name still finds it after the export.
std::string mesh_reference(const std::filesystem::path &file, const std::filesystem::path &document, bool saved_there);

// A new model's name from its mesh: the file's stem ("meshes/bunny.ply" -> "bunny").
std::string name_from_mesh(const std::string &mesh);

// How far a copy of `model` moves so that it does not overlap its original: the diameter of
// the bounding sphere around its mesh and those of the models under it (world metres, at the
// poses whose world matrices are `world`), or 1 m for an empty with nothing drawn under it.
double copy_distance(const Document &doc, const std::vector<std::shared_ptr<const Mesh>> &meshes,
                     const std::vector<glm::dmat4> &world, int model);

// The copies Duplicate makes of `selected` (each with what is under it, in document order): a
// unique name each, and for each copied model whose parent is not copied too, an offset of
// copy_distance() along the world's +x, turned into its parent's frame; the models under it
// follow it unmoved.
std::vector<ModelCopy> plan_copies(const Document &doc, const std::vector<std::shared_ptr<const Mesh>> &meshes,
                                   const std::vector<glm::dmat4> &world, const std::set<int> &selected);

// "'cube'", "'cube' and the 2 models under it", "3 models and the 2 models under them": the
// models Delete removes (`deleted`, from the selection `selected`), in the question it asks and
// the status line's "deleted ...".
std::string deletion_phrase(const Document &doc, const std::set<int> &selected, const std::set<int> &deleted);

} // namespace animator
