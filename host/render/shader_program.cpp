#include "render/shader_program.hpp"

#include <glad/gl.h>

#include <cstdlib>
#include <vector>

namespace animator {

namespace {

std::string info_log(GLuint object, bool is_program) {
    GLint length = 0;
    if (is_program)
        glGetProgramiv(object, GL_INFO_LOG_LENGTH, &length);
    else
        glGetShaderiv(object, GL_INFO_LOG_LENGTH, &length);
    std::vector<char> log(static_cast<size_t>(length > 0 ? length : 1), '\0');
    if (is_program)
        glGetProgramInfoLog(object, static_cast<GLsizei>(log.size()), nullptr, log.data());
    else
        glGetShaderInfoLog(object, static_cast<GLsizei>(log.size()), nullptr, log.data());
    std::string text(log.data());
    while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
    return text.empty() ? "(the driver gave no log)" : text;
}

GLuint compile(GLenum stage, const std::string &source, const char *stage_name) {
    const GLuint shader = glCreateShader(stage);
    const char *text = source.c_str();
    glShaderSource(shader, 1, &text, nullptr);
    glCompileShader(shader);
    GLint ok = GL_FALSE;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (ok != GL_TRUE) {
        const std::string log = info_log(shader, false);
        glDeleteShader(shader);
        throw ShaderError(std::string("the ") + stage_name + " shader does not compile: " + log);
    }
    return shader;
}

} // namespace

ShaderProgram::ShaderProgram(const std::string &vertex_source, const std::string &fragment_source) {
    const GLuint vertex = compile(GL_VERTEX_SHADER, vertex_source, "vertex");
    GLuint fragment = 0;
    try {
        fragment = compile(GL_FRAGMENT_SHADER, fragment_source, "fragment");
    } catch (...) {
        glDeleteShader(vertex);
        throw;
    }
    program_ = glCreateProgram();
    glAttachShader(program_, vertex);
    glAttachShader(program_, fragment);
    glLinkProgram(program_);
    glDeleteShader(vertex); // flagged; freed with the program
    glDeleteShader(fragment);
    GLint ok = GL_FALSE;
    glGetProgramiv(program_, GL_LINK_STATUS, &ok);
    if (ok != GL_TRUE) {
        const std::string log = info_log(program_, true);
        glDeleteProgram(program_);
        throw ShaderError("the program does not link: " + log);
    }
}

ShaderProgram::~ShaderProgram() {
    glDeleteProgram(program_);
}

int ShaderProgram::uniform_location(const std::string &name) const {
    return glGetUniformLocation(program_, name.c_str());
}

unsigned ShaderProgram::uniform_type(const std::string &name) const {
    // GL names an active array by its first element, "lights[0]", with its active size.
    std::string array;
    long element = -1;
    const auto open = name.rfind('[');
    if (open != std::string::npos && name.size() > open + 2 && name.back() == ']') {
        char *end = nullptr;
        element = std::strtol(name.c_str() + open + 1, &end, 10);
        if (end != name.c_str() + name.size() - 1 || element < 0) element = -1;
        array = name.substr(0, open) + "[0]";
    }
    GLint count = 0;
    glGetProgramiv(program_, GL_ACTIVE_UNIFORMS, &count);
    char buffer[256];
    for (GLint i = 0; i < count; ++i) {
        GLsizei length = 0;
        GLint size = 0;
        GLenum type = 0;
        glGetActiveUniform(program_, static_cast<GLuint>(i), sizeof buffer, &length, &size, &type,
                           buffer);
        const std::string active(buffer, static_cast<size_t>(length));
        if (name == active || (element >= 0 && element < size && array == active)) return type;
    }
    return 0;
}

} // namespace animator
