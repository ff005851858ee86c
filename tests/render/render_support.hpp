// What the render tests share: the process's off-screen GL context, small scenes built in code,
// rendering a document's first frame to an image, and golden-image comparison.
#pragma once

#include "assets/image.hpp"
#include "document/document.hpp"
#include "io/environment.hpp"
#include "render/offscreen_context.hpp"
#include "render/renderer.hpp"

#include <functional>
#include <memory>
#include <set>
#include <string>
#include <vector>

namespace animator::test {

// The one off-screen context of the test process, created on first use (EGL, no display).
OffscreenContext &gl_context();
// The plugins beside the test executables and the generated assets.
Environment &environment();

// A model with a mesh and a material (specular off unless given).
Model make_model(const std::string &name, const std::string &mesh, const glm::dvec3 &kd,
                 const glm::dvec3 &ks = glm::dvec3(0.0), double shininess = ANI_SHININESS_MAX);
ModelState make_state(const glm::dvec3 &center, const glm::dvec3 &scale = glm::dvec3(1.0),
                      const glm::dvec3 &angles = glm::dvec3(0.0));
// A camera at `position` turned `yaw` degrees left about +Y, then `pitch` degrees up.
CameraState make_camera(const glm::dvec3 &position, double yaw_degrees = 0.0,
                        double pitch_degrees = 0.0, double fov_degrees = 50.0);
// A document with `camera` keyed at t = 0 and these settings' cel shading and skybox.
Document make_document(const CameraState &camera, bool cel_shading = false,
                       const std::string &skybox = "");

// The meshes of a document's models (null for none), loaded once per id for the process.
std::vector<std::shared_ptr<const Mesh>> meshes_of(const Document &doc);
// The t = 0 keyframe as a frame: every model's keyed state and the camera.
Frame first_frame(const Document &doc);

struct Rendered {
    Image image;
    RenderStats stats;
    std::vector<std::string> log; // the renderer's warnings
    int samples = 1;              // the samples a pixel GL gave (it may give more than asked)
};

// Draws `frame` of `doc` into a fresh off-screen framebuffer of width x height, with `samples`
// samples a pixel (multisample anti-aliasing; 1 is none).
Rendered render_frame(const Document &doc, const Frame &frame, int width, int height,
                      const std::set<int> &selected = {}, RenderOptions options = {},
                      const std::set<int> &flagged = {}, int samples = 1);
// The same for the first frame.
Rendered render_document(const Document &doc, int width = 160, int height = 120,
                         const std::set<int> &selected = {}, RenderOptions options = {},
                         const std::set<int> &flagged = {}, int samples = 1);

// The colour at pixel (x, y) from the top left.
glm::ivec3 pixel(const Image &image, int x, int y);

} // namespace animator::test
