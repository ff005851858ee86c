// What should sound when, how loud and from which side: the pure half of sound (seed, "Sound").
// From a baked Timeline and the document's models it gives the collision cues (each model in a
// collision plays its own collision sound once, at the collision's time) and each model's moving
// sound (a loop while the model moves faster than a small threshold). No device, no files: the
// live player (live_player.hpp) and the offline soundtrack (mixer.hpp) both read these, so they
// agree on every volume and pan.
#pragma once

#include "document/document.hpp"
#include "timeline/timeline.hpp"

#include <glm/vec3.hpp>

#include <string>
#include <vector>

namespace animator::audio {

// volume = kVolumeScale * E / (4 pi r^2), clamped to [0, 100] (SFML's volume range), with E the
// kinetic energy in joules and r the distance to the camera in metres; so kVolumeScale is in
// square metres per joule. It is the largest round value at which no example scene clips: the
// densest, gas.ani (125 balls, about 1250 clicks a second, up to 32 at once), peaks at 0.84 of
// full scale, while the sparsest, cradle.ani (1 kg at 2 m/s, 9 m away: volume 1), still peaks at
// 0.011 (-39 dBFS), quiet but audible; drop.ani's first bounce (1 kg at 8.9 m/s, 12.4 m away)
// plays at volume 10 (docs/sound.md has the table).
inline constexpr double kVolumeScale = 500.0;

// A model's moving sound plays while its speed is above this (m/s): slow enough that any visible
// motion hums, fast enough that a model settling onto a floor (whose speed decays geometrically)
// falls silent once it looks still.
inline constexpr double kMovingThreshold = 0.05;

// Moving sounds follow a model's speed and side, sampled this often (seconds); the mixer ramps
// the gain linearly between samples.
inline constexpr double kMovingSampleStep = 0.01;

// kVolumeScale * E / (4 pi r^2) clamped to [0, 100]; 100 at r = 0 unless E = 0; 0 for
// anything not finite or negative.
double volume(double energy, double distance);

// Where `point` is heard, from -1 (fully left) through 0 (ahead, behind, above) to 1 (right):
// its x in camera space over its distance to the camera. 0 at the camera itself.
double pan(const CameraState &camera, const glm::dvec3 &point);

// Constant-power pan: the left and right gains for `pan` in [-1, 1] (cos and sin of
// (pan + 1) pi / 4, so left^2 + right^2 = 1 and both are 1/sqrt(2) in the middle).
struct StereoGain {
    double left, right;
};
StereoGain pan_gains(double pan);

// One model's collision sound, once.
struct CollisionCue {
    int model = -1;
    std::string sound;   // the model's collision sound id
    double time = 0.0;   // seconds
    double volume = 0.0; // 0..100
    double pan = 0.0;    // -1..1
};

// The collision cues of the events with from < t <= to, in time order (for equal times, in event
// order, a before b). Each model in an event (a, and b unless ANI_NO_MODEL) that has a collision
// sound plays it, with E = m v^2 / 2 from its own mass and the event's approach speed, r the
// distance from the contact point to the camera at the event's time, and the pan of the contact
// point.
std::vector<CollisionCue> collision_cues(const Timeline &timeline, double from, double to);

// A model's moving sound at one time: whether it plays, how loud and where.
struct MovingState {
    bool moving = false;
    double volume = 0.0;
    double pan = 0.0;
};

// Every model's world-space center in `frame` (states are relative to the parent in the scene
// tree: T(center) Rx Ry Rz S under the parent's matrix, docs/architecture.md).
std::vector<glm::dvec3> world_centers(const std::vector<Model> &models, const Frame &frame);

// The moving sound of model `model` at time t: it plays while the model's world speed is above
// kMovingThreshold, with E = m v^2 / 2 and r the distance from its world center to the camera.
// A model without a moving sound never plays.
MovingState moving_state(const Timeline &timeline, int model, double t);

// The same for every model at once (one evaluate), for the live player and the mixer.
std::vector<MovingState> moving_states(const Timeline &timeline, double t);

// Whether the document names any sound at all: a document without one never opens the device.
bool has_sounds(const Document &doc);

} // namespace animator::audio
