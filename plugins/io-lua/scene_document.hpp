// Scene data (what a scene file made) as the document the host opens: one keyframe at t = 0,
// each mesh found in the host's asset folders, the scene's warnings in the host's log.
#pragma once

#include "scene_result.hpp"

#include <animator/document_builder.hpp>
#include <animator/plugin.h>

#include <string>

namespace lua_scene {

// On failure (a mesh that is not found) returns false with "path:line: ..." in `error`.
bool build_document(const SceneResult &scene, const std::string &path, const ani_host *host,
                    ani::OwnedDocument &doc, std::string &error);

} // namespace lua_scene
