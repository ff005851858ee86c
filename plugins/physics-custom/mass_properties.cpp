#include "mass_properties.hpp"

#include <glm/matrix.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <map>
#include <utility>
#include <vector>

namespace physics_custom {

namespace {

glm::dvec3 vertex(const ani_mesh_view &mesh, uint32_t i) {
    return {mesh.positions[3 * std::size_t(i)], mesh.positions[3 * std::size_t(i) + 1],
            mesh.positions[3 * std::size_t(i) + 2]};
}

// The ten volume integrals of 1, x, y, z, x^2, y^2, z^2, xy, yz, zx over the solid, with the
// vertices taken relative to `origin` (so that a mesh far from the world origin keeps its
// digits). Eberly, "Polyhedral Mass Properties (Revisited)", Subexpressions and the sums.
std::array<double, 10> volume_integrals(const ani_mesh_view &mesh, const glm::dvec3 &origin) {
    std::array<double, 10> sum{};
    for (uint32_t t = 0; t < mesh.triangle_count; ++t) {
        const glm::dvec3 p0 = vertex(mesh, mesh.triangles[3 * std::size_t(t)]) - origin;
        const glm::dvec3 p1 = vertex(mesh, mesh.triangles[3 * std::size_t(t) + 1]) - origin;
        const glm::dvec3 p2 = vertex(mesh, mesh.triangles[3 * std::size_t(t) + 2]) - origin;
        const glm::dvec3 d = glm::cross(p1 - p0, p2 - p0);
        glm::dvec3 f1, f2, f3, g0, g1, g2;
        for (int c = 0; c < 3; ++c) {
            const double w0 = p0[c], w1 = p1[c], w2 = p2[c];
            const double temp0 = w0 + w1;
            f1[c] = temp0 + w2;
            const double temp1 = w0 * w0;
            const double temp2 = temp1 + w1 * temp0;
            f2[c] = temp2 + w2 * f1[c];
            f3[c] = w0 * temp1 + w1 * temp2 + w2 * f2[c];
            g0[c] = f2[c] + w0 * (f1[c] + w0);
            g1[c] = f2[c] + w1 * (f1[c] + w1);
            g2[c] = f2[c] + w2 * (f1[c] + w2);
        }
        sum[0] += d.x * f1.x;
        sum[1] += d.x * f2.x;
        sum[2] += d.y * f2.y;
        sum[3] += d.z * f2.z;
        sum[4] += d.x * f3.x;
        sum[5] += d.y * f3.y;
        sum[6] += d.z * f3.z;
        sum[7] += d.x * (p0.y * g0.x + p1.y * g1.x + p2.y * g2.x);
        sum[8] += d.y * (p0.z * g0.y + p1.z * g1.y + p2.z * g2.y);
        sum[9] += d.z * (p0.x * g0.z + p1.x * g1.z + p2.x * g2.z);
    }
    sum[0] /= 6.0;
    for (int i = 1; i <= 3; ++i) sum[i] /= 24.0;
    for (int i = 4; i <= 6; ++i) sum[i] /= 60.0;
    for (int i = 7; i <= 9; ++i) sum[i] /= 120.0;
    return sum;
}

glm::dvec3 mean_vertex(const ani_mesh_view &mesh) {
    glm::dvec3 sum(0.0);
    for (uint32_t i = 0; i < mesh.vertex_count; ++i) sum += vertex(mesh, i);
    return mesh.vertex_count ? sum / double(mesh.vertex_count) : sum;
}

} // namespace

void principal_axes(const glm::dmat3 &tensor, glm::dvec3 &moments, glm::dmat3 &axes) {
    // Cyclic Jacobi (Golub & Van Loan, Matrix Computations, 8.5): rotate away each off-diagonal
    // element in turn until they are zero to rounding. a[i][j] is row i, column j.
    double a[3][3], v[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) a[i][j] = 0.5 * (tensor[j][i] + tensor[i][j]);
    for (int sweep = 0; sweep < 64; ++sweep) {
        const double off = a[0][1] * a[0][1] + a[0][2] * a[0][2] + a[1][2] * a[1][2];
        const double diag = a[0][0] * a[0][0] + a[1][1] * a[1][1] + a[2][2] * a[2][2];
        if (off == 0.0 || off <= 1e-40 * diag) break;
        for (int p = 0; p < 2; ++p)
            for (int q = p + 1; q < 3; ++q) {
                if (a[p][q] == 0.0) continue;
                const double theta = (a[q][q] - a[p][p]) / (2.0 * a[p][q]);
                const double t =
                    (theta >= 0 ? 1.0 : -1.0) / (std::abs(theta) + std::sqrt(theta * theta + 1.0));
                const double c = 1.0 / std::sqrt(t * t + 1.0), s = t * c;
                for (int k = 0; k < 3; ++k) { // a = J^T a J with J the rotation in plane p, q
                    const double akp = a[k][p], akq = a[k][q];
                    a[k][p] = c * akp - s * akq;
                    a[k][q] = s * akp + c * akq;
                }
                for (int k = 0; k < 3; ++k) {
                    const double apk = a[p][k], aqk = a[q][k];
                    a[p][k] = c * apk - s * aqk;
                    a[q][k] = s * apk + c * aqk;
                }
                for (int k = 0; k < 3; ++k) {
                    const double vkp = v[k][p], vkq = v[k][q];
                    v[k][p] = c * vkp - s * vkq;
                    v[k][q] = s * vkp + c * vkq;
                }
            }
    }
    std::array<int, 3> order{0, 1, 2};
    std::stable_sort(order.begin(), order.end(), [&](int i, int j) { return a[i][i] < a[j][j]; });
    for (int n = 0; n < 3; ++n) {
        const int i = order[n];
        moments[n] = a[i][i];
        glm::dvec3 axis(v[0][i], v[1][i], v[2][i]);
        int big = 0;
        for (int k = 1; k < 3; ++k)
            if (std::abs(axis[k]) > std::abs(axis[big])) big = k;
        if (axis[big] < 0.0) axis = -axis;
        axes[n] = axis;
    }
    if (glm::determinant(axes) < 0.0) axes[2] = -axes[2];
}

MassProperties mass_properties(const ani_mesh_view &mesh, double mass) {
    MassProperties out;
    out.mass = mass;
    if (mesh.is_sphere) {
        const double r = mesh.bound_radius;
        out.volume = 4.0 / 3.0 * M_PI * r * r * r;
        out.center_of_mass = {mesh.bound_center.x, mesh.bound_center.y, mesh.bound_center.z};
        const double moment = 0.4 * mass * r * r;
        out.inertia = glm::dmat3(moment);
        out.principal_moments = glm::dvec3(moment);
        return out;
    }
    const glm::dvec3 origin = mean_vertex(mesh);
    const std::array<double, 10> in = volume_integrals(mesh, origin);
    out.volume = in[0];
    const double density = mass / in[0];
    const glm::dvec3 c(in[1] / in[0], in[2] / in[0], in[3] / in[0]); // relative to origin
    out.center_of_mass = origin + c;
    // Second moments about the centre of mass (parallel axis theorem, from `origin`).
    const double xx = density * in[4] - mass * c.x * c.x;
    const double yy = density * in[5] - mass * c.y * c.y;
    const double zz = density * in[6] - mass * c.z * c.z;
    const double xy = density * in[7] - mass * c.x * c.y;
    const double yz = density * in[8] - mass * c.y * c.z;
    const double zx = density * in[9] - mass * c.z * c.x;
    out.inertia = glm::dmat3(yy + zz, -xy, -zx, //
                             -xy, xx + zz, -yz, //
                             -zx, -yz, xx + yy);
    glm::dmat3 axes;
    principal_axes(out.inertia, out.principal_moments, axes);
    out.principal_orientation = quaternion_of(axes);
    return out;
}

} // namespace physics_custom
