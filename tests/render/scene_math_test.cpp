// The transforms of a frame: model matrices in the document's order, parents, the camera's view,
// the projection and where a point lands on the screen.
#include "render/scene_math.hpp"

#include <catch2/catch.hpp>
#include <glm/gtc/quaternion.hpp>

using namespace animator;
using Catch::Matchers::WithinAbs;

namespace {

glm::dvec3 apply(const glm::dmat4 &m, const glm::dvec3 &p) {
    return glm::dvec3(m * glm::dvec4(p, 1.0));
}

void check_near(const glm::dvec3 &a, const glm::dvec3 &b) {
    CHECK_THAT(a.x, WithinAbs(b.x, 1e-12));
    CHECK_THAT(a.y, WithinAbs(b.y, 1e-12));
    CHECK_THAT(a.z, WithinAbs(b.z, 1e-12));
}

} // namespace

TEST_CASE("a model matrix is T(center) Rx Ry Rz S(scale), angles in degrees") {
    ModelPose pose;
    pose.center = {1, 2, 3};
    pose.scale = {2, 3, 4};
    check_near(apply(model_matrix(pose), {1, 1, 1}), {3, 5, 7});

    // Rz first on the point, then Ry, then Rx: (1, 0, 0) -Rz 90-> (0, 1, 0) -Ry 90-> (0, 1, 0)
    // -Rx 90-> (0, 0, 1).
    pose = ModelPose{};
    pose.angles = {90, 90, 90};
    check_near(apply(model_matrix(pose), {1, 0, 0}), {0, 0, 1});
    // (0, 0, 1) -Rz-> (0, 0, 1) -Ry 90-> (1, 0, 0) -Rx-> (1, 0, 0).
    check_near(apply(model_matrix(pose), {0, 0, 1}), {1, 0, 0});

    // Scale applies before rotation: a unit X stretched by 2 then turned onto Y.
    pose = ModelPose{};
    pose.angles = {0, 0, 90};
    pose.scale = {2, 1, 1};
    check_near(apply(model_matrix(pose), {1, 0, 0}), {0, 2, 0});
}

TEST_CASE("world matrices compose a model's with its parent's") {
    std::vector<Model> models(3);
    models[1].parent = 0;
    models[2].parent = 1;
    std::vector<ModelPose> poses(3);
    poses[0].center = {10, 0, 0};
    poses[0].angles = {0, 0, 90};
    poses[1].center = {1, 0, 0};
    poses[2].center = {0, 1, 0};
    std::vector<glm::dmat4> world;
    world_matrices(models, poses, world);
    REQUIRE(world.size() == 3);
    check_near(apply(world[0], {0, 0, 0}), {10, 0, 0});
    // The child's offset (1, 0, 0) is turned by the parent's 90 degrees about Z onto +Y.
    check_near(apply(world[1], {0, 0, 0}), {10, 1, 0});
    check_near(apply(world[2], {0, 0, 0}), {9, 1, 0});
}

TEST_CASE("a rest shape shapes its own model's mesh and not its children's frames") {
    std::vector<Model> models(2);
    models[0].rest[1][0] = 0.5; // x += 0.5 y
    models[1].parent = 0;
    std::vector<ModelPose> poses(2);
    poses[0].center = {10, 0, 0};
    poses[0].scale = {2, 2, 2};
    poses[1].center = {0, 1, 0};
    std::vector<glm::dmat4> world;
    world_matrices(models, poses, world);
    check_near(apply(world[1], {0, 0, 0}), {10, 2, 0}); // the child hangs from T R S only
    apply_rest_shapes(models, world);
    // The parent's mesh corner (1, 1, 0) is sheared to (1.5, 1, 0), then scaled and moved.
    check_near(apply(world[0], {1, 1, 0}), {13, 2, 0});
    check_near(apply(world[1], {0, 0, 0}), {10, 2, 0});
}

TEST_CASE("the view matrix puts the camera at the origin looking down -Z") {
    CameraState camera;
    camera.position = {0, 0, 5};
    check_near(apply(view_matrix(camera), {0, 0, 0}), {0, 0, -5});

    // Turned 90 degrees left about +Y, the camera looks down world -X.
    camera.position = {1, 2, 3};
    camera.rotation = glm::angleAxis(glm::radians(90.0), glm::dvec3(0, 1, 0));
    check_near(apply(view_matrix(camera), {1 - 5, 2, 3}), {0, 0, -5});
    check_near(apply(view_matrix(camera), {1, 2, 3 - 1}), {1, 0, 0}); // world -Z is on its right
}

TEST_CASE("a point projects to the pixel the field of view says") {
    const int width = 200, height = 100;
    const glm::dmat4 vp = projection_matrix(90.0, 2.0, 0.1, 100.0);
    auto centre = project_to_pixel(vp, {0, 0, -3}, width, height);
    REQUIRE(centre);
    CHECK_THAT(centre->x, WithinAbs(100.0, 1e-9));
    CHECK_THAT(centre->y, WithinAbs(50.0, 1e-9));
    // A vertical fov of 90 degrees: at distance 3 the top edge is y = 3, so y = 1.5 is a quarter
    // of the way down; x = 3 is half way to the right edge (the aspect is 2).
    auto p = project_to_pixel(vp, {3, 1.5, -3}, width, height);
    REQUIRE(p);
    CHECK_THAT(p->x, WithinAbs(150.0, 1e-9));
    CHECK_THAT(p->y, WithinAbs(25.0, 1e-9));
    CHECK_FALSE(project_to_pixel(vp, {0, 0, 3}, width, height));   // behind the camera
    CHECK_FALSE(project_to_pixel(vp, {10, 0, -3}, width, height)); // off to the side
}
