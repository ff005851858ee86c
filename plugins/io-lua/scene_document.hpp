// Scene data (what a scene file made) as the document the host opens: one keyframe at t = 0,
// each mesh looked for in the host's asset folders (one not found is a warning), the scene's warnings in the host's log.
#pragma once

#include "scene_result.hpp"

#include <animator/document_builder.hpp>
#include <animator/plugin.h>

#include <string>

namespace lua_scene {

// The scene's warnings, and one for each mesh that is not found, go to the host's log.
void build_document(const SceneResult &scene, const std::string &path, const ani_host *host,
                    ani::OwnedDocument &doc);

} // namespace lua_scene
