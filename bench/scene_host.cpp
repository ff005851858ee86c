// The benchmark's side of tests/physics-bullet/bullet_support.hpp: what the exact scenes
// (tests/physics-bullet/scenes.cpp, compiled into animator-bench as they are) need from their
// host, without Catch2 or the test tree's paths. Plugins are found beside the executable, assets
// in the build's generated folder, then assets/ (AssetPaths::default_roots); the plugins' log is
// kept quiet (the scenes' overlaps and warnings are expected).
#include "bullet_support.hpp"

namespace animator::bullet_test {

Environment &env() {
    static Environment e(AssetPaths::default_roots(), PluginRegistry::default_search_dirs(),
                         [](ani_log_level, const std::string &, const std::string &) {});
    return e;
}

} // namespace animator::bullet_test
