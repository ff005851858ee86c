// The reply of the child process that ran a scene, as bytes on a pipe: either the scene's data
// or its error message. The child ran untrusted code, so the decoder trusts nothing: every
// length and count is checked against what is left, and any flaw is an error, never a crash.
#pragma once

#include "scene_result.hpp"

#include <string>

namespace lua_scene {

std::string encode_result(const SceneResult &result);
std::string encode_error(const std::string &message);

// Returns true with `out` filled from a result; false with the scene's own error message, or
// "path: ..." saying how the reply is malformed, in `error`.
bool decode_reply(const std::string &bytes, const std::string &path, SceneResult &out, std::string &error);

} // namespace lua_scene
