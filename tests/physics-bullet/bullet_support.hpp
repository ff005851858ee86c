// Shared by the physics.bullet tests: documents built in code, baked through the real timeline
// with either backend, and what the plugins logged.
#pragma once

#include "assets/asset_paths.hpp"
#include "io/document_io.hpp"
#include "io/environment.hpp"
#include "timeline/timeline.hpp"

#include "support.hpp"

#include <functional>
#include <memory>
#include <string>
#include <tuple>
#include <vector>

namespace animator::bullet_test {

constexpr double G = 9.81;
// The three steps every scene is measured at (1/60, 1/240, 1/1000 s).
extern const double kSteps[3];

Environment &env();
// Lines the plugins logged since the last call (and forgets them).
std::vector<std::string> take_log();

// A timeline of `doc` with `backend` ("physics.bullet" or "physics.custom"), meshes loaded.
std::unique_ptr<Timeline> timeline_of(const Document &doc,
                                      const std::string &backend = "physics.bullet");
// An empty document whose gravity is 0.
Document no_gravity();
// The document with physics.bullet's parameter `param` set.
Document with_param(Document doc, const std::string &param, double value);

double unit_sphere_radius(); // the generated sphere mesh's bounding radius (1 to float precision)

Model model(const std::string &name, const std::string &mesh, bool dynamics, bool gravity);
ModelState placed(glm::dvec3 center, glm::dvec3 scale = glm::dvec3(1.0),
                  glm::dvec3 angles = glm::dvec3(0.0));
void key(Document &doc, std::int64_t ms, int model, const ModelState &state);
Document load(const std::string &animation); // assets/animations/NAME

// The index of the model called `name` (throws when there is none).
int model_named(const Document &doc, const std::string &name);
// Where model m stands at the first keyframe.
glm::dvec3 start_of(const Document &doc, int m);
// The largest of f(t) at every 1/120 s of [0, until].
double worst(double until, const std::function<double(double)> &f);
// The energy of the models named (kinetic, turning and potential under G along -y), with their
// masses and moments of inertia (each about every axis through its centre: a cube's or a ball's).
double energy(const Timeline &t, const Document &doc, double at,
              const std::vector<std::tuple<std::string, double, double>> &models);

// The segment of a model covering t (the last one starting at or before t).
const ani_motion_segment *segment_at(const Timeline &t, int model, double time);

// Errors measured at kSteps: each must be under its bound, and each smaller than the one at the
// larger step before it, unless both are at or below `noise` (a floor Bullet reaches: rounding).
void check_converges(const char *what, const double (&errors)[3], const double (&bounds)[3],
                     double noise = 0.0);

} // namespace animator::bullet_test
