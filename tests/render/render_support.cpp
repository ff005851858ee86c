#include "render_support.hpp"

#include "render/framebuffer.hpp"

#include <glm/gtc/quaternion.hpp>

#include <map>

namespace animator::test {

OffscreenContext &gl_context() {
    static OffscreenContext context;
    return context;
}

Environment &environment() {
    static Environment env;
    return env;
}

Model make_model(const std::string &name, const std::string &mesh, const glm::dvec3 &kd,
                 const glm::dvec3 &ks, double shininess) {
    Model m;
    m.name = name;
    m.mesh = mesh;
    m.material.kd = kd;
    m.material.ks = ks;
    m.material.shininess = shininess;
    return m;
}

ModelState make_state(const glm::dvec3 &center, const glm::dvec3 &scale, const glm::dvec3 &angles) {
    ModelState s;
    s.center = center;
    s.scale = scale;
    s.angles = angles;
    return s;
}

CameraState make_camera(const glm::dvec3 &position, double yaw_degrees, double pitch_degrees,
                        double fov_degrees) {
    CameraState c;
    c.position = position;
    c.rotation = glm::angleAxis(glm::radians(yaw_degrees), glm::dvec3(0, 1, 0)) *
                 glm::angleAxis(glm::radians(pitch_degrees), glm::dvec3(1, 0, 0));
    c.fov_degrees = fov_degrees;
    return c;
}

Document make_document(const CameraState &camera, bool cel_shading, const std::string &skybox) {
    Document doc;
    Settings s = doc.settings();
    s.cel_shading = cel_shading;
    s.skybox = skybox;
    doc.set_settings(s);
    doc.set_camera(0, camera);
    return doc;
}

std::vector<std::shared_ptr<const Mesh>> meshes_of(const Document &doc) {
    static std::map<std::string, std::shared_ptr<const Mesh>> loaded;
    std::vector<std::shared_ptr<const Mesh>> out;
    for (const Model &m : doc.models()) {
        if (m.mesh.empty()) {
            out.push_back(nullptr);
            continue;
        }
        auto &slot = loaded[m.mesh];
        if (!slot) {
            const auto file = environment().assets.resolve(ANI_ASSET_MESH, m.mesh);
            if (!file) throw std::runtime_error("no mesh '" + m.mesh + "' in the test assets");
            slot = std::make_shared<const Mesh>(load_mesh(*file).mesh);
        }
        out.push_back(slot);
    }
    return out;
}

Frame first_frame(const Document &doc) {
    Frame frame;
    const Keyframe &k = doc.keyframes().front();
    for (const auto &state : k.states) {
        ModelPose pose;
        pose.center = state->center;
        pose.angles = state->angles;
        pose.scale = state->scale;
        frame.models.push_back(pose);
        frame.motion.push_back(ANI_MOTION_KEYED);
    }
    frame.camera = *k.camera;
    return frame;
}

Rendered render_frame(const Document &doc, const Frame &frame, int width, int height,
                      const std::set<int> &selected, RenderOptions options,
                      const std::set<int> &flagged, int samples) {
    gl_context();
    Rendered out;
    Renderer renderer(environment().plugins, environment().assets, std::move(options),
                      [&](const std::string &m) { out.log.push_back(m); });
    renderer.set_document(doc, meshes_of(doc));
    OffscreenFramebuffer framebuffer(width, height, samples);
    renderer.draw(frame, framebuffer.target(), selected, flagged);
    out.stats = renderer.stats();
    out.samples = framebuffer.actual_samples();
    out.image.width = width;
    out.image.height = height;
    framebuffer.read_rgb(out.image.rgb);
    return out;
}

Rendered render_document(const Document &doc, int width, int height, const std::set<int> &selected,
                         RenderOptions options, const std::set<int> &flagged, int samples) {
    return render_frame(doc, first_frame(doc), width, height, selected, std::move(options), flagged,
                        samples);
}

glm::ivec3 pixel(const Image &image, int x, int y) {
    const size_t at =
        (static_cast<size_t>(y) * static_cast<size_t>(image.width) + static_cast<size_t>(x)) * 3;
    return {image.rgb[at], image.rgb[at + 1], image.rgb[at + 2]};
}

} // namespace animator::test
