// Writes a Mesh as Wavefront OBJ text.
#pragma once

#include "mesh.hpp"

#include <filesystem>
#include <string>

namespace animator::assetgen {

std::string to_obj(const Mesh &mesh, const std::string &comment);
void write_obj(const std::filesystem::path &path, const Mesh &mesh, const std::string &comment);

} // namespace animator::assetgen
