#include "editor/gizmo.hpp"

#include "render/scene_math.hpp"

#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtx/euler_angles.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace animator {

namespace {

constexpr double kNear = 0.1, kFar = 1000.0; // the pixels do not depend on them
constexpr double kBoxPixels = 6.0;           // half a scale box's side
constexpr double kCenterPixels = 7.0;        // half the centre square's side
constexpr int kRingPoints = 64;

glm::dvec3 unit_or(const glm::dvec3 &v, const glm::dvec3 &fallback) {
    const double n = glm::length(v);
    return n > 1e-12 ? v / n : fallback;
}

glm::dvec3 forward_of(const CameraState &camera) { return glm::normalize(camera.rotation) * glm::dvec3(0, 0, -1); }

double cross2(glm::dvec2 a, glm::dvec2 b) { return a.x * b.y - a.y * b.x; }

// Into (-180, 180].
double wrap_half_turn(double degrees) {
    double d = std::fmod(degrees, 360.0);
    if (d > 180.0) d -= 360.0;
    if (d <= -180.0) d += 360.0;
    return d;
}

double distance_to_segment(glm::dvec2 p, glm::dvec2 a, glm::dvec2 b) {
    const glm::dvec2 ab = b - a;
    const double len2 = glm::dot(ab, ab);
    const double t = len2 > 0.0 ? std::clamp(glm::dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
    return glm::length(p - (a + ab * t));
}

// For a convex polygon in either winding.
bool inside_convex(glm::dvec2 p, const std::vector<glm::dvec2> &poly) {
    if (poly.size() < 3) return false;
    int sign = 0;
    for (size_t i = 0; i < poly.size(); ++i) {
        const double c = cross2(poly[(i + 1) % poly.size()] - poly[i], p - poly[i]);
        const int s = c > 0.0 ? 1 : (c < 0.0 ? -1 : 0);
        if (s == 0) continue;
        if (sign == 0) sign = s;
        else if (s != sign) return false;
    }
    return sign != 0; // a polygon seen edge on has no inside
}

double distance_to_shape(glm::dvec2 p, const GizmoShape &shape) {
    if (shape.filled && inside_convex(p, shape.points)) return 0.0;
    double best = std::numeric_limits<double>::infinity();
    const size_t n = shape.points.size();
    if (n == 1) return glm::length(p - shape.points[0]);
    const size_t segments = shape.closed ? n : n - 1;
    for (size_t i = 0; i < segments && n >= 2; ++i)
        best = std::min(best, distance_to_segment(p, shape.points[i], shape.points[(i + 1) % n]));
    return best;
}

std::vector<glm::dvec2> square_around(glm::dvec2 c, double half) {
    return {c + glm::dvec2(-half, -half), c + glm::dvec2(half, -half), c + glm::dvec2(half, half),
            c + glm::dvec2(-half, half)};
}

int axis_of(GizmoHandle h) {
    switch (h) {
    case GizmoHandle::AxisX: return 0;
    case GizmoHandle::AxisY: return 1;
    case GizmoHandle::AxisZ: return 2;
    default: return -1;
    }
}

// The two axes of a plane square, and the axis it is named after by its normal (its colour).
struct PlaneAxes {
    GizmoHandle handle;
    int a, b, normal;
};
constexpr std::array<PlaneAxes, 3> kPlanes{{{GizmoHandle::PlaneXY, 0, 1, 2},
                                            {GizmoHandle::PlaneYZ, 1, 2, 0},
                                            {GizmoHandle::PlaneZX, 2, 0, 1}}};

// The parameter along the line `origin + s * dir` (dir unit) of its point closest to the ray.
std::optional<double> closest_on_line(const glm::dvec3 &origin, const glm::dvec3 &dir,
                                      const std::pair<glm::dvec3, glm::dvec3> &ray) {
    const glm::dvec3 w0 = origin - ray.first;
    const double b = glm::dot(dir, ray.second);
    const double denom = 1.0 - b * b;
    if (denom < 1e-9) return std::nullopt; // the axis points along the ray
    const double d = glm::dot(dir, w0), e = glm::dot(ray.second, w0);
    return (b * e - d) / denom;
}

std::optional<glm::dvec3> hit_plane(const glm::dvec3 &point, const glm::dvec3 &normal,
                                    const std::pair<glm::dvec3, glm::dvec3> &ray) {
    const double along = glm::dot(ray.second, normal);
    if (std::abs(along) < 1e-9) return std::nullopt;
    const double t = glm::dot(point - ray.first, normal) / along;
    if (t <= 0.0) return std::nullopt;
    return ray.first + ray.second * t;
}

double snap_to(double value, double step) { return std::round(value / step) * step; }

} // namespace

glm::dmat4 GizmoView::view_projection() const {
    const double aspect = height > 0 ? static_cast<double>(width) / height : 1.0;
    return projection_matrix(camera.fov_degrees, aspect, kNear, kFar) * view_matrix(camera);
}

std::optional<glm::dvec2> GizmoView::project(const glm::dvec3 &world) const {
    const glm::dvec4 clip = view_projection() * glm::dvec4(world, 1.0);
    if (clip.w <= 1e-9) return std::nullopt;
    const glm::dvec3 ndc = glm::dvec3(clip) / clip.w;
    return glm::dvec2((ndc.x + 1.0) * 0.5 * width, (1.0 - ndc.y) * 0.5 * height);
}

std::pair<glm::dvec3, glm::dvec3> GizmoView::ray(glm::dvec2 pixel) const {
    const glm::dmat4 inverse = glm::inverse(view_projection());
    const double x = 2.0 * pixel.x / std::max(width, 1) - 1.0, y = 1.0 - 2.0 * pixel.y / std::max(height, 1);
    const glm::dvec4 near_point = inverse * glm::dvec4(x, y, -1.0, 1.0);
    const glm::dvec4 far_point = inverse * glm::dvec4(x, y, 1.0, 1.0);
    const glm::dvec3 a = glm::dvec3(near_point) / near_point.w, b = glm::dvec3(far_point) / far_point.w;
    return {camera.position, glm::normalize(b - a)};
}

std::vector<glm::dmat3> parent_matrices(const std::vector<Model> &models, const std::vector<ModelPose> &poses) {
    std::vector<glm::dmat4> world;
    world_matrices(models, poses, world);
    std::vector<glm::dmat3> out(models.size(), glm::dmat3(1.0));
    for (size_t m = 0; m < models.size(); ++m) {
        const int parent = models[m].parent;
        if (parent >= 0 && static_cast<size_t>(parent) < m) out[m] = glm::dmat3(world[static_cast<size_t>(parent)]);
    }
    return out;
}

GizmoTarget gizmo_target(const std::vector<Model> &models, const std::vector<ModelPose> &poses, int model) {
    GizmoTarget t;
    if (model < 0 || static_cast<size_t>(model) >= models.size() || static_cast<size_t>(model) >= poses.size()) return t;
    std::vector<glm::dmat4> world;
    world_matrices(models, poses, world);
    const auto m = static_cast<size_t>(model);
    t.center = glm::dvec3(world[m][3]);
    const int parent = models[m].parent;
    if (parent >= 0 && static_cast<size_t>(parent) < m) t.parent = glm::dmat3(world[static_cast<size_t>(parent)]);
    t.angles = poses[m].angles;
    return t;
}

std::optional<Gizmo> place_gizmo(const GizmoView &view, EditMode mode, const GizmoTarget &target) {
    if (mode == EditMode::Camera) return std::nullopt;
    const double depth = glm::dot(target.center - view.camera.position, forward_of(view.camera));
    if (depth <= kNear) return std::nullopt;
    const auto pixel = view.project(target.center);
    if (!pixel) return std::nullopt;
    Gizmo g;
    g.mode = mode;
    g.center = target.center;
    g.center_pixel = *pixel;
    g.parent = target.parent;
    g.length = kGizmoPixels * metres_per_pixel(depth, view.camera.fov_degrees, view.height);
    const glm::dmat3 rx(glm::eulerAngleX(glm::radians(target.angles.x)));
    const glm::dmat3 ry(glm::eulerAngleY(glm::radians(target.angles.y)));
    const glm::dmat3 rz(glm::eulerAngleZ(glm::radians(target.angles.z)));
    const std::array<glm::dvec3, 3> e{glm::dvec3(1, 0, 0), glm::dvec3(0, 1, 0), glm::dvec3(0, 0, 1)};
    std::array<glm::dvec3, 3> raw{};
    switch (mode) {
    case EditMode::Rotate: // the gimbal: each ring about the axis its own angle turns about
        raw = {target.parent * e[0], target.parent * rx * e[1], target.parent * rx * ry * e[2]};
        break;
    case EditMode::Scale: // the model's own axes
        for (int i = 0; i < 3; ++i) raw[i] = target.parent * rx * ry * rz * e[i];
        break;
    default: // the frame its position is stored in
        for (int i = 0; i < 3; ++i) raw[i] = target.parent * e[i];
        break;
    }
    for (int i = 0; i < 3; ++i) g.axes[i] = unit_or(raw[i], e[i]);
    return g;
}

std::vector<GizmoShape> gizmo_shapes(const Gizmo &g, const GizmoView &view) {
    std::vector<GizmoShape> out;
    const glm::dvec2 c = g.center_pixel;
    auto end_of = [&](int i) { return view.project(g.center + g.axes[i] * g.length); };
    // Handles whose pixels need a point behind the camera are left out (they cannot be seen).
    switch (g.mode) {
    case EditMode::Translate: {
        out.push_back({GizmoHandle::Center, -1, square_around(c, kCenterPixels), true, true});
        for (int i = 0; i < 3; ++i) {
            const auto end = end_of(i);
            if (!end) continue;
            const auto handle = static_cast<GizmoHandle>(static_cast<int>(GizmoHandle::AxisX) + i);
            const glm::dvec2 dir = glm::length(*end - c) > 1e-9 ? glm::normalize(*end - c) : glm::dvec2(1, 0);
            const glm::dvec2 side(-dir.y, dir.x);
            out.push_back({handle, i, {*end + dir * 12.0, *end + side * 5.0, *end - side * 5.0}, true, true});
            out.push_back({handle, i, {c, *end}, false, false});
        }
        for (const PlaneAxes &p : kPlanes) {
            GizmoShape s{p.handle, p.normal, {}, true, true};
            for (const glm::dvec2 uv : {glm::dvec2(0.25, 0.25), glm::dvec2(0.5, 0.25), glm::dvec2(0.5, 0.5),
                                        glm::dvec2(0.25, 0.5)}) {
                const auto px = view.project(g.center + (g.axes[p.a] * uv.x + g.axes[p.b] * uv.y) * g.length);
                if (px) s.points.push_back(*px);
            }
            if (s.points.size() == 4) out.push_back(std::move(s));
        }
        break;
    }
    case EditMode::Rotate:
        for (int i = 0; i < 3; ++i) {
            const glm::dvec3 u = unit_or(glm::cross(g.axes[i], g.axes[(i + 1) % 3]), g.axes[(i + 2) % 3]);
            const glm::dvec3 v = glm::cross(g.axes[i], u);
            GizmoShape s{static_cast<GizmoHandle>(static_cast<int>(GizmoHandle::AxisX) + i), i, {}, true, false};
            for (int k = 0; k < kRingPoints; ++k) {
                const double a = 2.0 * M_PI * k / kRingPoints;
                if (const auto px = view.project(g.center + (u * std::cos(a) + v * std::sin(a)) * g.length))
                    s.points.push_back(*px);
            }
            if (s.points.size() == kRingPoints) out.push_back(std::move(s));
        }
        break;
    case EditMode::Scale:
        out.push_back({GizmoHandle::Center, -1, square_around(c, kCenterPixels), true, true});
        for (int i = 0; i < 3; ++i) {
            const auto end = end_of(i);
            if (!end) continue;
            const auto handle = static_cast<GizmoHandle>(static_cast<int>(GizmoHandle::AxisX) + i);
            out.push_back({handle, i, square_around(*end, kBoxPixels), true, true});
            out.push_back({handle, i, {c, *end}, false, false});
        }
        break;
    case EditMode::Camera: break;
    }
    return out;
}

GizmoHandle gizmo_hit(const Gizmo &gizmo, const GizmoView &view, glm::dvec2 cursor) {
    GizmoHandle best = GizmoHandle::None;
    double best_distance = kGizmoHitPixels;
    // In order: the centre and the boxes and heads first, so a tie goes to the smaller target.
    for (const GizmoShape &s : gizmo_shapes(gizmo, view)) {
        const double d = distance_to_shape(cursor, s);
        if (d < best_distance || (d == 0.0 && best == GizmoHandle::None)) {
            best_distance = d;
            best = s.handle;
        }
    }
    return best;
}

GizmoChange gizmo_drag(const Gizmo &g, const GizmoView &view, GizmoHandle handle, glm::dvec2 from, glm::dvec2 to,
                       bool snap, double previous_degrees) {
    GizmoChange change;
    change.mode = g.mode;
    const int axis = axis_of(handle);
    switch (g.mode) {
    case EditMode::Translate: {
        if (axis >= 0) {
            // The point of the axis under the cursor follows it: the axis's point nearest the
            // cursor's ray, at the start and now.
            const auto a = closest_on_line(g.center, g.axes[axis], view.ray(from));
            const auto b = closest_on_line(g.center, g.axes[axis], view.ray(to));
            if (a && b) change.move = g.axes[axis] * (*b - *a);
            change.axis = axis;
        } else if (handle != GizmoHandle::None) {
            glm::dvec3 normal = forward_of(view.camera);
            for (const PlaneAxes &p : kPlanes)
                if (p.handle == handle) normal = unit_or(glm::cross(g.axes[p.a], g.axes[p.b]), g.axes[p.normal]);
            const auto a = hit_plane(g.center, normal, view.ray(from));
            const auto b = hit_plane(g.center, normal, view.ray(to));
            if (a && b) change.move = *b - *a;
        }
        if (snap) {
            // Each stored coordinate of the gizmo's model moves by a multiple of the step.
            glm::dvec3 local = glm::inverse(g.parent) * change.move;
            for (int i = 0; i < 3; ++i) local[i] = snap_to(local[i], kSnapMetres);
            change.move = g.parent * local;
        }
        break;
    }
    case EditMode::Rotate: {
        if (axis < 0) break;
        change.axis = axis;
        change.degrees = previous_degrees;
        const glm::dvec2 a = from - g.center_pixel, b = to - g.center_pixel;
        if (glm::length(a) < 1.0 || glm::length(b) < 1.0) break; // on the centre: no direction
        // Counter-clockwise on the screen (y down, hence the minus) is a positive turn about an
        // axis pointing at the viewer (right-handed), a negative one about an axis pointing away.
        double seen = glm::degrees(std::atan2(-cross2(a, b), glm::dot(a, b)));
        if (glm::dot(g.axes[axis], view.camera.position - g.center) < 0.0) seen = -seen;
        change.degrees = previous_degrees + wrap_half_turn(seen - previous_degrees);
        if (snap) change.degrees = snap_to(change.degrees, kSnapDegrees);
        break;
    }
    case EditMode::Scale: {
        const glm::dvec2 d = to - from;
        if (axis >= 0) {
            const auto end = view.project(g.center + g.axes[axis] * g.length);
            if (!end) break;
            const glm::dvec2 along = *end - g.center_pixel;
            const double length = glm::length(along);
            if (length < 1e-9) break;
            // Dragged out by the handle's length on the screen, the axis doubles.
            const double f = 1.0 + glm::dot(d, along / length) / std::max(length, kGizmoPixels * 0.25);
            change.factor[axis] = f;
            change.axis = axis;
        } else if (handle == GizmoHandle::Center) {
            change.factor = glm::dvec3(1.0 + (d.x - d.y) / kGizmoPixels); // right and up grow
        }
        for (int i = 0; i < 3; ++i) {
            change.factor[i] = std::max(change.factor[i], 0.01); // never flat, never mirrored
            if (snap) change.factor[i] = std::max(snap_to(change.factor[i], kSnapScale), kSnapScale);
        }
        break;
    }
    case EditMode::Camera: break;
    }
    return change;
}

ModelState apply_gizmo_change(const ModelState &start, const glm::dmat3 &parent, const GizmoChange &change) {
    ModelState s = start;
    switch (change.mode) {
    case EditMode::Translate: {
        if (change.move == glm::dvec3(0.0)) break;
        const glm::dvec3 local = glm::inverse(parent) * change.move;
        if (change.axis >= 0) s.center[change.axis] = start.center[change.axis] + local[change.axis];
        else s.center = start.center + local;
        break;
    }
    case EditMode::Rotate:
        // As the mouse drags turn (manipulation.cpp): a turn that increases the angle is
        // counter-clockwise, recorded as a negative `turn` (the seed's ccw).
        if (change.axis < 0 || change.degrees == 0.0) break;
        s.angles[change.axis] = wrap_degrees(start.angles[change.axis] + change.degrees);
        s.turn[change.axis] = change.degrees > 0.0 ? -1.0 : 1.0;
        break;
    case EditMode::Scale:
        for (int i = 0; i < 3; ++i)
            if (change.factor[i] != 1.0) s.scale[i] = start.scale[i] * change.factor[i];
        break;
    case EditMode::Camera: break;
    }
    return s;
}

} // namespace animator
