// Where assets named in a document live: meshes, textures, skyboxes and sounds are found by id
// under a list of asset roots (each with meshes/, textures/, skyboxes/, sounds/), and meshes
// also by a path relative to the document.
#pragma once

#include <animator/assets.h>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace animator {

class AssetPaths {
  public:
    explicit AssetPaths(std::vector<std::filesystem::path> roots) : roots_(std::move(roots)) {}
    AssetPaths(const AssetPaths &) = delete; // the extension points back at this object
    AssetPaths &operator=(const AssetPaths &) = delete;

    // ANIMATOR_ASSET_PATH (':'-separated), then the generated assets beside the executable
    // (<exe>/../assets), then the source tree's assets/ (scenes, animations).
    static std::vector<std::filesystem::path> default_roots();

    // The file (or, for a skybox, the folder) of asset `id`, or nothing. `document` is the file
    // that names it (for paths relative to it), or empty.
    std::optional<std::filesystem::path> resolve(ani_asset_kind kind, const std::string &id,
                                                 const std::filesystem::path &document = {}) const;
    // "looked for meshes/x.obj in: /a, /b": what resolve() tried, for error messages.
    std::string searched(ani_asset_kind kind, const std::string &id,
                         const std::filesystem::path &document = {}) const;

    const std::vector<std::filesystem::path> &roots() const { return roots_; }

    // Every id of this kind found under the roots, sorted, each once (the editor's dropdowns).
    std::vector<std::string> list(ani_asset_kind kind) const;

    // The SDK extension that lets plugins ask the same questions (sdk assets.h). It refers to
    // this object, which must outlive its use.
    const ani_assets_ext *extension() const { return &extension_.ext; }

  private:
    std::vector<std::filesystem::path> candidates(ani_asset_kind kind, const std::string &id,
                                                  const std::filesystem::path &document) const;
    static int32_t resolve_for_plugin(const ani_host *host, int32_t kind, const char *id,
                                      const char *relative_to, char *out, size_t out_size);

    // The extension struct first, so the pointer a plugin holds leads back to its owner.
    struct Extension {
        ani_assets_ext ext;
        const AssetPaths *owner;
    };

    std::vector<std::filesystem::path> roots_;
    Extension extension_{{sizeof(ani_assets_ext), &AssetPaths::resolve_for_plugin}, this};
};

} // namespace animator
