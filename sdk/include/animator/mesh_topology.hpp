// animator SDK, optional C++ helper (library animator_mesh_topology): whether a triangle mesh is a
// closed surface wound outward, shared by the backends that need a solid (a mesh that turns must
// enclose a volume) and the host's renderer (a closed mesh's back faces are hidden from outside
// it, so they are not drawn).
#pragma once

#include "animator/physics.h"

#include <string>

namespace ani {

// Whether every edge of the mesh is shared by exactly two triangles that run along it in
// opposite directions (a closed, consistently oriented surface), vertices at the same position
// counting as one (meshes split them for normals and UVs), and the surface encloses a positive
// volume (its triangles face outward). When not, `why` says what is wrong ("edge 3-7 is used by
// 1 triangle", "edge 3-7 runs the same way in triangles 2 and 5", "triangle 4 is degenerate",
// "its triangles face inward or enclose no volume (volume -1.000000)").
bool is_closed(const ani_mesh_view &mesh, std::string *why = nullptr);

} // namespace ani
