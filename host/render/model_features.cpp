#include "render/model_features.hpp"

#include <animator/shading.h>

namespace animator {

uint32_t model_features(const Model &model, bool has_texture, bool cel_shading, bool selected) {
    uint32_t features = 0;
    if (has_texture) features |= ANI_SHADE_TEXTURE;
    if (model.reflectivity > 0.0) features |= ANI_SHADE_REFLECTION;
    if (model.transparency > 0.0) features |= ANI_SHADE_REFRACTION;
    if (cel_shading) features |= ANI_SHADE_CEL;
    if (selected) features |= ANI_SHADE_SELECTED;
    return features;
}

} // namespace animator
