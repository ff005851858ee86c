// Exact times of first contact between bodies on parabolic paths (constant acceleration between
// events), and the seed's ray-triangle test (seed, "Collision Detection"; Scratchapixel's
// geometric solution). Closed forms and polynomial roots, never stepping: a contact cannot be
// stepped over, at any speed.
#pragma once

#include <animator/triangle_geometry.hpp>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <optional>

namespace physics_custom {

// A body's center on a segment: p + v t + a t^2 / 2, t measured from the segment's start.
struct Path {
    glm::dvec3 p{0.0}, v{0.0}, a{0.0};
    glm::dvec3 at(double t) const { return p + v * t + 0.5 * a * t * t; }
    glm::dvec3 velocity(double t) const { return v + a * t; }
};

// The axis-aligned box a path sweeps over [0, t]: per axis, a parabola's extremes are at the
// ends or at its vertex.
struct Box {
    glm::dvec3 lo{0.0}, hi{0.0};
    bool overlaps(const Box &o) const {
        return lo.x <= o.hi.x && o.lo.x <= hi.x && lo.y <= o.hi.y && o.lo.y <= hi.y && lo.z <= o.hi.z && o.lo.z <= hi.z;
    }
    // The distance between the two boxes, 0 where they meet (a lower bound of the distance
    // between anything inside them).
    double distance(const Box &o) const {
        return glm::length(glm::max(glm::max(lo - o.hi, o.lo - hi), glm::dvec3(0.0)));
    }
};
Box swept_box(const Path &path, double t);

struct Contact {
    double t = 0.0;            // time of first contact
    glm::dvec3 normal{0.0};    // unit, from the other body towards the sphere
    glm::dvec3 point{0.0};     // on the sphere's surface
};

// Two spheres, radii ra and rb, approaching within [0, t_max]. None if they never touch, or if
// they touch at 0 but are separating (the step after a bounce: no sticking).
std::optional<Contact> sphere_sphere(const Path &a, double ra, const Path &b, double rb, double t_max);

// A sphere against a fixed triangle (either side): its face, its three edges, its three
// corners. The normal is the face's for a face hit and from the nearest edge point or corner
// otherwise (a grazing edge or corner hit bounces off the rim, not the face).
std::optional<Contact> sphere_triangle(const Path &sphere, double r, const glm::dvec3 &v0, const glm::dvec3 &v1,
                                       const glm::dvec3 &v2, double t_max);

// The point of the triangle nearest to q (the SDK's, shared with the host's levels of detail).
using ani::closest_point_on_triangle;

// The seed's rayTriangleIntersection: the ray start + t * ray for t in [0, 1] against the
// triangle, with the seed's inside test (dot(n, cross(edge, poi - corner)) >= 0 for all three
// edges, so only the side the triangle faces counts as inside for a counter-clockwise one).
// Returns t, or none when parallel, outside [0, 1] or outside the triangle.
std::optional<double> ray_triangle(const glm::dvec3 &start, const glm::dvec3 &ray, const glm::dvec3 &v0,
                                   const glm::dvec3 &v1, const glm::dvec3 &v2);

} // namespace physics_custom
