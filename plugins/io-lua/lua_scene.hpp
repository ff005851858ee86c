// The CS488 scene API (gr.node, gr.mesh, gr.joint, gr.material and node methods) plus the
// animator's extensions (docs/scene-lua.md), run in a sandbox, turned into a document.
#pragma once

#include <animator/document_builder.hpp>
#include <animator/plugin.h>

#include <string>

namespace lua_scene {

// Runs the scene file at `path` and fills `doc` (one keyframe, at t = 0). On failure returns
// false with "path:line: what went wrong" in `error`. Warnings go to the host's log.
bool read_scene(const char *path, const ani_host *host, ani::OwnedDocument &doc, std::string &error);

} // namespace lua_scene
