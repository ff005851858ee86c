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

// The scene's lights (Settings::lights) as markers in `view`: a small diamond in each light's
// colour (scaled down into [0, 1] when brighter) ringed in black, with four short rays; none for
// a light behind the camera.
OverlayTriangles light_markers(const std::vector<Light> &lights, const GizmoView &view);

} // namespace animator
