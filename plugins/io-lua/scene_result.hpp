// What running a scene file yields: plain data with no pointers, so that it can cross from the
// child process that ran the scene to the plugin that turns it into a document (scene_wire).
#pragma once

#include <animator/document.h>

#include <cstdint>
#include <string>
#include <vector>

namespace lua_scene {

// A node of the scene tree that became a model, in depth-first order (a parent first).
struct SceneModel {
    std::string name;
    std::string mesh; // "" for an empty; resolved against the asset folders by the plugin
    int32_t line = 0; // where the scene made it
    int32_t parent = -1;
    ani_vec3 kd{0.7, 0.7, 0.7}, ks{0.3, 0.3, 0.3};
    double shininess = 25.0;
    std::string texture;
    double tint = 0.0, reflectivity = 0.0, transparency = 0.0, refractive_index = 1.0;
    bool dynamics = false, gravity = false;
    double mass = 1.0;
    ani_vec3 initial_velocity{0, 0, 0};
    double restitution = 1.0, friction = 0.0; // rigid-body settings (ABI 1.3)
    bool rotates = false;
    ani_vec3 angular_velocity{0, 0, 0};
    std::string collision_sound, moving_sound;
    ani_model_state state{}; // at t = 0, relative to the parent
    double rest[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1}; // the shear under T R S, column-major (ABI 1.7)
    bool has_joint = false;
    ani_vec3 joint_min{0, 0, 0}, joint_max{0, 0, 0};
};

// A light of the scene (gr.light).
struct SceneLight {
    std::string name;
    ani_vec3 position{0, 0, 0}, colour{1, 1, 1}, falloff{1, 0, 0};
};

struct SceneResult {
    std::vector<SceneModel> models;
    int64_t max_time_ms = 60000;
    double gravity = 9.81;
    int32_t down_axis = ANI_AXIS_Y;
    bool cel_shading = false;
    std::string skybox, backend = "physics.custom", interpolation = "interpolation.linear";
    ani_camera_state camera{{0, 0, 0}, {1, 0, 0, 0}, 50.0};
    std::vector<SceneLight> lights;
    ani_vec3 ambient{0.2, 0.2, 0.2};
    std::string render_output; // gr.render's file name and size; "" and 0 when not called
    int32_t render_width = 0, render_height = 0;
    std::vector<std::string> warnings; // "path:line: ..." for the host's log
};

} // namespace lua_scene
