// Mass properties of closed meshes (mass_properties.hpp) against closed forms derived by hand
// in each test, to 1e-12 relative; the detection of meshes that are not closed; and a box turning
// freely (free_rotation.hpp) from its principal frame.
#include "animator/free_rotation.hpp"
#include "mass_properties.hpp"

#include <catch2/catch.hpp>
#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/matrix.hpp>

#include <cmath>
#include <random>
#include <vector>

using namespace physics_custom;
using namespace ani;

namespace {

struct Mesh {
    std::vector<double> positions;
    std::vector<uint32_t> triangles;
    ani_mesh_view view() const {
        ani_mesh_view v{};
        v.struct_size = sizeof v;
        v.positions = positions.data();
        v.vertex_count = uint32_t(positions.size() / 3);
        v.triangles = triangles.data();
        v.triangle_count = uint32_t(triangles.size() / 3);
        return v;
    }
    glm::dvec3 vertex(uint32_t i) const {
        return {positions[3 * i], positions[3 * i + 1], positions[3 * i + 2]};
    }
    uint32_t add(const glm::dvec3 &p) {
        positions.insert(positions.end(), {p.x, p.y, p.z});
        return uint32_t(positions.size() / 3 - 1);
    }
    // Adds triangle a, b, c ordered counter-clockwise seen from outside, for a convex solid
    // with `inside` a point inside it.
    void face(uint32_t a, uint32_t b, uint32_t c, const glm::dvec3 &inside) {
        const glm::dvec3 n = glm::cross(vertex(b) - vertex(a), vertex(c) - vertex(a));
        if (glm::dot(n, vertex(a) - inside) < 0) std::swap(b, c);
        triangles.insert(triangles.end(), {a, b, c});
    }
};

// The box [0,a] x [0,b] x [0,c]: 8 corners, 12 triangles.
Mesh box(double a, double b, double c) {
    Mesh m;
    for (int k = 0; k < 8; ++k) m.add({k & 1 ? a : 0.0, k & 2 ? b : 0.0, k & 4 ? c : 0.0});
    const glm::dvec3 inside(a / 2, b / 2, c / 2);
    const int quads[6][4] = {{0, 1, 3, 2}, {4, 5, 7, 6}, {0, 1, 5, 4},
                             {2, 3, 7, 6}, {0, 2, 6, 4}, {1, 3, 7, 5}};
    for (const auto &q : quads) {
        m.face(q[0], q[1], q[2], inside);
        m.face(q[0], q[2], q[3], inside);
    }
    return m;
}

// A regular N-gon of circumradius R in the plane z = 0 centred on the axis, joined to a top:
// a prism of height h (top polygon at z = h) or, when `apex`, a pyramid with apex (0, 0, h).
Mesh prism_or_pyramid(int N, double R, double h, bool apex) {
    Mesh m;
    std::vector<uint32_t> bottom, top;
    for (int i = 0; i < N; ++i) {
        const double a = 2 * M_PI * i / N;
        bottom.push_back(m.add({R * std::cos(a), R * std::sin(a), 0.0}));
    }
    const uint32_t bottom_center = m.add({0, 0, 0});
    const glm::dvec3 inside(0, 0, h / 4);
    if (apex) {
        const uint32_t tip = m.add({0, 0, h});
        for (int i = 0; i < N; ++i) m.face(bottom[i], bottom[(i + 1) % N], tip, inside);
    } else {
        for (int i = 0; i < N; ++i) {
            const glm::dvec3 p = m.vertex(bottom[i]);
            top.push_back(m.add({p.x, p.y, h}));
        }
        const uint32_t top_center = m.add({0, 0, h});
        for (int i = 0; i < N; ++i) {
            const int j = (i + 1) % N;
            m.face(bottom[i], bottom[j], top[j], inside);
            m.face(bottom[i], top[j], top[i], inside);
            m.face(top[i], top[j], top_center, inside);
        }
    }
    for (int i = 0; i < N; ++i) m.face(bottom[i], bottom[(i + 1) % N], bottom_center, inside);
    return m;
}

void require_close(double got, double want, double scale) {
    INFO("got " << got << " want " << want);
    REQUIRE(std::abs(got - want) <= 1e-12 * scale);
}

void require_tensor(const glm::dmat3 &got, const glm::dmat3 &want, double scale) {
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r) require_close(got[c][r], want[c][r], scale);
}

} // namespace

TEST_CASE("mass properties: the unit cube has m/6 about each axis") {
    const Mesh cube = box(1, 1, 1);
    REQUIRE(is_closed(cube.view()));
    const MassProperties p = mass_properties(cube.view(), 3.0);
    require_close(p.volume, 1.0, 1.0);
    for (int i = 0; i < 3; ++i) require_close(p.center_of_mass[i], 0.5, 1.0);
    require_tensor(p.inertia, glm::dmat3(0.5), 0.5); // 3/6 on the diagonal, 0 off it
    for (int i = 0; i < 3; ++i) require_close(p.principal_moments[i], 0.5, 0.5);
}

TEST_CASE("mass properties: a box a x b x c has m (b^2 + c^2) / 12 ... and axes by size") {
    const double a = 1.0, b = 2.0, c = 3.0, m = 2.5;
    const MassProperties p = mass_properties(box(a, b, c).view(), m);
    require_close(p.volume, a * b * c, a * b * c);
    require_close(p.center_of_mass.x, a / 2, c);
    require_close(p.center_of_mass.y, b / 2, c);
    require_close(p.center_of_mass.z, c / 2, c);
    const double Ix = m * (b * b + c * c) / 12, Iy = m * (a * a + c * c) / 12,
                 Iz = m * (a * a + b * b) / 12;
    glm::dmat3 want(0.0);
    want[0][0] = Ix, want[1][1] = Iy, want[2][2] = Iz;
    require_tensor(p.inertia, want, Ix);
    // Ascending: Iz < Iy < Ix; the axes z, y, then x made right-handed: z x y = -x.
    require_close(p.principal_moments[0], Iz, Ix);
    require_close(p.principal_moments[1], Iy, Ix);
    require_close(p.principal_moments[2], Ix, Ix);
    const glm::dmat3 axes = glm::mat3_cast(p.principal_orientation);
    require_tensor(axes, glm::dmat3(glm::dvec3(0, 0, 1), glm::dvec3(0, 1, 0), glm::dvec3(-1, 0, 0)),
                   1.0);
}

TEST_CASE("mass properties: a box moved and turned carries its centre and tensor along") {
    // Moving every vertex by x -> R x + T moves the centre of mass the same way and turns the
    // tensor about it: I' = R I R^T (the inertia integral of (r.r) 1 - r r^T in new coordinates).
    const double a = 1.0, b = 2.0, c = 3.0, m = 4.0;
    const glm::dquat q = glm::normalize(glm::dquat(0.8, 0.3, -0.5, 0.2));
    const glm::dmat3 R = glm::mat3_cast(q);
    const glm::dvec3 T(100.0, -50.0, 7.0);
    Mesh moved = box(a, b, c);
    for (size_t i = 0; i < moved.positions.size(); i += 3) {
        const glm::dvec3 p = R * moved.vertex(uint32_t(i / 3)) + T;
        moved.positions[i] = p.x, moved.positions[i + 1] = p.y, moved.positions[i + 2] = p.z;
    }
    REQUIRE(is_closed(moved.view()));
    const MassProperties p = mass_properties(moved.view(), m);
    const glm::dvec3 center = R * glm::dvec3(a / 2, b / 2, c / 2) + T;
    for (int i = 0; i < 3; ++i) require_close(p.center_of_mass[i], center[i], 100.0);
    glm::dmat3 local(0.0);
    local[0][0] = m * (b * b + c * c) / 12, local[1][1] = m * (a * a + c * c) / 12,
    local[2][2] = m * (a * a + b * b) / 12;
    const double scale = local[0][0];
    require_tensor(p.inertia, R * local * glm::transpose(R), scale);
    // The principal axes are the turned box axes z, y, x up to sign, right-handed.
    const glm::dmat3 axes = glm::mat3_cast(p.principal_orientation);
    require_close(std::abs(glm::dot(axes[0], R[2])), 1.0, 1.0);
    require_close(std::abs(glm::dot(axes[1], R[1])), 1.0, 1.0);
    require_close(std::abs(glm::dot(axes[2], R[0])), 1.0, 1.0);
    require_close(glm::determinant(axes), 1.0, 1.0);
    require_tensor(glm::transpose(axes) * p.inertia * axes,
                   glm::dmat3(glm::dvec3(local[2][2], 0, 0), glm::dvec3(0, local[1][1], 0),
                              glm::dvec3(0, 0, local[0][0])),
                   scale);
}

TEST_CASE("mass properties: a regular tetrahedron has m a^2 / 20 about every axis") {
    // Edge a = 2 sqrt 2 for the corners v_i = (1,1,1), (1,-1,-1), (-1,1,-1), (-1,-1,1) of a
    // cube; volume a^3 / (6 sqrt 2) = 8/3, centroid 0. The second moments of a tetrahedron are
    // integral x x^T dm = m/20 (sum v_i v_i^T + s s^T), s = sum v_i = 0 here; sum v_i v_i^T is
    // 4 on the diagonal and 0 off it (1 - 1 - 1 + 1), so <x^2> = m/5 and each moment is
    // I = <y^2> + <z^2> = 2m/5 = m a^2 / 20, with no products of inertia.
    Mesh t;
    const glm::dvec3 v[4] = {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
    for (const auto &p : v) t.add(p);
    t.face(0, 1, 2, glm::dvec3(0.0));
    t.face(0, 1, 3, glm::dvec3(0.0));
    t.face(0, 2, 3, glm::dvec3(0.0));
    t.face(1, 2, 3, glm::dvec3(0.0));
    REQUIRE(is_closed(t.view()));
    const double m = 7.0, edge2 = 8.0;
    const MassProperties p = mass_properties(t.view(), m);
    require_close(p.volume, std::pow(std::sqrt(edge2), 3) / (6 * std::sqrt(2.0)), 1.0);
    for (int i = 0; i < 3; ++i) require_close(p.center_of_mass[i], 0.0, 1.0);
    require_tensor(p.inertia, glm::dmat3(m * edge2 / 20), m);
}

TEST_CASE("mass properties: a 64-sided prism and pyramid against their polyhedral closed forms") {
    // A regular N-gon of circumradius R, alpha = 2 pi / N, is N triangles (0, P_i, P_i+1); for a
    // triangle with a corner at 0, integral |x|^2 dA = area/12 (|P1|^2 + |P2|^2 + |P1 + P2|^2)
    // = area R^2 (2 + cos alpha) / 6, so the polygon's polar moment per area is
    // J/A = R^2 (2 + cos alpha) / 6, split equally between x^2 and y^2 (N >= 3 symmetry).
    // Prism of height h: Izz = m J/A, Ixx = Iyy = m J/(2A) + m h^2 / 12 about the centre h/2.
    // Pyramid of height h: a slice at z is the polygon scaled by s = 1 - z/h, density rho,
    // m = rho A h / 3; Izz = rho J h / 5 = 3/5 m J/A; about the base centre
    // Ixx = rho (J/2) h/5 + rho A h^3/30 = 3/10 m J/A + m h^2/10; the centre is at h/4, so
    // Ixx = 3/10 m J/A + 3/80 m h^2 (a cone, J/A = R^2/2: 3/20 m R^2 + 3/80 m h^2).
    const int N = 64;
    const double R = 1.5, h = 2.0, m = 3.0, alpha = 2 * M_PI / N;
    const double JA = R * R * (2 + std::cos(alpha)) / 6, area = N * R * R * std::sin(alpha) / 2;

    const Mesh prism = prism_or_pyramid(N, R, h, false);
    REQUIRE(is_closed(prism.view()));
    MassProperties p = mass_properties(prism.view(), m);
    require_close(p.volume, area * h, area * h);
    require_close(p.center_of_mass.z, h / 2, h);
    require_close(p.center_of_mass.x, 0.0, h);
    glm::dmat3 want(0.0);
    want[0][0] = want[1][1] = m * JA / 2 + m * h * h / 12;
    want[2][2] = m * JA;
    require_tensor(p.inertia, want, want[2][2]);

    const Mesh pyramid = prism_or_pyramid(N, R, h, true);
    REQUIRE(is_closed(pyramid.view()));
    p = mass_properties(pyramid.view(), m);
    require_close(p.volume, area * h / 3, area * h);
    require_close(p.center_of_mass.z, h / 4, h);
    want[0][0] = want[1][1] = 3.0 / 10 * m * JA + 3.0 / 80 * m * h * h;
    want[2][2] = 3.0 / 5 * m * JA;
    require_tensor(p.inertia, want, want[2][2]);
}

TEST_CASE("mass properties: a sphere mesh takes the ball's closed form") {
    ani_mesh_view sphere{};
    sphere.struct_size = sizeof sphere;
    sphere.bound_center = {1.0, 2.0, 3.0};
    sphere.bound_radius = 2.0;
    sphere.is_sphere = 1;
    const MassProperties p = mass_properties(sphere, 5.0);
    require_tensor(p.inertia, glm::dmat3(0.4 * 5.0 * 4.0), 8.0);
    require_close(p.volume, 4.0 / 3.0 * M_PI * 8.0, 1.0);
    REQUIRE(p.center_of_mass == glm::dvec3(1.0, 2.0, 3.0));
}

TEST_CASE("mass properties: the principal frame reproduces a random symmetric tensor") {
    std::mt19937_64 rng(18);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (int trial = 0; trial < 200; ++trial) {
        glm::dmat3 T;
        for (int c = 0; c < 3; ++c)
            for (int r = c; r < 3; ++r) T[c][r] = T[r][c] = u(rng) * (r == c ? 3.0 : 1.0);
        glm::dvec3 moments;
        glm::dmat3 axes;
        principal_axes(T, moments, axes);
        REQUIRE(moments[0] <= moments[1]);
        REQUIRE(moments[1] <= moments[2]);
        require_close(glm::determinant(axes), 1.0, 1.0);
        require_tensor(glm::transpose(axes) * axes, glm::dmat3(1.0), 1.0);
        glm::dmat3 D(0.0);
        for (int i = 0; i < 3; ++i) D[i][i] = moments[i];
        require_tensor(axes * D * glm::transpose(axes), T, 3.0);
        require_tensor(glm::mat3_cast(quaternion_of(axes)), axes, 1.0);
    }
}

TEST_CASE("mass properties: open meshes and misoriented triangles are found") {
    std::string why;
    Mesh cube = box(1, 1, 1);
    REQUIRE(is_closed(cube.view(), &why));

    Mesh open = cube;
    open.triangles.resize(open.triangles.size() - 6); // the face x = 1 removed
    REQUIRE_FALSE(is_closed(open.view(), &why));
    REQUIRE(why.find("is used by 1 triangle") != std::string::npos);

    Mesh flipped = cube;
    std::swap(flipped.triangles[4], flipped.triangles[5]); // triangle 1 turned over
    REQUIRE_FALSE(is_closed(flipped.view(), &why));
    REQUIRE(why.find("runs the same way in triangles") != std::string::npos);

    Mesh inside_out = cube;
    for (size_t t = 0; t < inside_out.triangles.size(); t += 3)
        std::swap(inside_out.triangles[t + 1], inside_out.triangles[t + 2]);
    REQUIRE_FALSE(is_closed(inside_out.view(), &why));
    REQUIRE(why.find("face inward") != std::string::npos);

    Mesh doubled = cube; // one face twice over: its edges have 3 or 4 users
    doubled.triangles.insert(doubled.triangles.end(), cube.triangles.begin(),
                             cube.triangles.begin() + 6);
    REQUIRE_FALSE(is_closed(doubled.view(), &why));
    REQUIRE(why.find("triangles") != std::string::npos);
}

TEST_CASE("mass properties: a box's principal frame turns freely with its full tensor's L and E") {
    // A 1 x 2 x 3 box of 4 kg turned by q_model: its principal frame is q_model * P (P the
    // principal orientation in the model), and the model at t is q(t) * conj(P). With the
    // model-frame tensor I_m (not the principal moments) the world tensor is R I_m R^T, and
    // L = R I_m R^T w and E = w . L / 2 stay what they were at t0 (no torque).
    const MassProperties p = mass_properties(box(1, 2, 3).view(), 4.0);
    const glm::dquat q_model = glm::normalize(glm::dquat(0.3, 0.9, -0.1, 0.4));
    const glm::dvec3 w0(0.7, -2.0, 1.1);
    const FreeRotation rotation(p.principal_moments, q_model * p.principal_orientation, w0, 0.0);
    auto momentum = [&](const glm::dquat &q, const glm::dvec3 &w) {
        const glm::dmat3 R = glm::mat3_cast(q);
        return R * p.inertia * glm::transpose(R) * w;
    };
    const glm::dvec3 L0 = momentum(q_model, w0);
    const double E0 = 0.5 * glm::dot(w0, L0);
    for (double t : {0.5, 3.0, 40.0, 900.0}) {
        glm::dquat q;
        glm::dvec3 w;
        rotation.evaluate(t, q, w);
        const glm::dvec3 L = momentum(q * glm::conjugate(p.principal_orientation), w);
        INFO("t " << t);
        require_close(glm::length(L - L0), 0.0, glm::length(L0));
        require_close(0.5 * glm::dot(w, L), E0, E0);
    }
}
