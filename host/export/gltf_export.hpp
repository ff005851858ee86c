// glTF 2.0 export (docs/export.md): a baked animation as a .glb or .gltf file that Blender, game
// engines and web viewers open: the models as nodes of the scene's tree with their meshes
// (normals, UVs) and materials, the camera, the lights, and one animation whose keys hold the
// motion exactly where glTF can (export_motion.hpp). Written with tinygltf.
#pragma once

#include "assets/asset_paths.hpp"
#include "assets/mesh.hpp"
#include "export/export_motion.hpp"
#include "timeline/timeline.hpp"

#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace animator {

struct ExportError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

struct GltfExportReport {
    // What glTF has no equivalent for, and what was written instead (the skybox, cel shading, a
    // light's falloff...), each once: for the user.
    std::vector<std::string> notes;
    std::size_t nodes = 0, channels = 0, keys = 0;
    std::size_t merged_keys = 0; // keys float32 could not tell apart from the one before
    MotionKeyStats pieces;
};

// Writes `out` (.glb: binary; .gltf: JSON with its buffers and images inside) from the timeline,
// which must be baked to `options.until`. `meshes` has one entry per model (null for an empty),
// as the timeline's; `document` is the animation's file (textures are found beside it too).
// Nothing is written over `out` unless the whole file is: it is written beside it and renamed.
// Throws ExportError naming the file and what went wrong.
GltfExportReport export_gltf(const Timeline &timeline,
                             const std::vector<std::shared_ptr<const Mesh>> &meshes,
                             const AssetPaths &assets, const std::filesystem::path &document,
                             const std::filesystem::path &out, const MotionKeyOptions &options);

} // namespace animator
