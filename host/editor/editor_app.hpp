// The editor's window: GLFW with an OpenGL 3.3 core context (loaded by glad), Dear ImGui over
// the 3D view, mouse and keys turned into calls on the session (seed, "Transforming the Camera
// and Model" and "Keys"). Idle means idle: with nothing playing, baking or moving, it sleeps in
// glfwWaitEvents and draws nothing.
#pragma once

#include <string>

namespace animator {

struct EditorOptions {
    std::string file;     // a .lua scene or an .ani animation; empty for the demo scene
    int width = 1280, height = 720;
};

// Runs the editor until the user quits. Returns 0, or 1 when there is no display to open a
// window on (said on stderr).
int run_editor(const EditorOptions &options);

} // namespace animator
