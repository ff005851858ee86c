// A pass over an OBJ file's text before assimp parses it, refusing at its line what would make
// assimp take minutes or gigabytes: a file is linear to read, but assimp's OBJ importer is
// quadratic in the number of objects, groups and material changes, and its triangulation in the
// corners of a polygon (measured: 50,000 'usemtl' lines, 1.5 MB, take 90 s; one polygon of
// 20,000 corners 6 s). The limits are far beyond any mesh a scene uses (docs/assets.md, "What
// the loaders read").
#pragma once

#include <cstddef>
#include <string>

namespace animator {

constexpr std::size_t kMaxMeshFileBytes = std::size_t{64} << 20;    // 64 MiB
constexpr std::size_t kMaxObjParts = 1024;                          // 'o', 'g' and 'usemtl' lines
constexpr std::size_t kMaxPolygonCorners = 1024;                    // the corners of one 'f'
constexpr std::size_t kMaxTriangulationWork = std::size_t{1} << 26; // sum of corners^2 over faces

// "" when `text` is within the limits, else "<name>:<line>: what is too large".
std::string obj_beyond_limits(const std::string &name, const std::string &text);

} // namespace animator
