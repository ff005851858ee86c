// physics.custom's print of a scene (scene_print.hpp): how a bake call is recognised as the next
// slice of the bake before it. The print is two hashes, so these check what a hash can get wrong:
// the same scene prints the same, and one number changed anywhere (a mass, a key's state by one
// unit in the last place, a key time, the order of the models) prints differently; a key that
// cannot be evaluated, or a NaN, makes a print equal to no other, and -0 counts as 0.
#include "scene_print.hpp"

#include <catch2/catch.hpp>
#include <glm/vec3.hpp>

#include <cmath>
#include <vector>

using physics_custom::scene_print;

namespace {

// Three balls, each keyed at 0 and 1 s: a scene built as the host builds one.
struct Scene {
    std::vector<ani_model_desc> descs;
    std::vector<ani_physics_model> models;
    std::vector<ani_time_span> spans;
    std::vector<double> key_times = {0.0, 1.0};
    std::vector<glm::dvec3> centres; // each model's keyed centre (the same at every key)
    bool fails = false;              // the keys of model 1 cannot be evaluated
    ani_physics_scene scene{};

    Scene() {
        for (int m = 0; m < 3; ++m) centres.emplace_back(m, 2.0 * m, 0.5);
        descs.resize(3);
        models.resize(3);
        spans.assign(3, ani_time_span{0.0, 1.0});
        for (std::size_t m = 0; m < 3; ++m) {
            descs[m].struct_size = sizeof(ani_model_desc);
            descs[m].dynamics = 1;
            descs[m].gravity = 1;
            descs[m].mass = 1.0 + static_cast<double>(m);
            descs[m].restitution = 1.0;
            models[m].struct_size = sizeof(ani_physics_model);
            models[m].group = static_cast<uint32_t>(m);
            models[m].keyed_span_count = 1;
            models[m].key_count = 2;
        }
        scene.struct_size = sizeof scene;
        scene.gravity = 9.81;
        scene.down_axis = 1;
        scene.host_context = this;
        scene.evaluate_keyed = [](void *context, uint32_t m, double, ani_model_state *s,
                                  ani_vec3 *v) {
            const auto *self = static_cast<const Scene *>(context);
            if (self->fails && m == 1) return ANI_ERR_FAILED;
            const glm::dvec3 &c = self->centres[m];
            *s = ani_model_state{};
            s->center = ani_vec3{c.x, c.y, c.z};
            s->scale = ani_vec3{1.0, 1.0, 1.0};
            *v = ani_vec3{0.0, 0.0, 0.0};
            return ANI_OK;
        };
    }
    // The pointers, as they are now (the vectors may have moved).
    const ani_physics_scene &get() {
        for (std::size_t m = 0; m < models.size(); ++m) {
            models[m].desc = &descs[m];
            models[m].keyed_spans = &spans[m];
            models[m].key_times = key_times.data();
        }
        scene.models = models.data();
        scene.model_count = static_cast<uint32_t>(models.size());
        return scene;
    }
};

} // namespace

TEST_CASE("a scene's print is the same for the same scene, and differs when one number does") {
    Scene s;
    const auto before = scene_print(s.get());
    CHECK(scene_print(s.get()) == before);
    {
        Scene t; // built anew: the same numbers in other memory
        CHECK(scene_print(t.get()) == before);
    }
    SECTION("a mass") {
        s.descs[2].mass = 3.0000000000000004;
    }
    SECTION("a key's centre, by one unit in the last place") {
        s.centres[1].y = std::nextafter(s.centres[1].y, 10.0);
    }
    SECTION("a key time") {
        s.key_times[1] = 1.5;
    }
    SECTION("the end of a keyed span") {
        s.spans[0].end = 2.0;
    }
    SECTION("gravity") {
        s.scene.gravity = 9.8;
    }
    SECTION("two models' masses swapped") {
        std::swap(s.descs[0].mass, s.descs[1].mass);
    }
    SECTION("a model more") {
        s.descs.push_back(s.descs[2]);
        s.models.push_back(s.models[2]);
        s.spans.push_back(s.spans[2]);
        s.centres.push_back(s.centres[2]);
    }
    CHECK(scene_print(s.get()) != before);
}

TEST_CASE("a scene's print takes -0 as 0, and a key it cannot evaluate or a NaN as equal to nothing") {
    Scene s;
    const auto before = scene_print(s.get());
    s.centres[0].x = -0.0; // was 0
    CHECK(scene_print(s.get()) == before);

    s.fails = true;
    const auto failing = scene_print(s.get());
    CHECK(failing.unknown());
    CHECK(failing != scene_print(s.get()));
    CHECK(failing != before);

    Scene n;
    n.scene.gravity = std::nan("");
    const auto with_nan = scene_print(n.get());
    CHECK(with_nan != scene_print(n.get()));
}

TEST_CASE("a scene's print made a few models at a time is the print made at once") {
    // (A large gas's print is made so by the lane's reporting thread while it waits.)
    Scene s;
    for (int m = 0; m < 40; ++m) { // 43 models, each its own mass and centre
        s.descs.push_back(s.descs[m % 3]);
        s.descs.back().mass = 1.0 + 0.25 * m;
        s.models.push_back(s.models[m % 3]);
        s.spans.push_back(s.spans[m % 3]);
        s.centres.emplace_back(m, -m, 0.5 * m);
    }
    const auto whole = scene_print(s.get());
    for (uint32_t step : {1u, 2u, 5u, 7u, 43u, 1000u}) {
        CAPTURE(step);
        physics_custom::ScenePrinter printer(s.get());
        int steps = 1;
        while (!printer.step(step)) ++steps;
        CHECK(steps == static_cast<int>((43 + step - 1) / step));
        CHECK(printer.done());
        CHECK(printer.print() == whole);
        CHECK(printer.step(3)); // (done stays done)
        CHECK(printer.print() == whole);
    }
    // Not done, it is not the whole scene's print.
    physics_custom::ScenePrinter part(s.get());
    part.step(42);
    CHECK_FALSE(part.done());
    CHECK(part.print() != whole);
}
