// The transforms a frame is drawn with, as small pure functions: a model's matrix from its pose
// (docs/architecture.md: T(center) Rx Ry Rz S(scale), under its parent's), the camera's view and
// perspective projection, and where a world point lands on the screen.
#pragma once

#include "document/document.hpp"
#include "timeline/keyed_motion.hpp" // ModelPose

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>

#include <optional>
#include <vector>

namespace animator {

// T(center) Rx(angles.x) Ry(angles.y) Rz(angles.z) S(scale), angles in degrees.
glm::dmat4 model_matrix(const ModelPose &pose);

// Every model's world frame: its parent's frame times its own T R S (parents come first in the
// document); a model's mesh is drawn at its frame times its rest shape (apply_rest_shapes). `out` is resized to the number of models and reused, so a frame allocates nothing.
void world_matrices(const std::vector<Model> &models, const std::vector<ModelPose> &poses,
                    std::vector<glm::dmat4> &out);

// Turns world_matrices' frames into the matrices the models' meshes are drawn and collided
// with: each frame times its model's rest shape (Model::rest, which children do not inherit).
void apply_rest_shapes(const std::vector<Model> &models, std::vector<glm::dmat4> &frames);

// World to camera, for a camera at `position` turned by the camera-to-world quaternion (the
// identity looks down -Z with +Y up).
glm::dmat4 view_matrix(const CameraState &camera);

// OpenGL's perspective projection; `fov_degrees` is the vertical field of view.
glm::dmat4 projection_matrix(double fov_degrees, double aspect, double near_plane,
                             double far_plane);

// The pixel (x right, y down from the top-left corner, pixel centres at .5) where `world` lands,
// or nothing when it is behind the camera or outside the clip volume.
std::optional<glm::dvec2> project_to_pixel(const glm::dmat4 &view_projection,
                                           const glm::dvec3 &world, int width, int height);

} // namespace animator
