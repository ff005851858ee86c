// Which shading features a model's draw needs (shading.h's ani_shading_feature bits): only what
// it uses, so a scene without textures, reflection, refraction or cel shading pays for none.
#pragma once

#include "document/document.hpp"

#include <cstdint>

namespace animator {

// `has_texture`: the model names a texture and it was loaded. `cel_shading`: the animation's
// setting. `selected`: the editor's selection.
uint32_t model_features(const Model &model, bool has_texture, bool cel_shading, bool selected);

} // namespace animator
