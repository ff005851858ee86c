#include "editor/manipulation.hpp"

#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>

namespace animator {

CameraState drag_camera(const CameraState &start, DragButton button, glm::dvec2 delta,
                        double metres_per_pixel) {
    CameraState c = start;
    const glm::dvec3 right = start.rotation * glm::dvec3(1, 0, 0);
    const glm::dvec3 up = start.rotation * glm::dvec3(0, 1, 0);
    switch (button) {
    case DragButton::Left: // grab the scene: it follows the cursor, so the camera goes the other way
        c.position = start.position - right * (delta.x * metres_per_pixel) + up * (delta.y * metres_per_pixel);
        break;
    case DragButton::Middle: // roll about the view axis
        c.rotation = glm::normalize(start.rotation * glm::angleAxis(glm::radians(delta.y * kDegreesPerPixel),
                                                                    glm::dvec3(0, 0, 1)));
        break;
    case DragButton::Right: // turn about the camera's y and x; the scene follows the cursor
        c.rotation = glm::normalize(
            start.rotation *
            glm::angleAxis(glm::radians(delta.x * kDegreesPerPixel), glm::dvec3(0, 1, 0)) *
            glm::angleAxis(glm::radians(delta.y * kDegreesPerPixel), glm::dvec3(1, 0, 0)));
        break;
    }
    return c;
}

CameraState scroll_camera(const CameraState &start, double notches, double distance) {
    CameraState c = start;
    const glm::dvec3 forward = start.rotation * glm::dvec3(0, 0, -1);
    c.position = start.position + forward * (notches * kScrollStep * std::max(distance, 0.1));
    return c;
}

namespace {

// Turns angle `axis` by `degrees`, wrapped into [0, 360), and records the direction: a turn
// that increases the angle is counter-clockwise, recorded as a negative `turn` (the seed's ccw).
void turn_axis(ModelState &s, const ModelState &start, int axis, double degrees) {
    if (degrees == 0.0) return;
    s.angles[axis] = wrap_degrees(start.angles[axis] + degrees);
    s.turn[axis] = degrees > 0.0 ? -1.0 : 1.0;
}

} // namespace

ModelState drag_model(const ModelState &start, EditMode mode, DragButton button, glm::dvec2 delta,
                      double metres_per_pixel) {
    ModelState s = start;
    if (button == DragButton::Left) return s;
    switch (mode) {
    case EditMode::Camera:
        break;
    case EditMode::Rotate:
        if (button == DragButton::Middle) {
            turn_axis(s, start, 1, delta.y * kDegreesPerPixel);
        } else {
            turn_axis(s, start, 0, delta.y * kDegreesPerPixel);
            turn_axis(s, start, 2, delta.x * kDegreesPerPixel);
        }
        break;
    case EditMode::Translate:
        if (button == DragButton::Middle) {
            s.center.z = start.center.z + delta.y * metres_per_pixel;
        } else {
            s.center.x = start.center.x + delta.x * metres_per_pixel;
            s.center.y = start.center.y - delta.y * metres_per_pixel;
        }
        break;
    case EditMode::Scale:
        if (button == DragButton::Middle) {
            s.scale.z = start.scale.z * std::exp(-delta.y * kScalePerPixel);
        } else {
            s.scale.x = start.scale.x * std::exp(delta.x * kScalePerPixel);
            s.scale.y = start.scale.y * std::exp(-delta.y * kScalePerPixel);
        }
        break;
    }
    return s;
}

double metres_per_pixel(double depth, double fov_degrees, int height) {
    const double visible = 2.0 * std::max(depth, 0.01) * std::tan(glm::radians(fov_degrees) / 2.0);
    return visible / std::max(height, 1);
}

} // namespace animator
