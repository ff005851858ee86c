#include "audio/sound_cues.hpp"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/mat4x4.hpp>

#include <algorithm>
#include <cmath>

namespace animator::audio {

namespace {

constexpr double kPi = 3.14159265358979323846;

glm::dmat4 local_matrix(const ModelPose &pose) {
    glm::dmat4 m = glm::translate(glm::dmat4(1.0), pose.center);
    m = glm::rotate(m, glm::radians(pose.angles.x), glm::dvec3(1, 0, 0));
    m = glm::rotate(m, glm::radians(pose.angles.y), glm::dvec3(0, 1, 0));
    m = glm::rotate(m, glm::radians(pose.angles.z), glm::dvec3(0, 0, 1));
    return glm::scale(m, pose.scale);
}

double energy(double mass, double speed) {
    return 0.5 * mass * speed * speed;
}

MovingState state_of(const Model &model, double speed, const glm::dvec3 &center,
                     const CameraState &camera) {
    MovingState s;
    if (model.moving_sound.empty() || !(speed > kMovingThreshold)) return s;
    s.moving = true;
    s.volume = volume(energy(model.mass, speed), glm::length(center - camera.position));
    s.pan = pan(camera, center);
    return s;
}

// The world speed of every model at t. A model under the root moves as its pose says; a part of
// a jointed model also moves with its parent, which its own velocity (relative to the parent)
// does not show, so its speed is the change of its world center over a millisecond.
std::vector<double> world_speeds(const Timeline &timeline, double t, const Frame &frame,
                                 const std::vector<glm::dvec3> &centers) {
    const auto &models = timeline.document().models();
    std::vector<double> speeds(models.size(), 0.0);
    bool any_child = false;
    for (size_t m = 0; m < models.size(); ++m) {
        if (models[m].parent >= 0)
            any_child = true;
        else
            speeds[m] = glm::length(frame.models[m].velocity);
    }
    if (!any_child) return speeds;
    constexpr double h = 1e-3;
    // Forward where the bake reaches, else backward.
    const double t2 = t + h <= timeline.baked_until() || t < h ? t + h : t - h;
    const std::vector<glm::dvec3> other = world_centers(models, timeline.evaluate(t2));
    for (size_t m = 0; m < models.size(); ++m)
        if (models[m].parent >= 0) speeds[m] = glm::length(other[m] - centers[m]) / h;
    return speeds;
}

} // namespace

double volume(double energy, double distance) {
    if (!(energy > 0.0) || !std::isfinite(energy) || !(distance >= 0.0)) return 0.0;
    if (distance == 0.0) return 100.0;
    const double v = kVolumeScale * energy / (4.0 * kPi * distance * distance);
    return std::isfinite(v) ? std::clamp(v, 0.0, 100.0) : 100.0;
}

double pan(const CameraState &camera, const glm::dvec3 &point) {
    // The camera's rotation takes camera space to the world; its inverse brings the point back.
    const glm::dvec3 local = glm::inverse(camera.rotation) * (point - camera.position);
    const double r = glm::length(local);
    if (!(r > 0.0) || !std::isfinite(r)) return 0.0;
    return std::clamp(local.x / r, -1.0, 1.0);
}

StereoGain pan_gains(double p) {
    const double angle = (std::clamp(p, -1.0, 1.0) + 1.0) * kPi / 4.0;
    return {std::cos(angle), std::sin(angle)};
}

std::vector<CollisionCue> collision_cues(const Timeline &timeline, double from, double to) {
    std::vector<CollisionCue> cues;
    const auto &models = timeline.document().models();
    const auto &events = timeline.events();
    // Events arrive in time order from a bake; a stable sort keeps that promise cheap to rely on.
    std::vector<const ani_collision_event *> picked;
    for (const ani_collision_event &e : events)
        if (e.t > from && e.t <= to) picked.push_back(&e);
    std::stable_sort(
        picked.begin(), picked.end(),
        [](const ani_collision_event *x, const ani_collision_event *y) { return x->t < y->t; });
    for (const ani_collision_event *e : picked) {
        const glm::dvec3 point(e->point.x, e->point.y, e->point.z);
        const CameraState camera = timeline.keyed().camera(e->t);
        const double r = glm::length(point - camera.position);
        const double p = pan(camera, point);
        for (const uint32_t m : {e->a, e->b}) {
            if (m == ANI_NO_MODEL || m >= models.size()) continue;
            const Model &model = models[m];
            if (model.collision_sound.empty()) continue;
            cues.push_back({static_cast<int>(m), model.collision_sound, e->t,
                            volume(energy(model.mass, e->speed), r), p});
        }
    }
    return cues;
}

std::vector<glm::dvec3> world_centers(const std::vector<Model> &models, const Frame &frame) {
    std::vector<glm::dmat4> world(models.size(), glm::dmat4(1.0));
    std::vector<glm::dvec3> centers(models.size(), glm::dvec3(0.0));
    for (size_t m = 0; m < models.size() && m < frame.models.size(); ++m) {
        const int parent = models[m].parent;
        // Parents come before their children in the document.
        const glm::dmat4 up = parent >= 0 && static_cast<size_t>(parent) < m
                                  ? world[static_cast<size_t>(parent)]
                                  : glm::dmat4(1.0);
        world[m] = up * local_matrix(frame.models[m]);
        centers[m] = glm::dvec3(up * glm::dvec4(frame.models[m].center, 1.0));
    }
    return centers;
}

MovingState moving_state(const Timeline &timeline, int model, double t) {
    const auto &models = timeline.document().models();
    if (model < 0 || static_cast<size_t>(model) >= models.size() ||
        models[static_cast<size_t>(model)].moving_sound.empty())
        return {};
    return moving_states(timeline, t)[static_cast<size_t>(model)];
}

std::vector<MovingState> moving_states(const Timeline &timeline, double t) {
    const auto &models = timeline.document().models();
    std::vector<MovingState> states(models.size());
    const bool any = std::any_of(models.begin(), models.end(),
                                 [](const Model &m) { return !m.moving_sound.empty(); });
    if (!any) return states;
    const Frame frame = timeline.evaluate(t);
    const std::vector<glm::dvec3> centers = world_centers(models, frame);
    const std::vector<double> speeds = world_speeds(timeline, t, frame, centers);
    for (size_t m = 0; m < models.size(); ++m)
        states[m] = state_of(models[m], speeds[m], centers[m], frame.camera);
    return states;
}

bool has_sounds(const Document &doc) {
    return std::any_of(doc.models().begin(), doc.models().end(), [](const Model &m) {
        return !m.collision_sound.empty() || !m.moving_sound.empty();
    });
}

} // namespace animator::audio
