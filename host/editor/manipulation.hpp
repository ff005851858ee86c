// What a mouse drag does to the camera or to a model (seed, "Transforming the Camera and
// Model"), as pure functions of the state when the drag began and the mouse's movement since, so
// a drag never accumulates rounding and can be cancelled by going back to where it began.
//
// Pixels: x right, y down. Lengths follow the cursor: `metres_per_pixel` is the size of a pixel
// at the depth of what is moved, so a model dragged in a view along -Z stays under the cursor.
#pragma once

#include "document/document.hpp"

#include <glm/vec2.hpp>

namespace animator {

enum class EditMode { Camera = 0, Rotate = 1, Translate = 2, Scale = 3 };
enum class DragButton { Left = 0, Right = 1, Middle = 2 }; // GLFW's numbering

constexpr double kDegreesPerPixel = 0.5;
constexpr double kScalePerPixel = 0.01; // the factor is exp(0.01 px): 69 px doubles
constexpr double kScrollStep = 0.1;     // of the distance to what is looked at, per notch

// The camera after a drag of `delta` pixels with `button` (Camera mode):
// left translates on the camera's x/y (the scene follows the cursor), middle rotates about its
// z by the vertical movement, right rotates about its y by the horizontal movement and about its
// x by the vertical one.
CameraState drag_camera(const CameraState &start, DragButton button, glm::dvec2 delta,
                        double metres_per_pixel);

// The camera after `notches` of the scroll wheel (up is positive): along its view axis, by a
// tenth of `distance` (how far it is from what it looks at) per notch.
CameraState scroll_camera(const CameraState &start, double notches, double distance);

// A model's state after a drag in Rotate, Translate or Scale mode, in its parent's frame:
// - Rotate: middle turns about y by the vertical movement; right turns about x by the vertical
//   movement and (beyond the seed) about z by the horizontal one. `turn` records the direction
//   of each axis's turn (docs/interpolation.md), so interpolation follows the user's hand.
// - Translate: middle moves along z by the vertical movement (down the screen is +z, towards a
//   camera at the default orientation); right moves along x and y with the cursor.
// - Scale: middle scales z by the vertical movement, right scales x and y (right and up grow).
// The left button does nothing here (it selects).
ModelState drag_model(const ModelState &start, EditMode mode, DragButton button, glm::dvec2 delta,
                      double metres_per_pixel);

// The size of a pixel at `depth` metres in front of a camera with this vertical field of view,
// in a viewport `height` pixels tall.
double metres_per_pixel(double depth, double fov_degrees, int height);

} // namespace animator
