// A linked GLSL program, compiled from vertex and fragment source. Compile and link errors say
// the stage and carry the driver's log, so a broken shading plugin can be reported and replaced.
#pragma once

#include "render/render_error.hpp"

#include <string>

namespace animator {

struct ShaderError : RenderError {
    using RenderError::RenderError;
};

class ShaderProgram {
  public:
    // Needs a current GL context for its whole life. Throws ShaderError: "the fragment shader
    // does not compile: 0:12(3): error: ..." or "the program does not link: ...".
    ShaderProgram(const std::string &vertex_source, const std::string &fragment_source);
    ~ShaderProgram();
    ShaderProgram(const ShaderProgram &) = delete;
    ShaderProgram &operator=(const ShaderProgram &) = delete;

    unsigned name() const { return program_; }
    // The location of a uniform, or -1 when the program has none by that name (or the compiler
    // dropped it as unused).
    int uniform_location(const std::string &name) const;
    // GL's type of an active uniform (GL_FLOAT_VEC3...), or 0 when it is not active. An element
    // of an array ("lights[3]") has the array's type when the array is active that far.
    unsigned uniform_type(const std::string &name) const;

  private:
    unsigned program_ = 0;
};

} // namespace animator
