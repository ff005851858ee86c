#include "editor/free_view.hpp"

#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>

namespace animator {

namespace {

constexpr double kMaxPitch = 89.0;   // degrees: never straight over the pivot
constexpr double kFrameMargin = 1.1; // the framed sphere fills 1/1.1 of the view

glm::dquat orientation(const FreeView &v) {
    // Yaw about world +Y, then pitch about the turned x: looking down on the pivot for pitch > 0.
    return glm::angleAxis(glm::radians(v.yaw), glm::dvec3(0, 1, 0)) *
           glm::angleAxis(glm::radians(-v.pitch), glm::dvec3(1, 0, 0));
}

double clamp_distance(double d) { return std::clamp(d, kMinViewDistance, kMaxViewDistance); }

} // namespace

CameraState free_view_camera(const FreeView &view) {
    CameraState c;
    c.rotation = orientation(view);
    c.position = view.pivot - c.rotation * glm::dvec3(0, 0, -1) * view.distance;
    c.fov_degrees = view.fov_degrees;
    return c;
}

FreeView free_view_from(const CameraState &camera, double distance) {
    FreeView v;
    v.fov_degrees = camera.fov_degrees;
    v.distance = clamp_distance(distance);
    const glm::dvec3 forward = glm::normalize(camera.rotation) * glm::dvec3(0, 0, -1);
    v.pitch = std::clamp(glm::degrees(std::asin(std::clamp(-forward.y, -1.0, 1.0))), -kMaxPitch, kMaxPitch);
    v.yaw = glm::degrees(std::atan2(-forward.x, -forward.z));
    v.pivot = camera.position + forward * v.distance;
    return v;
}

FreeView orbit(const FreeView &start, glm::dvec2 delta) {
    FreeView v = start;
    // Dragging right turns the view left about the pivot, so the scene follows the cursor.
    v.yaw = std::remainder(start.yaw - delta.x * kOrbitDegreesPerPixel, 360.0);
    v.pitch = std::clamp(start.pitch + delta.y * kOrbitDegreesPerPixel, -kMaxPitch, kMaxPitch);
    return v;
}

FreeView pan(const FreeView &start, glm::dvec2 delta, int height) {
    FreeView v = start;
    // The size of a pixel at the pivot's depth (manipulation.hpp's metres_per_pixel).
    const double pixel = 2.0 * start.distance * std::tan(glm::radians(start.fov_degrees) / 2.0) / std::max(height, 1);
    const glm::dquat q = orientation(start);
    const glm::dvec3 right = q * glm::dvec3(1, 0, 0), up = q * glm::dvec3(0, 1, 0);
    // The scene follows the cursor: the view moves the other way.
    v.pivot = start.pivot - right * (delta.x * pixel) + up * (delta.y * pixel);
    return v;
}

FreeView zoom_drag(const FreeView &start, glm::dvec2 delta) {
    FreeView v = start;
    v.distance = clamp_distance(start.distance * std::exp(-(delta.x + delta.y) * kZoomPerPixel));
    return v;
}

FreeView zoom_wheel(const FreeView &start, double notches) {
    FreeView v = start;
    v.distance = clamp_distance(start.distance * std::pow(1.0 - kZoomPerNotch, notches));
    return v;
}

FreeView frame_spheres(const FreeView &start, const std::vector<Sphere> &spheres, double aspect) {
    if (spheres.empty()) return start;
    // A sphere around all of them (Ritter's style, enough for framing): the centre of their
    // boxes, and the farthest reach from it.
    glm::dvec3 lo(INFINITY), hi(-INFINITY);
    for (const Sphere &s : spheres) {
        lo = glm::min(lo, s.center - s.radius);
        hi = glm::max(hi, s.center + s.radius);
    }
    const glm::dvec3 centre = (lo + hi) * 0.5;
    double radius = 0.0;
    for (const Sphere &s : spheres) radius = std::max(radius, glm::length(s.center - centre) + s.radius);
    radius = std::max(radius, 1e-3);
    // A sphere of radius r fits a half-angle a when seen from r / sin(a): vertical, and
    // horizontal through the aspect (tan(h) = aspect * tan(v)).
    const double half_v = glm::radians(start.fov_degrees) / 2.0;
    const double half_h = std::atan(std::tan(half_v) * std::max(aspect, 1e-3));
    FreeView v = start;
    v.pivot = centre;
    v.distance = clamp_distance(kFrameMargin * radius / std::sin(std::min(half_v, half_h)));
    return v;
}

} // namespace animator
