// The host's own minimal programs, used when the shading plugin's program for some features
// cannot be had (the plugin refuses, a shader does not compile or link): plain Phong with kd, ks
// and shininess and the selection tint for models, and a plain skybox, so a broken plugin never
// leaves the screen empty.
#pragma once

#include <animator/shading.h>

#include <cstdint>

namespace animator {

// A program as a plugin would hand it over.
ani_shader_program built_in_program(bool skybox_pass);

} // namespace animator
