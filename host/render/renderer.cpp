#include "render/renderer.hpp"

#include "render/model_features.hpp"
#include "render/scene_math.hpp"

#include <glad/gl.h>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <cmath>
#include <tuple>
#include <iostream>
#include <limits>

namespace animator {

namespace {

std::unique_ptr<PluginInstance> shading_instance(PluginRegistry &plugins, const std::string &id) {
    if (id.empty()) return nullptr;
    const PluginInfo *info = plugins.find(id);
    if (!info || info->kind != ANI_KIND_SHADING) {
        std::string known;
        for (const PluginInfo *p : plugins.find_kind(ANI_KIND_SHADING))
            known += (known.empty() ? "" : ", ") + p->id;
        throw PluginError("no shading plugin '" + id +
                          "' (found: " + (known.empty() ? "none" : known) + ")");
    }
    return std::make_unique<PluginInstance>(*info, plugins.host());
}

// Sorts (features, model) pairs by features, models in the document's order within a group.
void group_by_program(std::vector<std::pair<std::uint32_t, int>> &draws) {
    std::stable_sort(draws.begin(), draws.end(),
                     [](const auto &a, const auto &b) { return a.first < b.first; });
}

// The skybox's faces in GL's cube-map order (docs/assets.md).
constexpr const char *kFaces[6] = {"right", "left", "top", "bottom", "front", "back"};

} // namespace

Renderer::Renderer(PluginRegistry &plugins, const AssetPaths &assets, RenderOptions options,
                   LogSink log)
    : assets_(assets), options_(std::move(options)), log_(std::move(log)) {
    if (!log_) log_ = [](const std::string &m) { std::cerr << "animator: warning: " << m << "\n"; };
    programs_ =
        std::make_unique<ShadingPrograms>(shading_instance(plugins, options_.shading), log_);
    skybox_cube_ = std::make_unique<GpuMesh>(GpuMesh::skybox_cube());
}

Renderer::~Renderer() {
    if (sky_sampler_) glDeleteSamplers(1, &sky_sampler_);
}

void Renderer::set_document(const Document &doc,
                            const std::vector<std::shared_ptr<const Mesh>> &meshes) {
    models_ = doc.models();
    settings_ = doc.settings();
    // Uploads are keyed by the mesh's address: every mesh uploaded before is still held by
    // meshes_ until here, so a new mesh cannot have the address of an old one.
    meshes_ = meshes;
    meshes_.resize(models_.size());
    gpu_meshes_.assign(models_.size(), nullptr);
    std::map<const Mesh *, std::unique_ptr<GpuMesh>> still_used;
    for (size_t m = 0; m < models_.size(); ++m) {
        const Mesh *mesh = meshes_[m].get();
        if (!mesh) continue;
        auto found = still_used.find(mesh);
        if (found == still_used.end()) {
            auto old = uploaded_.find(mesh);
            found = still_used
                        .emplace(mesh, old != uploaded_.end() ? std::move(old->second)
                                                              : std::make_unique<GpuMesh>(*mesh))
                        .first;
        }
        gpu_meshes_[m] = found->second.get();
    }
    uploaded_ = std::move(still_used);

    if (settings_.skybox != skybox_id_) load_skybox(settings_.skybox);

    programs_->reset_params();
    const auto saved = settings_.params.find(programs_->plugin_id());
    if (saved != settings_.params.end())
        for (const auto &[id, value] : saved->second) programs_->set_param(id, value);
}

void Renderer::load_skybox(const std::string &id) {
    skybox_id_ = id;
    skybox_.reset();
    if (id.empty()) return;
    try {
        const auto folder = assets_.resolve(ANI_ASSET_SKYBOX, id);
        if (!folder) throw AssetError(assets_.searched(ANI_ASSET_SKYBOX, id));
        std::array<Image, 6> faces;
        for (size_t i = 0; i < 6; ++i) {
            auto file = *folder / (std::string(kFaces[i]) + ".png");
            if (!std::filesystem::exists(file)) file.replace_extension(".bmp");
            faces[i] = load_image(file);
        }
        skybox_ = GpuTexture::cube_map(faces);
        skybox_size_ = faces[0].width;
    } catch (const std::exception &e) {
        log_("skybox '" + id + "' cannot be loaded: " + e.what() + "; drawing without it");
    }
}

const GpuTexture *Renderer::texture(const std::string &id) {
    auto found = textures_.find(id);
    if (found == textures_.end()) {
        std::optional<GpuTexture> loaded;
        try {
            const auto file = assets_.resolve(ANI_ASSET_TEXTURE, id);
            if (!file) throw AssetError(assets_.searched(ANI_ASSET_TEXTURE, id));
            loaded = GpuTexture::image_2d(load_image(*file));
        } catch (const std::exception &e) {
            log_("texture '" + id + "' cannot be loaded: " + e.what() + "; drawing without it");
        }
        found = textures_.emplace(id, std::move(loaded)).first;
    }
    return found->second ? &*found->second : nullptr;
}

void Renderer::prepare_frame(const Frame &frame, int width, int height) {
    world_matrices(models_, frame.models, world_);
    apply_rest_shapes(models_, world_); // what is drawn: each mesh in its rest shape
    const glm::dmat4 view = view_matrix(frame.camera);
    const double aspect = height > 0 ? static_cast<double>(width) / height : 1.0;
    const glm::dmat4 projection = projection_matrix(frame.camera.fov_degrees, aspect,
                                                    options_.near_plane, options_.far_plane);
    view_ = view;
    view_projection_ = projection * view;
    frustum_ = Frustum(view_projection_);
    eye_ = frame.camera.position;
    FrameUniforms &u = frame_uniforms_;
    u.view = glm::mat4(view);
    u.projection = glm::mat4(projection);
    u.camera_position = glm::vec3(frame.camera.position);
    // The document's lights where it has some, else one riding with the camera.
    u.light_position.fill(glm::vec3(0.0f));
    u.light_colour.fill(glm::vec3(0.0f)); // unused slots give no light
    u.light_falloff.fill(glm::vec3(1.0f, 0.0f, 0.0f));
    const auto &lights = settings_.lights;
    if (lights.empty()) {
        u.light_count = 1;
        u.light_position[0] =
            glm::vec3(frame.camera.position +
                      glm::normalize(frame.camera.rotation) * glm::dvec3(options_.light_offset));
        u.light_colour[0] = options_.light_colour;
    } else {
        u.light_count = static_cast<int>(std::min<size_t>(lights.size(), kMaxShadingLights));
        for (size_t i = 0; i < static_cast<size_t>(u.light_count); ++i) {
            u.light_position[i] = glm::vec3(lights[i].position);
            u.light_colour[i] = glm::vec3(lights[i].colour);
            u.light_falloff[i] = glm::vec3(lights[i].falloff);
        }
    }
    u.ambient = glm::vec3(settings_.ambient);
    u.selected_tint = options_.selected_tint;

    // One level of detail a model for the frame, as the camera sees it, in the view and the shadow
    // maps: a shadow map drawn with another surface than the one it falls on would shade it
    // (speckles where a coarser level lies inside a finer one's shadow). (A cube map may see a
    // far model coarser, its shadow lookups pushed out by the difference: draw_reflections.)
    // Mirrors, glass and cel shading keep their whole meshes: what they show turns with the
    // surface's normals, which a coarser level bends by more than its outline moves (a
    // reflection's features shift by pixels); mirrors and glass take levels too when asked
    // (RenderOptions::mirror_levels).
    const double pixel_per_distance = height > 0 ? 2.0 / (projection[1][1] * height) : 0.0;
    const std::size_t count = std::min(models_.size(), world_.size());
    levels_.assign(count, 0);
    for (std::size_t m = 0; m < count; ++m) {
        const Model &model = models_[m];
        const bool mirror = model.reflectivity > 0.0 || model.transparency > 0.0;
        if (gpu_meshes_[m] && !settings_.cel_shading && (!mirror || options_.mirror_levels))
            levels_[m] = level_of(static_cast<int>(m), frame.camera.position, pixel_per_distance);
    }
}

void Renderer::bounds_of(int model, glm::dvec3 &centre, double &radius) const {
    const Mesh &mesh = *meshes_[static_cast<size_t>(model)];
    transform_bounding_sphere(world_[static_cast<size_t>(model)], mesh.bound_center,
                              mesh.bound_radius, centre, radius);
}

bool Renderer::closed_seen_from_outside(int model, const glm::dvec3 &from) const {
    if (!gpu_meshes_[static_cast<size_t>(model)]->closed()) return false;
    glm::dvec3 centre;
    double radius = 0.0;
    bounds_of(model, centre, radius);
    return glm::length(from - centre) > radius;
}

bool Renderer::visible(int model) const {
    if (hidden_.count(model)) return false;
    glm::dvec3 centre;
    double radius = 0.0;
    bounds_of(model, centre, radius);
    return frustum_.may_see(centre, radius);
}

double Renderer::stretch_of(int model) const {
    const glm::dmat4 &world = world_[static_cast<size_t>(model)];
    return std::max({glm::length(glm::dvec3(world[0])), glm::length(glm::dvec3(world[1])),
                     glm::length(glm::dvec3(world[2]))});
}

std::size_t Renderer::level_of(int model, const glm::dvec3 &eye, double pixel_per_distance) const {
    const GpuMesh &mesh = *gpu_meshes_[static_cast<size_t>(model)];
    if (options_.detail_pixels <= 0.0 || mesh.levels().size() < 2) return 0;
    glm::dvec3 centre;
    double radius = 0.0;
    bounds_of(model, centre, radius);
    // Its nearest point's distance: where its pixels are smallest. (A point off the view's axis
    // is a little nearer in depth than in distance; 25 degrees off, 10%.)
    const double distance =
        std::max(glm::length(centre - eye) - radius, options_.near_plane);
    // The mesh's errors grow with the model's largest stretch.
    const double stretch = stretch_of(model);
    if (!(stretch > 0.0)) return 0;
    return choose_level(mesh.levels(),
                        options_.detail_pixels * pixel_per_distance * distance / stretch,
                        !models_[static_cast<size_t>(model)].texture.empty());
}

std::size_t Renderer::counted_level(int model) {
    const std::size_t level = levels_[static_cast<size_t>(model)];
    const std::vector<LodLevel> &levels = gpu_meshes_[static_cast<size_t>(model)]->levels();
    stats_.triangles += levels[level].count / 3;
    stats_.triangles_saved += (levels[0].count - levels[level].count) / 3;
    return level;
}

void Renderer::bind(unsigned unit, unsigned target, unsigned name, std::size_t &counter) {
    if (bound_[unit] == name) return;
    glActiveTexture(GL_TEXTURE0 + unit);
    glBindTexture(target, name);
    bound_[unit] = name;
    ++counter;
}

void Renderer::order_front_to_back(std::vector<std::pair<std::uint32_t, int>> &draws) const {
    // (open, program, distance of its nearest point, model): a total order, so the same frame
    // draws the same way every time.
    std::vector<std::tuple<bool, std::uint32_t, double, int>> keyed;
    keyed.reserve(draws.size());
    for (const auto &[features, m] : draws) {
        glm::dvec3 centre;
        double radius = 0.0;
        bounds_of(m, centre, radius);
        keyed.emplace_back(!gpu_meshes_[static_cast<size_t>(m)]->closed(), features,
                           glm::length(centre - eye_) - radius, m);
    }
    std::sort(keyed.begin(), keyed.end());
    for (std::size_t k = 0; k < draws.size(); ++k)
        draws[k] = {std::get<1>(keyed[k]), std::get<3>(keyed[k])};
}

void Renderer::draw_skybox(int pixels_high, bool first) {
    const LinkedProgram &program = programs_->get(ANI_SHADE_SKYBOX_PASS);
    stats_.features_used |= ANI_SHADE_SKYBOX_PASS;
    glUseProgram(program.shader->name());
    ++stats_.program_binds;
    current_program_ = &program; // so that the next model binds its own
    bind(kSkyboxUnit, GL_TEXTURE_CUBE_MAP, skybox_->name(), stats_.cube_map_binds);
    apply_uniforms(program, *programs_, frame_uniforms_, nullptr);
    // The sky's texels per pixel are nearly the same over the whole view, so the pass samples one
    // level chosen here (the shading plugin's skybox pass samples at the least level its sampler
    // allows, docs/sdk.md) instead of each pixel working its level out from its neighbours': a
    // third of the sky's cost on llvmpipe. The level of the view's centre, where a face of N
    // texels spans 2 / projection[1][1] of the tangent plane over `pixels_high` pixels: 0 for
    // the view (the sky is magnified), 1 for a 128-pixel cube map of a 256-texel sky.
    if (!sky_sampler_) {
        glGenSamplers(1, &sky_sampler_);
        glSamplerParameteri(sky_sampler_, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        for (GLenum wrap : {GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T, GL_TEXTURE_WRAP_R})
            glSamplerParameteri(sky_sampler_, wrap, GL_CLAMP_TO_EDGE);
    }
    const double texels_per_pixel =
        static_cast<double>(skybox_size_) /
        (std::abs(static_cast<double>(frame_uniforms_.projection[1][1])) *
         std::max(pixels_high, 1));
    const double level = std::max(0.0, std::log2(texels_per_pixel));
    glSamplerParameterf(sky_sampler_, GL_TEXTURE_MIN_LOD, static_cast<float>(level));
    // At level 0, without mipmapping: the same texels, and llvmpipe's sampling without the mip
    // levels' logic takes the sky from 4.7 to 3.0 ms a frame at 1280x720.
    glSamplerParameteri(sky_sampler_, GL_TEXTURE_MIN_FILTER,
                        level > 0.0 ? GL_LINEAR_MIPMAP_LINEAR : GL_LINEAR);
    glBindSampler(kSkyboxUnit, sky_sampler_);
    // The seed drew it first without writing depth, so that every model covers it. Drawn after
    // the opaque models instead, at the far plane's depth (glDepthRange(1, 1)) where the depth
    // buffer is still cleared to it (GL_LEQUAL), only the pixels no model covers run its shader:
    // the same picture, without shading the sky behind a floor (docs/performance.md). (`first`:
    // as the seed did, without the depth test.) It writes neither depth nor stencil (transparent
    // models drawn after see nothing opaque there).
    glDisable(GL_CULL_FACE); // (seen from inside)
    if (first)
        glDisable(GL_DEPTH_TEST);
    else
        glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
    glDepthRange(1.0, 1.0);
    glDepthMask(GL_FALSE);
    GLboolean stencil = GL_FALSE;
    glGetBooleanv(GL_STENCIL_TEST, &stencil);
    glDisable(GL_STENCIL_TEST);
    skybox_cube_->draw();
    glBindSampler(kSkyboxUnit, 0);
    if (stencil) glEnable(GL_STENCIL_TEST);
    glEnable(GL_DEPTH_TEST);
    glDepthMask(GL_TRUE);
    glDepthRange(0.0, 1.0);
    glDepthFunc(GL_LESS);
    stats_.skybox_drawn = true;
}

uint32_t Renderer::features_of(int m, bool selected, uint32_t without, const GpuTexture **image) {
    const Model &model = models_[static_cast<size_t>(m)];
    // A stand-in for a mesh not found: plain magenta, as a placeholder reads in any 3D program.
    if (meshes_[static_cast<size_t>(m)] && meshes_[static_cast<size_t>(m)]->stand_in)
        without |= ANI_SHADE_TEXTURE | ANI_SHADE_REFLECTION | ANI_SHADE_REFRACTION;
    const GpuTexture *loaded = model.texture.empty() ? nullptr : texture(model.texture);
    if (image) *image = loaded;
    // The shadow maps the frame has (0 with shadows off) and its lights: the program reads
    // exactly those.
    return (model_features(model, loaded != nullptr, settings_.cel_shading, selected) |
            ANI_SHADE_SHADOW_MAPS(frame_uniforms_.shadow_lights) |
            ANI_SHADE_LIGHTS(frame_uniforms_.light_count)) &
           ~without;
}

void Renderer::draw_model(int m, bool selected, uint32_t without) {
    const Model &model = models_[static_cast<size_t>(m)];
    const bool stand_in = meshes_[static_cast<size_t>(m)] && meshes_[static_cast<size_t>(m)]->stand_in;
    const GpuTexture *image = nullptr;
    const uint32_t features = features_of(m, selected, without, &image);
    const LinkedProgram &program = programs_->get(features);
    stats_.features_used |= features;
    if (&program != current_program_) {
        glUseProgram(program.shader->name());
        ++stats_.program_binds;
        current_program_ = &program;
    }
    if (features & ANI_SHADE_TEXTURE)
        bind(kTextureUnit, GL_TEXTURE_2D, image->name(), stats_.texture_binds);
    if (features & (ANI_SHADE_REFLECTION | ANI_SHADE_REFRACTION)) {
        if (!skybox_ && !background_cube_)
            background_cube_ = GpuTexture::solid_cube_map(options_.background);
        // Its own view of the models around it, where it has one (not inside another's).
        const unsigned around = probing_ < 0 ? probes_.texture(m) : 0;
        const unsigned environment =
            around ? around : skybox_ ? skybox_->name() : background_cube_->name();
        bind(kSkyboxUnit, GL_TEXTURE_CUBE_MAP, environment, stats_.cube_map_binds);
    }
    const glm::dmat4 &world = world_[static_cast<size_t>(m)];
    ModelUniforms &u = model_uniforms_;
    u.model = glm::mat4(world);
    u.normal_matrix = glm::mat3(glm::transpose(glm::inverse(glm::dmat3(world))));
    u.kd = glm::vec3(model.material.kd);
    u.ks = glm::vec3(model.material.ks);
    u.shininess = static_cast<float>(model.material.shininess);
    u.tint = static_cast<float>(model.tint);
    u.reflectivity = static_cast<float>(model.reflectivity);
    u.transparency = static_cast<float>(model.transparency);
    u.refractive_index = static_cast<float>(model.refractive_index);
    u.selected = selected;
    if (stand_in) {
        u.kd = glm::vec3(1.0f, 0.0f, 1.0f);
        u.ks = glm::vec3(0.0f);
        u.tint = u.reflectivity = u.transparency = 0.0f;
    }
    apply_uniforms(program, *programs_, frame_uniforms_, &u);
    const GpuMesh &mesh = *gpu_meshes_[static_cast<size_t>(m)];
    // (Transparent models in the view are drawn from outside only: draw_transparent culls.)
    if (model.transparency <= 0.0 || probing_ >= 0) {
        // A closed mesh seen from outside itself: its back faces are hidden behind its front
        // ones and are not drawn. Seen from within, or open (a floor is seen from below), both
        // sides.
        if (closed_seen_from_outside(m, eye_)) {
            glEnable(GL_CULL_FACE);
            ++stats_.one_sided;
        } else {
            glDisable(GL_CULL_FACE);
        }
    }
    mesh.draw(counted_level(m));
}

void Renderer::draw_transparent(int m, bool selected) {
    const float transparency = static_cast<float>(models_[static_cast<size_t>(m)].transparency);
    // Where a model is behind (stencil 1), it shows through: this one's colour without the
    // skybox's refraction, blended as colour * (1 - transparency) + behind * transparency.
    glEnable(GL_BLEND);
    glBlendColor(0.0f, 0.0f, 0.0f, transparency);
    glBlendFunc(GL_ONE_MINUS_CONSTANT_ALPHA, GL_CONSTANT_ALPHA);
    glStencilFunc(GL_EQUAL, 1, 0xFF);
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    draw_model(m, selected, ANI_SHADE_REFRACTION);
    // Where only the skybox is behind (stencil 0): the seed's refraction mapping, opaque, and
    // marked so that nearer transparent models see this one behind them.
    glDisable(GL_BLEND);
    glStencilFunc(GL_EQUAL, 0, 0xFF);
    glStencilOp(GL_KEEP, GL_KEEP, GL_INCR);
    draw_model(m, selected, 0);
}

void Renderer::draw_reflections() {
    std::vector<std::pair<double, int>> &wanted = reflecting_; // (distance to the camera, model)
    wanted.clear();
    const int count = static_cast<int>(std::min(models_.size(), world_.size()));
    const glm::dvec3 eye(frame_uniforms_.camera_position);
    if (options_.reflection_size > 0)
        for (int m = 0; m < count; ++m) {
            const Model &model = models_[static_cast<size_t>(m)];
            if (!gpu_meshes_[static_cast<size_t>(m)] || meshes_[static_cast<size_t>(m)]->stand_in ||
                (model.reflectivity <= 0.0 && model.transparency <= 0.0) || !visible(m))
                continue;
            wanted.emplace_back(glm::length(glm::dvec3(world_[static_cast<size_t>(m)][3]) - eye), m);
        }
    std::sort(wanted.begin(), wanted.end());
    const auto most = static_cast<std::size_t>(std::max(options_.reflection_models, 0));
    if (wanted.size() > most) {
        if (!told_reflection_limit_)
            log_(std::to_string(wanted.size()) + " models reflect or refract: the " +
                 std::to_string(most) +
                 " nearest the camera show the models around them, the others the skybox only");
        told_reflection_limit_ = true;
        wanted.resize(most);
    }
    probes_.keep_only([&](int m) {
        return std::any_of(wanted.begin(), wanted.end(), [&](const auto &w) { return w.second == m; });
    });
    if (wanted.empty()) return;
    // Every model, grouped by program as in the view (draw()), for the cube maps' faces.
    by_program_.clear();
    for (int o = 0; o < count; ++o)
        if (gpu_meshes_[static_cast<size_t>(o)]) by_program_.emplace_back(features_of(o, false, 0, nullptr), o);
    group_by_program(by_program_);
    // The frame as the camera sees it, put back after.
    const FrameUniforms camera = frame_uniforms_;
    const glm::dvec3 camera_eye = eye_;
    const glm::dmat4 view = view_, view_projection = view_projection_;
    const Frustum frustum = frustum_;
    // The skybox's level as large as a cube map's faces, when it has one and it can be copied:
    // then it is copied into each cube map and not drawn into its faces (the same pixels).
    std::optional<ReflectionProbes::Sky> sky;
    if (skybox_ && options_.reflection_size > 0 && ReflectionProbes::copies_sky())
        for (int level = 0; (skybox_size_ >> level) >= options_.reflection_size; ++level)
            if (skybox_size_ == options_.reflection_size << level) sky = {skybox_->name(), level};
    for (const auto &[distance, m] : wanted) {
        glm::dvec3 centre;
        double radius = 0.0;
        bounds_of(m, centre, radius);
        // What it holds (a glass box's balls) is seen through it where it is in front of them,
        // not as its surroundings: only the models whose centres lie outside it are drawn.
        const auto around = [&](int o) {
            glm::dvec3 c;
            double r = 0.0;
            bounds_of(o, c, r);
            return glm::length(c - centre) >= radius;
        };
        // Over a copied sky, the faces that see any of them (the others are left as they are);
        // every face where the sky is drawn.
        unsigned faces = 0x3f;
        if (sky) {
            faces = 0;
            for (int f = 0; f < 6; ++f) {
                frustum_ = Frustum(ReflectionProbes::face_view_projection(f, centre));
                for (const auto &[features, o] : by_program_)
                    if (o != m && visible(o) && around(o)) {
                        faces |= 1u << f;
                        break;
                    }
            }
        }
        // The models around it at the levels its faces see them at (as the view's, but from its
        // centre at the faces' pixels), never finer than the view's: what its shadow maps were
        // drawn with.
        probe_levels_.assign(levels_.begin(), levels_.end());
        for (const auto &[features, o] : by_program_) {
            if (o == m || settings_.cel_shading) continue;
            const std::vector<LodLevel> &chain = gpu_meshes_[static_cast<size_t>(o)]->levels();
            const std::size_t seen = level_of(o, centre, 2.0 / options_.reflection_size);
            if (chain[seen].count < chain[levels_[static_cast<size_t>(o)]].count)
                probe_levels_[static_cast<size_t>(o)] = seen;
        }
        std::swap(levels_, probe_levels_); // (probe_levels_ holds the view's until swapped back)
        probing_ = m;
        probes_.draw(m, options_.reflection_size, centre, options_.background,
                     sky ? &*sky : nullptr, faces,
                     [&](const glm::dmat4 &face_view, const glm::dmat4 &projection) {
                         ++stats_.reflection_faces;
                         frame_uniforms_.view = glm::mat4(face_view);
                         frame_uniforms_.projection = glm::mat4(projection);
                         frame_uniforms_.camera_position = glm::vec3(centre);
                         eye_ = centre;
                         view_ = face_view;
                         view_projection_ = projection * face_view;
                         frustum_ = Frustum(view_projection_);
                         glEnable(GL_DEPTH_TEST);
                         glDepthFunc(GL_LESS);
                         for (const auto &[features, o] : by_program_)
                             if (o != m && visible(o) && around(o)) {
                                 widen_shadow_offset(o, probe_levels_[static_cast<size_t>(o)],
                                                     camera.shadow_texel);
                                 draw_model(o, false, 0);
                             }
                         frame_uniforms_.shadow_texel = camera.shadow_texel;
                         if (skybox_ && !sky) draw_skybox(options_.reflection_size, false);
                     });
        std::swap(levels_, probe_levels_);
        ++stats_.reflection_maps;
        if (sky) ++stats_.skies_copied;
    }
    probes_.finish();
    probing_ = -1;
    eye_ = camera_eye;
    frame_uniforms_ = camera;
    view_ = view;
    view_projection_ = view_projection;
    frustum_ = frustum;
}

void Renderer::widen_shadow_offset(int model, std::size_t shadowed_level,
                                   const std::array<float, kMaxShadowSemantics> &texel) {
    frame_uniforms_.shadow_texel = texel;
    const std::size_t level = levels_[static_cast<size_t>(model)];
    if (level == shadowed_level) return;
    // Its surface here strays from the one its shadow maps hold by at most the two levels'
    // errors (each from the mesh's own surface), in world units with its largest stretch; a
    // lit point as far inside would read its own shadow. The shading pushes a point 1.5 texel
    // widths (texel * d at distance d from the light) along its normal before the lookup
    // (shading.phong, docs/sdk.md): that push grows by the straying, at the model's nearest
    // distance from each light, where the push is least.
    const std::vector<LodLevel> &levels = gpu_meshes_[static_cast<size_t>(model)]->levels();
    const double strays = (levels[level].error + levels[shadowed_level].error) * stretch_of(model);
    glm::dvec3 centre;
    double radius = 0.0;
    bounds_of(model, centre, radius);
    for (int i = 0; i < frame_uniforms_.shadow_lights; ++i) {
        const double nearest = std::max(
            glm::length(glm::dvec3(frame_uniforms_.light_position[static_cast<size_t>(i)]) -
                        centre) -
                radius,
            options_.near_plane);
        frame_uniforms_.shadow_texel[static_cast<size_t>(i)] +=
            static_cast<float>(strays / (1.5 * nearest));
    }
}

void Renderer::draw(const Frame &frame, const RenderTarget &target, const std::set<int> &selected,
                    const std::set<int> &flagged) {
    stats_ = RenderStats{};
    bound_[0] = bound_[1] = 0;
    const int count = static_cast<int>(std::min(models_.size(), frame.models.size()));
    prepare_frame(frame, target.width, target.height);
    draw_shadow_maps(count);
    current_program_ = nullptr;
    // (Shadows fall in the models' cube maps too.)
    if (frame_uniforms_.shadow_lights > 0) shadows_->bind(frame_uniforms_.shadow_lights);
    draw_reflections();
    glBindFramebuffer(GL_FRAMEBUFFER, target.framebuffer);
    glViewport(target.x, target.y, target.width, target.height);
    glEnable(GL_SCISSOR_TEST); // the clear keeps to the viewport
    glScissor(target.x, target.y, target.width, target.height);
    glDisable(GL_BLEND);
    glDisable(GL_CULL_FACE); // open meshes (a floor) are seen from both sides (draw_model)
    glDepthMask(GL_TRUE);
    glStencilMask(0xFF);
    glClearColor(options_.background.r, options_.background.g, options_.background.b, 1.0f);
    glClearStencil(0);
    // With a skybox every pixel is written (a model's or the sky's, drawn where no model is): the
    // colour is not cleared first (a whole buffer's writes, four samples a pixel with
    // anti-aliasing).
    glClear((skybox_ ? 0 : GL_COLOR_BUFFER_BIT) | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    glDisable(GL_SCISSOR_TEST);

    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    // Opaque models mark the stencil: what a transparent model drawn later has behind it.
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_ALWAYS, 1, 0xFF);
    glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
    transparent_.clear();
    by_program_.clear();
    for (int m = 0; m < count; ++m) {
        if (!gpu_meshes_[static_cast<size_t>(m)] || hidden_.count(m)) continue;
        if (!visible(m)) {
            ++stats_.models_culled;
            continue;
        }
        ++stats_.models_drawn;
        if (models_[static_cast<size_t>(m)].transparency > 0.0) {
            const double depth = (view_ * world_[static_cast<size_t>(m)][3]).z;
            transparent_.emplace_back(depth, m);
            continue;
        }
        by_program_.emplace_back(features_of(m, selected.count(m) > 0, 0, nullptr), m);
    }
    // Grouped by program, so each program is bound about once: a program switch costs llvmpipe
    // more than the draw of a small model (docs/performance.md); closed meshes before open ones
    // (a floor is mostly behind what stands on it) and the nearest first in a group, so that the
    // depth test, which llvmpipe runs before the shader (at one sample a pixel), leaves hidden
    // pixels unshaded. The depth test makes the order invisible (but where two models' surfaces
    // coincide).
    order_front_to_back(by_program_);
    // The skybox behind the opaque models, only where none is (draw_skybox). With anti-aliasing,
    // llvmpipe shades every pixel of each 4x4 block a triangle touches before its samples' depth
    // test decides (docs/performance.md): drawn after the models the sky would be shaded behind
    // them just the same, and its depth test paid at every sample; so then it is drawn first,
    // without the test.
    GLint samples = 0;
    glGetIntegerv(GL_SAMPLES, &samples);
    const bool sky_first = skybox_ && samples > 1;
    if (sky_first) draw_skybox(target.height, true);
    for (const auto &[features, m] : by_program_) draw_model(m, selected.count(m) > 0, 0);
    if (skybox_ && !sky_first) draw_skybox(target.height, false);
    // Transparent models last, the farthest first, each seen from outside only.
    std::sort(transparent_.begin(), transparent_.end());
    glEnable(GL_CULL_FACE);
    for (const auto &[depth, m] : transparent_) draw_transparent(m, selected.count(m) > 0);
    glDisable(GL_CULL_FACE);
    if (options_.selection_outline && (!selected.empty() || !flagged.empty()))
        draw_outlines(selected, flagged, target.width, target.height);
    glDisable(GL_STENCIL_TEST);
    glDisable(GL_BLEND);
    glBindVertexArray(0);
    glUseProgram(0);
    glActiveTexture(GL_TEXTURE0);
}

void Renderer::draw_shadow_maps(int count) {
    FrameUniforms &u = frame_uniforms_;
    u.shadow_lights = 0;
    if (!options_.shadows) return;
    // The scene's bounds: a sphere around every drawn model's (transparent ones too, which
    // receive shadows; they cast none, as glass would hardly).
    glm::dvec3 low(std::numeric_limits<double>::max()), high(-std::numeric_limits<double>::max());
    bool any = false;
    for (int m = 0; m < count; ++m) {
        if (!gpu_meshes_[static_cast<size_t>(m)] || hidden_.count(m)) continue;
        glm::dvec3 c;
        double r = 0.0;
        bounds_of(m, c, r);
        low = glm::min(low, c - r);
        high = glm::max(high, c + r);
        any = true;
    }
    if (!any) return;
    const glm::dvec3 centre = (low + high) * 0.5;
    double radius = 1e-6;
    for (int m = 0; m < count; ++m) {
        if (!gpu_meshes_[static_cast<size_t>(m)] || hidden_.count(m)) continue;
        glm::dvec3 c;
        double r = 0.0;
        bounds_of(m, c, r);
        radius = std::max(radius, glm::length(c - centre) + r);
    }
    if (!shadows_) shadows_ = std::make_unique<ShadowPass>();
    const int lights = std::min(u.light_count, kMaxShadowLights);
    for (int i = 0; i < lights; ++i) {
        const ShadowProjection p =
            shadow_projection(glm::dvec3(u.light_position[static_cast<size_t>(i)]), centre, radius,
                              options_.shadow_map_size);
        shadows_->begin(i, options_.shadow_map_size, p);
        const glm::dvec3 light(u.light_position[static_cast<size_t>(i)]);
        for (int m = 0; m < count; ++m) {
            if (!gpu_meshes_[static_cast<size_t>(m)] || hidden_.count(m) ||
                models_[static_cast<size_t>(m)].transparency > 0.0)
                continue;
            const bool one_sided = closed_seen_from_outside(m, light);
            shadows_->draw(*gpu_meshes_[static_cast<size_t>(m)],
                           glm::mat4(world_[static_cast<size_t>(m)]), counted_level(m), one_sided);
            ++stats_.shadow_casters;
            if (one_sided) ++stats_.shadow_one_sided;
        }
        shadows_->finish();
        u.shadow_matrix[static_cast<size_t>(i)] = glm::mat4(p.world_to_map);
        u.shadow_texel[static_cast<size_t>(i)] = static_cast<float>(p.texel_per_distance);
    }
    u.shadow_lights = lights;
    stats_.shadow_maps = lights;
}

void Renderer::draw_outlines(const std::set<int> &selected, const std::set<int> &flagged, int width, int height) {
    if (!outline_) outline_ = std::make_unique<SelectionOutline>();
    current_program_ = nullptr; // the outline binds its own program
    const int count = static_cast<int>(std::min(models_.size(), world_.size()));
    // Each at the level of detail it was drawn with, so its ring meets its silhouette.
    auto each = [&](const std::set<int> &models, auto &&draw) {
        for (int m : models)
            if (m >= 0 && m < count && gpu_meshes_[static_cast<size_t>(m)] && visible(m))
                draw(*gpu_meshes_[static_cast<size_t>(m)], glm::mat4(world_[static_cast<size_t>(m)]),
                     levels_[static_cast<size_t>(m)]);
    };
    outline_->begin(glm::mat4(view_projection_), width, height);
    // Every selected silhouette first, so one selected model's ring never covers another. The
    // wider flagged rings next, each keeping off its own silhouette only (a flagged cube on a
    // flagged or selected floor is ringed over the floor), then the selection's over them.
    each(selected, [&](const GpuMesh &mesh, const glm::mat4 &world, std::size_t level) {
        outline_->mark(mesh, world, level);
    });
    each(flagged, [&](const GpuMesh &mesh, const glm::mat4 &world, std::size_t level) {
        outline_->outline_alone(mesh, world, level, options_.flagged_style);
    });
    each(selected, [&](const GpuMesh &mesh, const glm::mat4 &world, std::size_t level) {
        outline_->outline(mesh, world, level, options_.outline_style);
    });
    outline_->end();
}

void Renderer::draw_paths(const std::vector<PathLines> &paths, const RenderTarget &target, const PathStyle &style) {
    if (paths.empty()) return;
    if (!paths_) paths_ = std::make_unique<MotionPathOverlay>();
    glBindFramebuffer(GL_FRAMEBUFFER, target.framebuffer);
    glViewport(target.x, target.y, target.width, target.height);
    current_program_ = nullptr; // the overlay binds its own program
    paths_->draw(paths, glm::mat4(view_projection_), style);
}

int Renderer::pick(const Frame &frame, int width, int height, int x, int y) {
    if (!picking_) picking_ = std::make_unique<PickingPass>();
    prepare_frame(frame, width, height);
    if (!picking_->begin(width, height, x, y, glm::mat4(view_projection_))) return -1;
    const int count = static_cast<int>(std::min(models_.size(), frame.models.size()));
    for (int m = 0; m < count; ++m) {
        const GpuMesh *mesh = gpu_meshes_[static_cast<size_t>(m)];
        if (mesh && visible(m))
            picking_->draw(*mesh, glm::mat4(world_[static_cast<size_t>(m)]), levels_[static_cast<size_t>(m)],
                           static_cast<std::uint32_t>(m) + 1);
    }
    const std::uint32_t id = picking_->finish();
    return id == 0 ? -1 : static_cast<int>(id) - 1;
}

} // namespace animator
