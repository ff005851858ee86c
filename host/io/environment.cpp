#include "io/environment.hpp"

namespace animator {

Environment::Environment() : Environment(AssetPaths::default_roots(), PluginRegistry::default_search_dirs()) {}

Environment::Environment(std::vector<std::filesystem::path> asset_roots,
                         const std::vector<std::filesystem::path> &plugin_dirs, PluginRegistry::LogSink log)
    : assets(std::move(asset_roots)), plugins(plugin_dirs, std::move(log)) {
    plugins.provide_extension(ANI_EXT_ASSETS, assets.extension());
}

} // namespace animator
