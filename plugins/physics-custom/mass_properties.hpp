// Mass properties of a closed triangle mesh of uniform density: volume, centre of mass, inertia
// tensor about the centre of mass, and its principal moments and axes, for the rotation of
// rigid bodies (free_rotation.hpp). Volume integrals by the divergence theorem over each
// triangle (Mirtich 1996, "Fast and accurate computation of polyhedral mass properties"; in the
// form of Eberly, "Polyhedral Mass Properties (Revisited)"), exact for polyhedra.
#pragma once

#include <animator/free_rotation.hpp>
#include <animator/mesh_topology.hpp>
#include <animator/physics.h>

#include <glm/gtc/quaternion.hpp>
#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

#include <string>

namespace physics_custom {

struct MassProperties {
    double mass = 0.0;
    double volume = 0.0;
    glm::dvec3 center_of_mass{0.0};
    glm::dmat3 inertia{0.0};           // about the centre of mass, model axes (kg m^2)
    glm::dvec3 principal_moments{0.0}; // I1 <= I2 <= I3
    // The rotation from the principal frame to the model frame: its columns (as a matrix) are
    // the principal axes; right-handed, and deterministic (see principal_axes).
    glm::dquat principal_orientation{1.0, 0.0, 0.0, 0.0};
};

// Whether the mesh is closed and wound outward (the SDK's, animator/mesh_topology.hpp); `why`
// goes into the message "model 'X' cannot rotate: its mesh is not closed (why)".
using ani::is_closed;

// Principal moments (ascending) and axes of a symmetric 3x3 tensor by cyclic Jacobi rotations.
// The axes are the columns of `axes`, ordered with the moments; each axis' sign makes its
// largest-magnitude component positive (the first such component on ties), then the third is
// flipped if needed so that the frame is right-handed. Equal moments leave the axes within
// their eigenspace as Jacobi finds them (deterministic for a given tensor).
void principal_axes(const glm::dmat3 &tensor, glm::dvec3 &moments, glm::dmat3 &axes);

// The mass properties of a closed mesh of the given mass (> 0) and uniform density. The mesh
// must be closed (is_closed) with positive volume. When mesh.is_sphere, the closed forms of a
// solid ball: centre bound_center, inertia 2/5 m r^2 with r = bound_radius, volume 4/3 pi r^3.
MassProperties mass_properties(const ani_mesh_view &mesh, double mass);

using ani::quaternion_of; // animator/free_rotation.hpp

} // namespace physics_custom
