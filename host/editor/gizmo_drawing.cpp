#include "editor/gizmo_drawing.hpp"

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

} // namespace animator
