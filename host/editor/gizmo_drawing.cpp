#include "editor/gizmo_drawing.hpp"

#include <algorithm>

namespace animator {

glm::vec3 gizmo_colour(int axis, bool highlighted) {
    if (highlighted) return {1.0f, 0.9f, 0.1f};
    switch (axis) {
    case 0: return {0.95f, 0.2f, 0.2f};
    case 1: return {0.25f, 0.85f, 0.25f};
    case 2: return {0.25f, 0.45f, 1.0f};
    default: return {0.85f, 0.85f, 0.85f};
    }
}

const char *gizmo_handle_tip(EditMode mode, GizmoHandle handle) {
    switch (mode) {
    case EditMode::Translate:
        switch (handle) {
        case GizmoHandle::AxisX: return "Drag: move along x (the parent's axes), keyed at the current time. CTRL snaps to 0.1 m.";
        case GizmoHandle::AxisY: return "Drag: move along y (the parent's axes), keyed at the current time. CTRL snaps to 0.1 m.";
        case GizmoHandle::AxisZ: return "Drag: move along z (the parent's axes), keyed at the current time. CTRL snaps to 0.1 m.";
        case GizmoHandle::PlaneXY: return "Drag: move in the x-y plane, keyed at the current time. CTRL snaps to 0.1 m.";
        case GizmoHandle::PlaneYZ: return "Drag: move in the y-z plane, keyed at the current time. CTRL snaps to 0.1 m.";
        case GizmoHandle::PlaneZX: return "Drag: move in the z-x plane, keyed at the current time. CTRL snaps to 0.1 m.";
        case GizmoHandle::Center: return "Drag: move in the view's plane, keyed at the current time. CTRL snaps to 0.1 m.";
        default: return nullptr;
        }
    case EditMode::Rotate:
        switch (handle) {
        case GizmoHandle::AxisX: return "Drag around: turn the x angle (a gimbal ring: one Euler angle), keyed at the current time. CTRL snaps to 15 degrees.";
        case GizmoHandle::AxisY: return "Drag around: turn the y angle (a gimbal ring: one Euler angle), keyed at the current time. CTRL snaps to 15 degrees.";
        case GizmoHandle::AxisZ: return "Drag around: turn the z angle (a gimbal ring: one Euler angle), keyed at the current time. CTRL snaps to 15 degrees.";
        default: return nullptr;
        }
    case EditMode::Scale:
        switch (handle) {
        case GizmoHandle::AxisX: return "Drag: scale along the model's x, keyed at the current time. CTRL snaps to steps of 0.1.";
        case GizmoHandle::AxisY: return "Drag: scale along the model's y, keyed at the current time. CTRL snaps to steps of 0.1.";
        case GizmoHandle::AxisZ: return "Drag: scale along the model's z, keyed at the current time. CTRL snaps to steps of 0.1.";
        case GizmoHandle::Center: return "Drag: scale all three axes, keyed at the current time. CTRL snaps to steps of 0.1.";
        default: return nullptr;
        }
    default: return nullptr;
    }
}

OverlayTriangles gizmo_triangles(const std::vector<GizmoShape> &shapes, GizmoHandle highlighted) {
    OverlayTriangles t;
    // gizmo_shapes lists the small targets first (they win a tie when picked): drawn last.
    for (auto s = shapes.rbegin(); s != shapes.rend(); ++s) {
        std::vector<glm::vec2> points;
        points.reserve(s->points.size());
        for (const glm::dvec2 &p : s->points) points.emplace_back(p);
        const glm::vec3 colour = gizmo_colour(s->axis, s->handle == highlighted);
        if (s->filled) t.convex(points, colour);
        else t.polyline(points, s->closed, kGizmoLineWidth, colour);
    }
    return t;
}

OverlayTriangles light_markers(const std::vector<Light> &lights, const GizmoView &view) {
    OverlayTriangles t;
    constexpr float kHalf = 6.0f, kRay = 11.0f;
    for (const Light &l : lights) {
        const auto p = view.project(l.position);
        if (!p) continue;
        const glm::vec2 c(*p);
        const glm::vec3 bright(l.colour);
        const float top = std::max({bright.x, bright.y, bright.z, 1.0f});
        const glm::vec3 colour = bright / top;
        const std::vector<glm::vec2> diamond{c + glm::vec2(0, -kHalf), c + glm::vec2(kHalf, 0), c + glm::vec2(0, kHalf),
                                             c + glm::vec2(-kHalf, 0)};
        for (const glm::vec2 d : {glm::vec2(1, 1), glm::vec2(1, -1), glm::vec2(-1, 1), glm::vec2(-1, -1)})
            t.line(c + d * (kHalf * 0.6f), c + d * (kRay * 0.75f), 2.0f, colour);
        t.polyline(diamond, true, 3.0f, glm::vec3(0.0f));
        t.convex(diamond, colour);
    }
    return t;
}

} // namespace animator
