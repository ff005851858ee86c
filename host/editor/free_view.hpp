// A view to look around with, apart from the animated camera (Blender's viewport, Maya's
// perspective view): it orbits a pivot, pans and zooms, frames everything or the selection,
// and is never part of the document (no edit, no keyframe, nothing exported). The window shows
// either this view or the animated camera (docs/manual.md, "Looking around").
//
// Pure functions of the view and the mouse's movement in pixels (x right, y down), tested
// without a window (tests/session/free_view_test.cpp).
#pragma once

#include "document/document.hpp"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <vector>

namespace animator {

struct FreeView {
    glm::dvec3 pivot{0.0};  // what it orbits about and looks at
    double distance = 10.0; // from the pivot, metres
    double yaw = 0.0;       // degrees about the world's up (+Y); 0 looks down -Z
    double pitch = 0.0;     // degrees about the view's x; positive looks down on the pivot
    double fov_degrees = 50.0;
};

// Orbits and zoom speeds: half a degree per pixel, as a Rotate-mode drag turns a model, and
// the distance halved by 69 px of a zoom drag (as Scale mode doubles) or by 7 wheel notches.
constexpr double kOrbitDegreesPerPixel = 0.5;
constexpr double kZoomPerPixel = 0.01;
constexpr double kZoomPerNotch = 0.1;
constexpr double kMinViewDistance = 0.01, kMaxViewDistance = 1e6;

// The camera the renderer draws the free view with.
CameraState free_view_camera(const FreeView &view);

// The free view where `camera` is, orbiting a pivot `distance` ahead of it: switching to the
// free view starts from what the animated camera showed (its roll, which an orbit has not,
// is dropped).
FreeView free_view_from(const CameraState &camera, double distance);

// Alt + left drag: turns about the pivot (right drags the scene right, down tilts it towards
// the viewer, as in Blender and Maya); the distance to the pivot is kept. Pitch stops short of
// straight up or down, where yaw would lose its meaning.
FreeView orbit(const FreeView &start, glm::dvec2 delta);

// Alt + middle drag: moves the pivot and the view together on the view's plane, so the point
// at the pivot's depth under the cursor stays under it (viewport `height` pixels tall).
FreeView pan(const FreeView &start, glm::dvec2 delta, int height);

// Alt + right drag (right or down comes closer) and the wheel in the free view (`notches`, up
// comes closer): the distance to the pivot shrinks or grows by a factor, never through it.
FreeView zoom_drag(const FreeView &start, glm::dvec2 delta);
FreeView zoom_wheel(const FreeView &start, double notches);

struct Sphere {
    glm::dvec3 center{0.0};
    double radius = 0.0;
};

// Home (every model) and F (the selection): the same direction, the pivot at the spheres'
// bounding sphere's centre, and the distance at which that sphere fits the view vertically and
// horizontally (`aspect` = width / height), with a margin. No spheres: the view unchanged.
FreeView frame_spheres(const FreeView &start, const std::vector<Sphere> &spheres, double aspect);

} // namespace animator
