// The GLSL 330 core text of the Phong shading model. Each body is compiled after a `#version`
// line and one `#define` per feature in use (phong_program.cpp), so a program carries only the
// code and uniforms of its features.
#pragma once

namespace shading {

extern const char *const kModelVertexBody;
extern const char *const kModelFragmentBody;
extern const char *const kSkyboxVertexBody;
extern const char *const kSkyboxFragmentBody;

} // namespace shading
