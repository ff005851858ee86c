// The transform gizmo (docs/manual.md, "Transforming the camera and models"): arrows, plane
// squares and a centre square that move, rings that turn, boxes that scale the selected models,
// as pure functions of the view and of the models when a drag began, so a drag never
// accumulates rounding and goes back to where it began when cancelled (as manipulation.hpp).
//
// Pixels are the 3D view's own: x right, y down from its top-left corner. The gizmo keeps its
// size on the screen (kGizmoPixels) at any distance.
//
// Frames: the arrows and plane squares are the axes of the last selected model's PARENT (the
// world's for a model at the root), the frame its position is stored in, so an arrow changes one
// stored coordinate. The rings are Maya's "gimbal" rings: the X ring turns angles.x about the
// parent's x, the Y ring angles.y about Rx*y, the Z ring angles.z about Rx*Ry*z (the model's
// matrix is T Rx Ry Rz S), so a ring changes exactly one stored angle and keys interpolate as
// the user turned. The scale boxes sit on the model's own axes.
#pragma once

#include "document/document.hpp"
#include "editor/manipulation.hpp" // EditMode
#include "timeline/keyed_motion.hpp" // ModelPose

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <array>
#include <optional>
#include <vector>

namespace animator {

constexpr double kGizmoPixels = 80.0;   // an arrow's length, a ring's radius, on the screen
constexpr double kGizmoHitPixels = 6.0; // how near the cursor must be to grab a handle
constexpr double kSnapMetres = 0.1;     // CTRL: moves in steps of 10 cm (of each stored coordinate)
constexpr double kSnapDegrees = 15.0;   // CTRL: turns in steps of 15 degrees (Maya's default)
constexpr double kSnapScale = 0.1;      // CTRL: scale factors in steps of 0.1

// Translate: AxisX/Y/Z are the arrows, PlaneXY/YZ/ZX the squares, Center moves in the view's
// plane. Rotate: AxisX/Y/Z are the rings. Scale: AxisX/Y/Z are the boxes, Center scales all three.
enum class GizmoHandle { None, AxisX, AxisY, AxisZ, PlaneXY, PlaneYZ, PlaneZX, Center };

// What the gizmo is seen through: the camera of the shown frame and the view's size in pixels.
struct GizmoView {
    CameraState camera;
    int width = 1, height = 1;
    glm::dmat4 view_projection() const;
    // Where a world point lands (nothing behind the camera); unlike project_to_pixel, also
    // outside the view, so a handle partly off the screen still has its shape.
    std::optional<glm::dvec2> project(const glm::dvec3 &world) const;
    // The ray from the camera through a pixel: origin and unit direction.
    std::pair<glm::dvec3, glm::dvec3> ray(glm::dvec2 pixel) const;
};

// The last selected model, where the gizmo sits, in the world at the drag's start.
struct GizmoTarget {
    glm::dvec3 center{0.0};      // world
    glm::dmat3 parent{1.0};      // the parent's world matrix, linear part (identity at the root)
    glm::dvec3 angles{0.0};      // its own Euler angles, degrees
};

// A model's gizmo target in frame `poses` (a model's pose is in its parent's frame).
GizmoTarget gizmo_target(const std::vector<Model> &models, const std::vector<ModelPose> &poses, int model);
// The parent's world linear part for every model (identity at the root), to move each model by
// a world displacement in its own frame.
std::vector<glm::dmat3> parent_matrices(const std::vector<Model> &models, const std::vector<ModelPose> &poses);

// The gizmo as placed in a view: its centre, its three axes (unit, world) and the world length
// that shows kGizmoPixels long at its depth.
struct Gizmo {
    EditMode mode = EditMode::Translate;
    glm::dvec3 center{0.0};
    glm::dvec2 center_pixel{0.0};
    std::array<glm::dvec3, 3> axes{};
    double length = 1.0;
    glm::dmat3 parent{1.0}; // the target's (CTRL snaps the move in this frame)
};

// None in Camera mode or when the target is behind the camera.
std::optional<Gizmo> place_gizmo(const GizmoView &view, EditMode mode, const GizmoTarget &target);

// A handle's shape on the screen, for drawing and for hit testing: a polyline (closed for a
// ring or a square), filled when `filled`.
struct GizmoShape {
    GizmoHandle handle = GizmoHandle::None;
    int axis = -1; // 0, 1, 2 for x, y, z (its colour); -1 for the centre
    std::vector<glm::dvec2> points;
    bool closed = false, filled = false;
};
std::vector<GizmoShape> gizmo_shapes(const Gizmo &gizmo, const GizmoView &view);

// The handle under `cursor`: the nearest within kGizmoHitPixels (a square or box: inside it),
// or None.
GizmoHandle gizmo_hit(const Gizmo &gizmo, const GizmoView &view, glm::dvec2 cursor);

// What a drag of `handle` from pixel `from` to pixel `to` does, the same for every selected model:
struct GizmoChange {
    EditMode mode = EditMode::Camera;
    glm::dvec3 move{0.0};   // Translate: the displacement in the world
    int axis = -1;          // the arrow, ring or box dragged (-1: a square or the centre)
    double degrees = 0.0;   // Rotate: the turn of that ring's angle (unwrapped: may pass 180)
    glm::dvec3 factor{1.0}; // Scale: of each stored scale
};
// `previous_degrees`: the turn at the drag's last update, so a ring dragged on past half a turn
// keeps counting (the angle on the screen is only known modulo 360). `snap` is CTRL.
GizmoChange gizmo_drag(const Gizmo &gizmo, const GizmoView &view, GizmoHandle handle, glm::dvec2 from, glm::dvec2 to,
                       bool snap, double previous_degrees = 0.0);

// A model's state after `change`, from its state when the drag began; `parent` is its parent's
// world linear part (parent_matrices), which turns the world displacement into its own frame.
// A turn records its direction in `turn` (docs/interpolation.md) as the mouse drags do.
ModelState apply_gizmo_change(const ModelState &start, const glm::dmat3 &parent, const GizmoChange &change);

} // namespace animator
