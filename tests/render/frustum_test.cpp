// Frustum culling: which bounding spheres can be seen.
#include "render/frustum.hpp"
#include "render/scene_math.hpp"

#include <catch2/catch.hpp>

#include <cmath>

using namespace animator;

TEST_CASE("the frustum keeps spheres in view or straddling a plane and culls the rest") {
    CameraState camera;
    camera.position = {0, 0, 10};
    camera.fov_degrees = 60;
    const Frustum f(projection_matrix(60, 1.0, 0.1, 100.0) * view_matrix(camera));
    CHECK(f.may_see({0, 0, 0}, 1.0));          // straight ahead
    CHECK_FALSE(f.may_see({0, 0, 20}, 1.0));   // behind the camera
    CHECK_FALSE(f.may_see({0, 0, -200}, 1.0)); // past the far plane
    // At distance 10 the half-height is 10 tan(30) = 5.77: a sphere at y = 7 with radius 1
    // is out, with radius 2 it straddles the top plane.
    CHECK_FALSE(f.may_see({0, 7, 0}, 1.0));
    CHECK(f.may_see({0, 7, 0}, 2.0));
    CHECK_FALSE(f.may_see({-8, 0, 0}, 1.0));
}

TEST_CASE("a bounding sphere grows with the largest scale of its model") {
    ModelPose pose;
    pose.center = {1, 2, 3};
    pose.scale = {1, 4, 2};
    glm::dvec3 c;
    double r = 0.0;
    transform_bounding_sphere(model_matrix(pose), {0, 1, 0}, 0.5, c, r);
    CHECK(c == glm::dvec3(1, 6, 3));
    CHECK(r == Approx(2.0));
}

TEST_CASE("a sheared model's bounding sphere holds every point of its mesh's sphere") {
    // A shear stretches some directions by more than any column's length: the unit sphere's point
    // along the largest singular direction must stay inside.
    glm::dmat4 shear(1.0);
    shear[1][0] = 2.0; // x += 2 y
    glm::dvec3 c;
    double r = 0.0;
    transform_bounding_sphere(shear, {0, 0, 0}, 1.0, c, r);
    // The largest singular value of [[1, 2], [0, 1]] is 1 + sqrt(2).
    CHECK(r >= 1.0 + std::sqrt(2.0) - 1e-12);
    CHECK(r <= 3.0); // and not far more: the squared column lengths sum to 1 + 5 + 1
}
