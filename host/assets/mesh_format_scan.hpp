// The mesh formats beside OBJ (PLY, STL, glTF), chosen by the file's extension, and a look at
// each file before assimp parses it, refusing what would make assimp allocate without bound
// or open another file: a PLY header promising more elements than the file holds or than a
// scene's mesh needs (a binary STL takes 50 bytes a triangle: the 64 MiB limit bounds it), a glTF accessor of more than that many elements (a
// sparse one needs no bytes in the file at all), a glTF that names a file outside itself (docs/
// assets.md, "What the loaders read").
#pragma once

#include <cstddef>
#include <string>

namespace animator {

enum class MeshFormat { Obj, Ply, Stl, Glb, Gltf };

// At most this many vertices or faces (a PLY element, a glTF accessor): far beyond any mesh of a scene, small enough that what assimp allocates for them
// stays within a few hundred MiB.
constexpr std::size_t kMaxMeshElements = std::size_t{1} << 22; // 4,194,304

// By extension (any case): .ply, .stl, .glb, .gltf; anything else is read as OBJ, whatever it
// is called (assimp's other importers are never reached).
MeshFormat mesh_format_of(const std::string &path);
// The name assimp is given for the file's bytes ("mesh.ply"): it picks its importer by it.
const char *assimp_name_of(MeshFormat format);

// "" when `bytes` (the file `name`, in `format`) is within the limits, else "<name>: why not".
// OBJ files are checked by obj_scan.hpp instead.
std::string mesh_beyond_limits(const std::string &name, MeshFormat format, const std::string &bytes);

} // namespace animator
