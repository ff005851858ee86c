// The transform gizmo's look (docs/manual.md): X red, Y green, Z blue, the centre light grey,
// the handle under the cursor (or being dragged) yellow, as in Maya and Blender.
#pragma once

#include "editor/gizmo.hpp"
#include "render/screen_overlay.hpp"

#include <vector>

namespace animator {

constexpr float kGizmoLineWidth = 3.0f;

glm::vec3 gizmo_colour(int axis, bool highlighted);

// What dragging `handle` does in `mode` (Rotate, Translate or Scale), for its tooltip.
const char *gizmo_handle_tip(EditMode mode, GizmoHandle handle);

// The triangles that draw `shapes` (gizmo_shapes) in the view's pixels, the centre on top.
OverlayTriangles gizmo_triangles(const std::vector<GizmoShape> &shapes, GizmoHandle highlighted);

} // namespace animator
