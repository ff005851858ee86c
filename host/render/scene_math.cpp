#include "render/scene_math.hpp"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtx/euler_angles.hpp>

#include <cmath>

namespace animator {

glm::dmat4 model_matrix(const ModelPose &pose) {
    const glm::dmat4 rotation =
        glm::eulerAngleXYZ(glm::radians(pose.angles.x), glm::radians(pose.angles.y),
                           glm::radians(pose.angles.z)); // Rx * Ry * Rz
    return glm::translate(glm::dmat4(1.0), pose.center) * rotation *
           glm::scale(glm::dmat4(1.0), pose.scale);
}

void world_matrices(const std::vector<Model> &models, const std::vector<ModelPose> &poses,
                    std::vector<glm::dmat4> &out) {
    out.resize(models.size());
    for (size_t m = 0; m < models.size() && m < poses.size(); ++m) {
        const glm::dmat4 local = model_matrix(poses[m]);
        const int parent = models[m].parent;
        out[m] = parent >= 0 && static_cast<size_t>(parent) < m
                     ? out[static_cast<size_t>(parent)] * local
                     : local;
    }
}

void apply_rest_shapes(const std::vector<Model> &models, std::vector<glm::dmat4> &frames) {
    for (size_t m = 0; m < models.size() && m < frames.size(); ++m)
        if (models[m].rest != glm::dmat3(1.0)) frames[m] = frames[m] * glm::dmat4(models[m].rest);
}

glm::dmat4 view_matrix(const CameraState &camera) {
    // The inverse of the camera's own matrix T(position) R(rotation).
    const glm::dmat3 to_camera = glm::transpose(glm::mat3_cast(glm::normalize(camera.rotation)));
    glm::dmat4 view(to_camera);
    view[3] = glm::dvec4(-(to_camera * camera.position), 1.0);
    return view;
}

glm::dmat4 projection_matrix(double fov_degrees, double aspect, double near_plane,
                             double far_plane) {
    return glm::perspective(glm::radians(fov_degrees), aspect, near_plane, far_plane);
}

std::optional<glm::dvec2> project_to_pixel(const glm::dmat4 &view_projection,
                                           const glm::dvec3 &world, int width, int height) {
    const glm::dvec4 clip = view_projection * glm::dvec4(world, 1.0);
    if (clip.w <= 0.0) return std::nullopt;
    const glm::dvec3 ndc = glm::dvec3(clip) / clip.w;
    if (std::abs(ndc.x) > 1.0 || std::abs(ndc.y) > 1.0 || std::abs(ndc.z) > 1.0)
        return std::nullopt;
    return glm::dvec2((ndc.x + 1.0) * 0.5 * width, (1.0 - ndc.y) * 0.5 * height);
}

} // namespace animator
