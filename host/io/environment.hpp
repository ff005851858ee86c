// What the command line and the editor start from: the plugins found, and the asset folders,
// offered to plugins through the "animator.assets.v1" host extension.
#pragma once

#include "assets/asset_paths.hpp"
#include "plugin/registry.hpp"

namespace animator {

struct Environment {
    AssetPaths assets;
    PluginRegistry plugins;

    // The default asset roots and plugin folders.
    Environment();
    Environment(std::vector<std::filesystem::path> asset_roots,
                const std::vector<std::filesystem::path> &plugin_dirs, PluginRegistry::LogSink log = {});
};

} // namespace animator
