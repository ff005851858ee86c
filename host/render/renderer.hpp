// The renderer: draws a frame of the timeline (every model's pose and the camera) with the
// shading plugin's programs into any framebuffer, a window's or an off-screen one. Meshes are
// uploaded once, textures and skyboxes loaded once by id; each draw asks for the program of
// exactly the features a model uses, binds a texture or a cube map only when one is used, and
// skips models outside the view (frustum culling). For the editor it also answers which model
// is under a pixel and tints selected models yellow (seed, "Transforming the Camera and Model").
//
// Transparent models follow the seed (the skybox, refracted, blended by transparency) where only
// the skybox is behind them, and beyond the seed let the models behind them show through: they
// are drawn after the opaque ones, farthest first, and the stencil buffer says which pixels have
// a model behind. A target without a stencil buffer gets the seed's look only.
//
// Reflective and transparent models see the models around them (the seed's "Reflecting Other
// Models"): each has a cube map drawn from its centre every frame (reflection_probes.hpp), in
// which the other models reflect and refract the skybox only (one bounce).
//
// A far model is drawn with a coarser level of detail of its mesh (mesh_lod.hpp), one level a
// model a frame, as the camera sees it, in every pass.
#pragma once

#include "assets/asset_paths.hpp"
#include "assets/mesh.hpp"
#include "document/document.hpp"
#include "render/framebuffer.hpp"
#include "render/frustum.hpp"
#include "render/gpu_mesh.hpp"
#include "render/gpu_texture.hpp"
#include "render/motion_path_overlay.hpp"
#include "render/picking_pass.hpp"
#include "render/reflection_probes.hpp"
#include "render/selection_outline.hpp"
#include "render/shading_programs.hpp"
#include "render/shadow_pass.hpp"
#include "render/uniform_values.hpp"
#include "timeline/timeline.hpp"

#include <glm/mat4x4.hpp>

#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace animator {

struct RenderOptions {
    std::string shading = "shading.phong"; // the shading plugin; "" draws with the built-in Phong
    glm::vec3 background{0.16f, 0.17f, 0.20f}; // behind everything when there is no skybox
    // A document without lights is lit by one riding with the camera, above, left of and behind
    // it in camera space, so a scene is lit wherever the camera looks (the seed's had one fixed
    // light). A document's lights replace it; the ambient light is always the document's.
    glm::vec3 light_offset{Settings::kCameraLightOffset};
    glm::vec3 light_colour{1.0f};
    glm::vec4 selected_tint{1.0f, 0.9f, 0.0f, 0.6f}; // yellow, and how much of it
    // A ring around each selected model that reads on any colour (selection_outline.hpp).
    bool selection_outline = true;
    OutlineStyle outline_style;
    // A wider ring around each flagged model (the editor flags models found overlapping): red,
    // edged in white; a flagged model that is also selected shows both rings.
    OutlineStyle flagged_style{{0.95f, 0.1f, 0.1f}, {1.0f, 1.0f, 1.0f}, 7.0f, 9.0f};
    double near_plane = 0.1, far_plane = 1000.0;
    // Reflections of other models (reflection_probes.hpp): the side in pixels of the cube map
    // each reflective or transparent model sees the others in, drawn every frame; 0 turns them
    // off (such models then show the skybox only, as the seed's did).
    int reflection_size = 128;
    // At most this many such models get one in a frame, the nearest the camera first; the
    // others show the skybox only (said once in the log).
    int reflection_models = 8;
    // Shadows from the first kMaxShadowLights lights (the document's, or the camera's), each a
    // shadow map of shadow_map_size texels square (shadow_pass.hpp).
    bool shadows = true;
    int shadow_map_size = 1024;
    // Levels of detail (mesh_lod.hpp): each model is drawn with the coarsest level of its mesh
    // whose surface strays at most this many pixels (or shadow-map texels) from the mesh's where
    // it is seen; 0 draws every mesh whole.
    double detail_pixels = 0.5;
    // Mirrors and glass at levels of detail too (by default they keep their whole meshes: what
    // they show turns with their normals, which a coarser level bends by more than its outline
    // moves). The editor's frame budget sets it while playing (editor/frame_budget.hpp).
    bool mirror_levels = false;
};

// What the last draw did, counted: the observable seam for tests (and a debug overlay) that a
// scene pays only for what it uses.
struct RenderStats {
    std::size_t models_drawn = 0;
    std::size_t models_culled = 0;
    std::size_t program_binds = 0;
    std::size_t texture_binds = 0;  // 2D textures bound
    std::size_t cube_map_binds = 0; // skybox cube maps bound (the skybox, or reflection's)
    int shadow_maps = 0;            // shadow maps drawn (one a shadow-casting light)
    std::size_t shadow_casters = 0; // models drawn into them, summed over the maps
    std::size_t shadow_one_sided = 0; // of those, drawn one-sided (closed, the light outside)
    bool skybox_drawn = false;
    std::size_t reflection_maps = 0; // cube maps of the models around drawn (six faces each)
    std::size_t skies_copied = 0;    // of those, with the skybox copied in, not drawn
    std::size_t reflection_faces = 0; // their faces drawn (those that see nothing keep the sky)
    // Triangles of models drawn, summed over every pass (shadow maps, cube maps, the view), and
    // how many of them levels of detail left out.
    std::size_t triangles = 0;
    std::size_t triangles_saved = 0;
    // Opaque models drawn one-sided (closed meshes seen from outside: back faces not drawn),
    // summed over every pass.
    std::size_t one_sided = 0;
    std::uint32_t features_used = 0; // the union of the feature sets asked of the shading plugin
};

class Renderer {
  public:
    using LogSink = ShadingPrograms::LogSink;

    // Needs a current OpenGL 3.3 core context, with glad loaded, for its whole life. Throws
    // PluginError when options.shading names no shading plugin. `log` gets warnings (a texture
    // that cannot be loaded, a shader that does not compile); the default writes to stderr.
    Renderer(PluginRegistry &plugins, const AssetPaths &assets, RenderOptions options = {},
             LogSink log = {});
    ~Renderer();
    Renderer(const Renderer &) = delete;
    Renderer &operator=(const Renderer &) = delete;

    // The models, their materials and the settings to draw with. `meshes` has one per model
    // (null for an empty or a missing mesh); each is uploaded once, and `document` is the file
    // the document came from, or empty. Sets the shading plugin's parameters to the document's
    // saved values (the others to their defaults); throws PluginError for a value it refuses.
    void set_document(const Document &doc, const std::vector<std::shared_ptr<const Mesh>> &meshes);

    // Draws `frame` into `target` (cleared first). `selected` and `flagged` hold model indices.
    void draw(const Frame &frame, const RenderTarget &target, const std::set<int> &selected = {},
              const std::set<int> &flagged = {});

    // Motion paths over the frame draw() drew last, into the same target (motion_path_overlay.hpp).
    void draw_paths(const std::vector<PathLines> &paths, const RenderTarget &target, const PathStyle &style = {});

    // The model drawn at pixel (x, y), from the top left of a target of this size, or -1.
    int pick(const Frame &frame, int width, int height, int x, int y);

    // Models that draw() and pick() leave out until said otherwise (the editor's hidden ones):
    // not drawn, outlined, ringed nor picked.
    void set_hidden(std::set<int> hidden) { hidden_ = std::move(hidden); }

    const RenderStats &stats() const { return stats_; }
    ShadingPrograms &programs() { return *programs_; }
    const RenderOptions &options() const { return options_; }
    // Shadows on or off, and the size of their maps (the editor's View menu, a fallback when a
    // frame takes too long), from the next draw on.
    // The side of the models' cube maps of the models around them (0: the skybox only).
    void set_reflections(int size) { options_.reflection_size = size; }
    void set_detail(double pixels, bool mirrors) {
        options_.detail_pixels = pixels;
        options_.mirror_levels = mirrors;
    }
    void set_shadows(bool on, int map_size) {
        options_.shadows = on;
        options_.shadow_map_size = map_size;
    }

  private:
    void prepare_frame(const Frame &frame, int width, int height);
    // Model m's bounding sphere in the world: its mesh's, under its world matrix.
    void bounds_of(int model, glm::dvec3 &centre, double &radius) const;
    bool visible(int model) const;
    // Model m's mesh is closed and `from` (an eye, a light) is outside its bounding sphere, so
    // outside the mesh: its faces turned away from `from` are behind its others and need not be
    // drawn.
    bool closed_seen_from_outside(int model, const glm::dvec3 &from) const;
    // The level of detail of model m's mesh (RenderOptions::detail_pixels) seen from `eye`, whose
    // pixels are `pixel_per_distance` wide at distance 1.
    std::size_t level_of(int model, const glm::dvec3 &eye, double pixel_per_distance) const;
    // Sets the shadow maps' texel widths (`texel`, the frame's) for drawing model `model` at its
    // level (levels_) where its shadow maps hold it at `shadowed_level`: widened so that the
    // shading's normal offset covers how far the two surfaces may part.
    void widen_shadow_offset(int model, std::size_t shadowed_level,
                             const std::array<float, kMaxShadowSemantics> &texel);
    // The largest factor by which model m's world matrix stretches a length.
    double stretch_of(int model) const;
    // Model m's level this frame (levels_), its triangles counted in the stats.
    std::size_t counted_level(int model);
    const GpuTexture *texture(const std::string &id);
    void load_skybox(const std::string &id);
    // The skybox behind what is drawn, into a viewport `pixels_high` pixels high: after the opaque
    // models where none is (the depth test), or `first`, before them, everywhere.
    void draw_skybox(int pixels_high, bool first);
    // The view's opaque draws (by_program_) in the order they are drawn.
    void order_front_to_back(std::vector<std::pair<std::uint32_t, int>> &draws) const;
    // The features model m is drawn with, less `without` (and its texture, when `image`).
    uint32_t features_of(int m, bool selected, uint32_t without, const GpuTexture **image);
    // Draws model m with the features it uses, less `without`.
    void draw_model(int m, bool selected, uint32_t without);
    void draw_transparent(int m, bool selected);
    // Each reflective or transparent model's view of the others, drawn into its cube map.
    void draw_reflections();
    void bind(unsigned unit, unsigned target, unsigned name, std::size_t &counter);
    // The shadow maps of the frame prepare_frame() set up, for its first `count` models.
    void draw_shadow_maps(int count);

    const AssetPaths &assets_;
    RenderOptions options_;
    LogSink log_;
    std::unique_ptr<ShadingPrograms> programs_;

    std::vector<Model> models_;
    Settings settings_;
    std::vector<std::shared_ptr<const Mesh>> meshes_; // per model
    std::vector<const GpuMesh *> gpu_meshes_;         // per model, null without a mesh
    std::map<const Mesh *, std::unique_ptr<GpuMesh>> uploaded_;
    std::map<std::string, std::optional<GpuTexture>> textures_; // by id; empty when unloadable
    std::string skybox_id_;
    std::optional<GpuTexture> skybox_;
    int skybox_size_ = 0;       // its faces' side in texels
    unsigned sky_sampler_ = 0; // the skybox pass's (draw_skybox), made on its first draw
    std::optional<GpuTexture> background_cube_; // reflection and refraction without a skybox
    std::unique_ptr<GpuMesh> skybox_cube_;
    std::unique_ptr<PickingPass> picking_;
    std::unique_ptr<ShadowPass> shadows_;
    std::unique_ptr<SelectionOutline> outline_;
    std::unique_ptr<MotionPathOverlay> paths_;
    std::set<int> hidden_;
    ReflectionProbes probes_;
    int probing_ = -1; // the model whose cube map is being drawn, or -1
    bool told_reflection_limit_ = false;
    void draw_outlines(const std::set<int> &selected, const std::set<int> &flagged, int width, int height);

    // Per frame, kept to reuse their storage.
    std::vector<glm::dmat4> world_;
    glm::dmat4 view_{1.0}, view_projection_{1.0};
    Frustum frustum_{glm::dmat4(1.0)};
    // Per model, its level of detail in the pass being drawn: the view's (and its shadow maps'),
    // or while a cube map is drawn the cube map's, which may be coarser (draw_reflections()).
    std::vector<std::size_t> levels_;
    // While a cube map is drawn, the view's levels (swapped with levels_).
    std::vector<std::size_t> probe_levels_;
    glm::dvec3 eye_{0.0};             // where the pass being drawn is seen from
    FrameUniforms frame_uniforms_;
    ModelUniforms model_uniforms_;
    unsigned bound_[2] = {0, 0}; // the texture names bound on the two units this frame
    const LinkedProgram *current_program_ = nullptr;
    std::vector<std::pair<double, int>> transparent_; // (view-space z, model): far ones first
    std::vector<std::pair<std::uint32_t, int>> by_program_; // (features, model): the draw order
    std::vector<std::pair<double, int>> reflecting_;  // (distance to the camera, model): nearest first
    RenderStats stats_;
};

} // namespace animator
