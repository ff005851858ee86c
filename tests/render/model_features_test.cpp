// A model's draw asks for exactly the features it uses.
#include "render/model_features.hpp"

#include <animator/shading.h>
#include <catch2/catch.hpp>

using namespace animator;

TEST_CASE("a plain model needs no feature, and each property adds its own") {
    Model m;
    m.texture = "checker";
    CHECK(model_features(m, false, false, false) == 0u); // named but not loaded: none
    CHECK(model_features(m, true, false, false) == uint32_t(ANI_SHADE_TEXTURE));
    m = Model{};
    m.reflectivity = 0.2;
    CHECK(model_features(m, false, false, false) == uint32_t(ANI_SHADE_REFLECTION));
    m = Model{};
    m.transparency = 0.2;
    m.refractive_index = 1.5;
    CHECK(model_features(m, false, false, false) == uint32_t(ANI_SHADE_REFRACTION));
    m = Model{};
    m.refractive_index = 1.5; // without transparency, refraction shows nothing
    CHECK(model_features(m, false, false, false) == 0u);
    CHECK(model_features(m, false, true, false) == uint32_t(ANI_SHADE_CEL));
    CHECK(model_features(m, false, false, true) == uint32_t(ANI_SHADE_SELECTED));
    m.reflectivity = 1;
    m.transparency = 1;
    CHECK(model_features(m, true, true, true) ==
          uint32_t(ANI_SHADE_TEXTURE | ANI_SHADE_REFLECTION | ANI_SHADE_REFRACTION | ANI_SHADE_CEL |
                   ANI_SHADE_SELECTED));
}
