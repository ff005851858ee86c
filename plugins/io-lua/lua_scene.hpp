// The CS488 scene API (gr.node, gr.mesh, gr.joint, gr.material and node methods) plus the
// animator's extensions (docs/scene-lua.md), run in a sandbox, turned into plain scene data.
#pragma once

#include "scene_result.hpp"

#include <string>

namespace lua_scene {

// Runs the scene `text` (read from `path`, which names it in messages) in a sandbox and fills
// `out`. On failure returns false with "path:line: what went wrong" in `error`. Touches no file
// and calls nothing of the host's: it is what runs in the isolated child (scene_isolation).
bool run_scene(const std::string &path, const std::string &text, SceneResult &out, std::string &error);

} // namespace lua_scene
