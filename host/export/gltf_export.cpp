#include "export/gltf_export.hpp"

#include "assets/image.hpp"

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_inverse.hpp>

#include <stb_image_write.h>
#include <tiny_gltf.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <iterator>
#include <limits>
#include <map>
#include <tuple>
#include <string>

namespace animator {

namespace {

using tinygltf::Value;

constexpr double kNearPlane = 0.1, kFarPlane = 1000.0; // the renderer's (render/renderer.hpp)

std::vector<double> to_vector(const glm::dvec3 &v) {
    return {v.x, v.y, v.z};
}
std::vector<double> to_vector(const glm::dquat &q) {
    return {q.x, q.y, q.z, q.w};
} // glTF: x y z w

bool has_extension(const tinygltf::Model &model, const std::string &name) {
    return std::find(model.extensionsUsed.begin(), model.extensionsUsed.end(), name) !=
           model.extensionsUsed.end();
}

class GltfBuilder {
  public:
    GltfBuilder(const Timeline &timeline, const std::vector<std::shared_ptr<const Mesh>> &meshes,
                const AssetPaths &assets, const std::filesystem::path &document,
                const MotionKeyOptions &options)
        : timeline_(timeline), doc_(timeline.document()), meshes_(meshes), assets_(assets),
          document_(document), options_(options) {
        model_.asset.version = "2.0";
        model_.asset.generator = "animator";
        model_.buffers.emplace_back();
        model_.defaultScene = 0;
        model_.scenes.emplace_back();
        model_.scenes[0].name = document.stem().string();
    }

    GltfExportReport build() {
        const MotionKeys keys = motion_keys_of(timeline_, options_);
        report_.pieces = keys.stats;
        const auto &models = doc_.models();
        model_nodes_.assign(models.size(), -1);
        std::vector<int> roots;
        for (size_t m = 0; m < models.size(); ++m) {
            const int node = model_node(static_cast<int>(m), keys.models[m]);
            const int parent = models[m].parent;
            if (parent >= 0 && static_cast<size_t>(parent) < m)
                model_.nodes[static_cast<size_t>(model_nodes_[static_cast<size_t>(parent)])]
                    .children.push_back(node);
            else
                roots.push_back(node);
        }
        roots.push_back(camera_node(keys.camera));
        for (int light : light_nodes()) roots.push_back(light);
        scene_settings();
        model_.scenes[0].nodes = world_root(roots);
        report_.nodes = model_.nodes.size();
        return report_;
    }

    const tinygltf::Model &model() const { return model_; }

  private:
    void note(const std::string &message) {
        if (std::find(report_.notes.begin(), report_.notes.end(), message) == report_.notes.end())
            report_.notes.push_back(message);
    }

    void use_extension(const std::string &name) {
        if (!has_extension(model_, name)) model_.extensionsUsed.push_back(name);
    }

    // Bytes appended to the one buffer, 4-aligned, as a buffer view.
    int buffer_view(const void *data, size_t bytes, int target) {
        auto &buffer = model_.buffers[0].data;
        while (buffer.size() % 4 != 0) buffer.push_back(0);
        tinygltf::BufferView view;
        view.buffer = 0;
        view.byteOffset = buffer.size();
        view.byteLength = bytes;
        view.target = target;
        const auto *p = static_cast<const unsigned char *>(data);
        buffer.insert(buffer.end(), p, p + bytes);
        model_.bufferViews.push_back(view);
        return static_cast<int>(model_.bufferViews.size() - 1);
    }

    // `components` floats per element; with `bounds`, its min and max (required for positions and
    // animation times).
    int float_accessor(const std::vector<float> &data, int type, int components, bool bounds,
                       int target = 0) {
        tinygltf::Accessor a;
        a.bufferView = buffer_view(data.data(), data.size() * sizeof(float), target);
        a.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
        a.count = data.size() / static_cast<size_t>(components);
        a.type = type;
        if (bounds && !data.empty()) {
            a.minValues.assign(static_cast<size_t>(components),
                               std::numeric_limits<double>::infinity());
            a.maxValues.assign(static_cast<size_t>(components),
                               -std::numeric_limits<double>::infinity());
            for (size_t i = 0; i < data.size(); ++i) {
                const size_t c = i % static_cast<size_t>(components);
                a.minValues[c] = std::min(a.minValues[c], static_cast<double>(data[i]));
                a.maxValues[c] = std::max(a.maxValues[c], static_cast<double>(data[i]));
            }
        }
        model_.accessors.push_back(a);
        return static_cast<int>(model_.accessors.size() - 1);
    }

    // ---- meshes and materials ----

    int texture(const std::string &id) {
        const auto found = textures_.find(id);
        if (found != textures_.end()) return found->second;
        int index = -1;
        const auto path = assets_.resolve(ANI_ASSET_TEXTURE, id, document_);
        if (!path) {
            note("texture '" + id + "' was not found (" +
                 assets_.searched(ANI_ASSET_TEXTURE, id, document_) +
                 "): its models are exported with their colour only");
        } else {
            std::vector<unsigned char> png;
            std::string extension = path->extension().string();
            std::transform(extension.begin(), extension.end(), extension.begin(), ::tolower);
            if (extension == ".png") {
                std::ifstream in(*path, std::ios::binary);
                png.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
            } else { // BMP: glTF takes PNG and JPEG; decoded and written as PNG
                const Image image = load_image(*path);
                stbi_write_png_to_func(
                    [](void *context, void *data, int size) {
                        auto *out = static_cast<std::vector<unsigned char> *>(context);
                        const auto *bytes = static_cast<const unsigned char *>(data);
                        out->insert(out->end(), bytes, bytes + size);
                    },
                    &png, image.width, image.height, 3, image.rgb.data(), image.width * 3);
            }
            tinygltf::Image image;
            image.name = id;
            image.mimeType = "image/png";
            image.bufferView = buffer_view(png.data(), png.size(), 0);
            model_.images.push_back(image);
            if (model_.samplers.empty()) {
                tinygltf::Sampler sampler;
                sampler.magFilter = TINYGLTF_TEXTURE_FILTER_LINEAR;
                sampler.minFilter = TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_LINEAR;
                sampler.wrapS = sampler.wrapT = TINYGLTF_TEXTURE_WRAP_REPEAT;
                model_.samplers.push_back(sampler);
            }
            tinygltf::Texture t;
            t.sampler = 0;
            t.source = static_cast<int>(model_.images.size() - 1);
            model_.textures.push_back(t);
            index = static_cast<int>(model_.textures.size() - 1);
        }
        textures_.emplace(id, index);
        return index;
    }

    // The model's look as glTF's metallic-roughness material and its extensions (docs/export.md).
    int material(const Model &m) {
        const int image = m.texture.empty() ? -1 : texture(m.texture);
        const auto key = std::make_tuple(m.material.kd.x, m.material.kd.y, m.material.kd.z,
                                         m.material.ks.x, m.material.ks.y, m.material.ks.z,
                                         m.material.shininess, image, image >= 0 ? m.tint : 0.0,
                                         m.reflectivity, m.transparency, m.refractive_index);
        const auto found = materials_.find(key);
        if (found != materials_.end()) return found->second;

        tinygltf::Material mat;
        mat.name = m.name;
        glm::dvec3 base = m.material.kd;
        if (image >= 0) {
            // The shading mixes texture and colour, mix(texture, kd, tint); glTF multiplies them.
            mat.pbrMetallicRoughness.baseColorTexture.index = image;
            base = glm::mix(glm::dvec3(1.0), m.material.kd, m.tint);
            if (m.tint > 0.0 && m.tint < 1.0)
                note("a texture tinted part way (tint between 0 and 1) is written as the texture "
                     "times a "
                     "colour, which glTF has; the mix of the two is not");
        }
        mat.pbrMetallicRoughness.baseColorFactor = {base.x, base.y, base.z, 1.0};
        // Phong's shininess n as a roughness: Blinn-Phong n matches a Beckmann slope
        // alpha = sqrt(2 / (n + 2)), and glTF's roughness is sqrt(alpha).
        const double alpha = std::sqrt(2.0 / (std::max(0.0, m.material.shininess) + 2.0));
        mat.pbrMetallicRoughness.roughnessFactor = std::sqrt(alpha);
        // A mirror of the skybox: glTF's metal, which reflects what is around it.
        mat.pbrMetallicRoughness.metallicFactor = std::clamp(m.reflectivity, 0.0, 1.0);
        const double ks = std::max({m.material.ks.x, m.material.ks.y, m.material.ks.z});
        if (m.material.ks != glm::dvec3(1.0)) {
            Value::Object specular;
            specular["specularFactor"] = Value(std::min(1.0, ks));
            const glm::dvec3 colour = ks > 0.0 ? m.material.ks / ks : glm::dvec3(1.0);
            specular["specularColorFactor"] =
                Value(Value::Array{Value(colour.x), Value(colour.y), Value(colour.z)});
            mat.extensions["KHR_materials_specular"] = Value(specular);
            use_extension("KHR_materials_specular");
        }
        if (m.transparency > 0.0) {
            Value::Object transmission;
            transmission["transmissionFactor"] = Value(std::clamp(m.transparency, 0.0, 1.0));
            mat.extensions["KHR_materials_transmission"] = Value(transmission);
            use_extension("KHR_materials_transmission");
            Value::Object ior;
            ior["ior"] = Value(std::max(1.0, m.refractive_index));
            if (m.refractive_index < 1.0)
                note("glTF's index of refraction is at least 1: '" + m.name + "' has " +
                     std::to_string(m.refractive_index) + ", written as 1");
            mat.extensions["KHR_materials_ior"] = Value(ior);
            use_extension("KHR_materials_ior");
        }
        model_.materials.push_back(mat);
        const int index = static_cast<int>(model_.materials.size() - 1);
        materials_.emplace(key, index);
        return index;
    }

    // The accessors of a mesh as a model's rest shape puts it: a primitive without material.
    tinygltf::Primitive geometry(const Mesh &source, const glm::dmat3 &shape, const std::array<double, 9> &key,
                                 bool textured) {
        const auto cache_key = std::make_tuple(&source, key, textured);
        const auto found = geometries_.find(cache_key);
        if (found != geometries_.end()) return found->second;
        // A rest shape (a course node's shear) is the model's own: glTF nodes cannot shear, so
        // it goes into the vertices, and the normals by its inverse transpose.
        const glm::dmat3 normal_matrix = glm::inverseTranspose(shape);
        std::vector<float> positions, normals, uvs;
        for (size_t i = 0; i < source.positions.size(); ++i) {
            const glm::dvec3 p = shape * source.positions[i];
            const glm::dvec3 n = glm::normalize(normal_matrix * source.normals[i]);
            positions.insert(positions.end(), {float(p.x), float(p.y), float(p.z)});
            normals.insert(normals.end(), {float(n.x), float(n.y), float(n.z)});
            // Our UVs count v up from the image's bottom row (OBJ's way); glTF's from its top.
            uvs.insert(uvs.end(), {float(source.uvs[i].x), float(1.0 - source.uvs[i].y)});
        }
        tinygltf::Primitive primitive;
        primitive.mode = TINYGLTF_MODE_TRIANGLES;
        primitive.attributes["POSITION"] =
            float_accessor(positions, TINYGLTF_TYPE_VEC3, 3, true, TINYGLTF_TARGET_ARRAY_BUFFER);
        primitive.attributes["NORMAL"] =
            float_accessor(normals, TINYGLTF_TYPE_VEC3, 3, false, TINYGLTF_TARGET_ARRAY_BUFFER);
        if (textured)
            primitive.attributes["TEXCOORD_0"] =
                float_accessor(uvs, TINYGLTF_TYPE_VEC2, 2, false, TINYGLTF_TARGET_ARRAY_BUFFER);
        tinygltf::Accessor indices;
        indices.bufferView =
            buffer_view(source.triangles.data(), source.triangles.size() * sizeof(std::uint32_t),
                        TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
        indices.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
        indices.count = source.triangles.size();
        indices.type = TINYGLTF_TYPE_SCALAR;
        model_.accessors.push_back(indices);
        primitive.indices = static_cast<int>(model_.accessors.size() - 1);
        geometries_.emplace(cache_key, primitive);
        return primitive;
    }

    int mesh(size_t m) {
        const Model &model = doc_.models()[m];
        const std::shared_ptr<const Mesh> &source = m < meshes_.size() ? meshes_[m] : nullptr;
        if (!source) return -1;
        if (source->stand_in)
            note("mesh '" + model.mesh + "' was not found: '" + model.name +
                 "' is exported as the stand-in cube");
        const int material_index = material(model);
        std::array<double, 9> rest{};
        for (int c = 0; c < 3; ++c)
            for (int r = 0; r < 3; ++r) rest[static_cast<size_t>(c * 3 + r)] = model.rest[c][r];
        const bool textured =
            source->has_uvs && model_.materials[static_cast<size_t>(material_index)]
                                       .pbrMetallicRoughness.baseColorTexture.index >= 0;
        const auto key = std::make_tuple(source.get(), rest, textured, material_index);
        const auto found = gltf_meshes_.find(key);
        if (found != gltf_meshes_.end()) return found->second;
        // One mesh per material, all of them over one set of accessors: a gas of 125 balls of
        // as many colours holds the sphere once.
        tinygltf::Primitive primitive = geometry(*source, model.rest, rest, textured);
        primitive.material = material_index;
        tinygltf::Mesh out;
        out.name = model.mesh;
        out.primitives.push_back(primitive);
        model_.meshes.push_back(out);
        const int index = static_cast<int>(model_.meshes.size() - 1);
        gltf_meshes_.emplace(key, index);
        return index;
    }

    // ---- animation ----

    // A channel of `node` from the keys, unless they hold one value (then it is the node's own).
    void vec_channel(int node, const std::string &path, std::vector<motion_keys::VecKey> keys) {
        if (keys.empty()) return;
        bool still = true;
        for (const motion_keys::VecKey &k : keys)
            still = still && k.value == keys.front().value && k.in == glm::dvec3(0.0) &&
                    k.out == glm::dvec3(0.0);
        if (still || keys.size() == 1) return;
        std::vector<float> times;
        report_.merged_keys += motion_keys::merge_float_times(keys, options_.from, times);
        if (times.size() < 2) return;
        const double tolerance =
            options_.position_tolerance * (1.0 + glm::length(keys.front().value));
        const bool linear = options_.fps > 0.0 || motion_keys::is_linear(keys, tolerance);
        std::vector<float> values;
        for (const motion_keys::VecKey &k : keys) {
            if (linear) {
                values.insert(values.end(), {float(k.value.x), float(k.value.y), float(k.value.z)});
                continue;
            }
            // CUBICSPLINE: in-tangent, value, out-tangent, each per second.
            for (const glm::dvec3 *v : {&k.in, &k.value, &k.out})
                values.insert(values.end(), {float(v->x), float(v->y), float(v->z)});
        }
        sampler(node, path, times, values, TINYGLTF_TYPE_VEC3, 3,
                linear ? "LINEAR" : "CUBICSPLINE");
    }

    void rotation_channel(int node, std::vector<motion_keys::QuatKey> keys) {
        if (keys.size() < 2) return;
        bool still = true;
        for (const motion_keys::QuatKey &k : keys)
            still = still && motion_keys::angle_between(k.q, keys.front().q) == 0.0;
        if (still) return;
        std::vector<float> times;
        report_.merged_keys += motion_keys::merge_float_times(keys, options_.from, times);
        if (times.size() < 2) return;
        std::vector<float> values;
        for (const motion_keys::QuatKey &k : keys) {
            const glm::dquat q = glm::normalize(k.q);
            values.insert(values.end(), {float(q.x), float(q.y), float(q.z), float(q.w)});
        }
        sampler(node, "rotation", times, values, TINYGLTF_TYPE_VEC4, 4, "LINEAR");
    }

    void sampler(int node, const std::string &path, const std::vector<float> &times,
                 const std::vector<float> &values, int type, int components,
                 const std::string &interpolation) {
        if (model_.animations.empty()) {
            model_.animations.emplace_back();
            model_.animations[0].name = doc_.models().empty() ? "animation" : model_.scenes[0].name;
        }
        tinygltf::Animation &animation = model_.animations[0];
        tinygltf::AnimationSampler s;
        s.input = float_accessor(times, TINYGLTF_TYPE_SCALAR, 1, true);
        s.output = float_accessor(values, type, components, false);
        s.interpolation = interpolation;
        animation.samplers.push_back(s);
        tinygltf::AnimationChannel c;
        c.sampler = static_cast<int>(animation.samplers.size() - 1);
        c.target_node = node;
        c.target_path = path;
        animation.channels.push_back(c);
        ++report_.channels;
        report_.keys += times.size();
    }

    // ---- nodes ----

    int add_node(tinygltf::Node node) {
        model_.nodes.push_back(std::move(node));
        return static_cast<int>(model_.nodes.size() - 1);
    }

    int model_node(int m, const NodeKeys &keys) {
        const Model &model = doc_.models()[static_cast<size_t>(m)];
        tinygltf::Node node;
        node.name = model.name;
        node.mesh = mesh(static_cast<size_t>(m));
        // Its place at the start; the animation moves it from there.
        if (!keys.translation.empty()) node.translation = to_vector(keys.translation.front().value);
        if (!keys.rotation.empty())
            node.rotation = to_vector(glm::normalize(keys.rotation.front().q));
        if (!keys.scale.empty()) node.scale = to_vector(keys.scale.front().value);
        const int index = add_node(std::move(node));
        model_nodes_[static_cast<size_t>(m)] = index;
        vec_channel(index, "translation", keys.translation);
        rotation_channel(index, keys.rotation);
        vec_channel(index, "scale", keys.scale);
        return index;
    }

    int camera_node(const NodeKeys &keys) {
        const CameraState start = timeline_.keyed().camera(options_.from);
        tinygltf::Camera camera;
        camera.name = "camera";
        camera.type = "perspective";
        camera.perspective.yfov = glm::radians(start.fov_degrees);
        camera.perspective.znear = kNearPlane;
        camera.perspective.zfar = kFarPlane;
        model_.cameras.push_back(camera);
        for (const Keyframe *k : doc_.keys_of(-1))
            if (k->camera->fov_degrees != start.fov_degrees)
                note("the camera's field of view changes over the animation; glTF cannot animate "
                     "it, so it is "
                     "the one at the start, " +
                     std::to_string(start.fov_degrees) + " degrees");
        tinygltf::Node node;
        node.name = "camera";
        node.camera = 0;
        if (!keys.translation.empty()) node.translation = to_vector(keys.translation.front().value);
        if (!keys.rotation.empty())
            node.rotation = to_vector(glm::normalize(keys.rotation.front().q));
        if (doc_.settings().lights.empty()) {
            // The light that rides with the camera where the document has none.
            tinygltf::Node light;
            light.name = "camera light";
            light.translation = to_vector(glm::dvec3(Settings::kCameraLightOffset));
            light.extensions["KHR_lights_punctual"] = Value(
                Value::Object{{"light", Value(point_light("camera light", glm::dvec3(1.0)))}});
            node.children.push_back(add_node(std::move(light)));
        }
        const int index = add_node(std::move(node));
        vec_channel(index, "translation", keys.translation);
        rotation_channel(index, keys.rotation);
        return index;
    }

    int point_light(const std::string &name, const glm::dvec3 &colour) {
        tinygltf::Light light;
        light.name = name;
        light.type = "point";
        // glTF's light is a colour (at most 1) and an intensity in candela, falling off as 1/d^2.
        const double strength = std::max({colour.x, colour.y, colour.z});
        const glm::dvec3 c = strength > 0.0 ? colour / strength : glm::dvec3(1.0);
        light.color = to_vector(c);
        light.intensity = strength;
        model_.lights.push_back(light);
        use_extension("KHR_lights_punctual");
        return static_cast<int>(model_.lights.size() - 1);
    }

    std::vector<int> light_nodes() {
        std::vector<int> nodes;
        for (const Light &l : doc_.settings().lights) {
            if (l.falloff != glm::dvec3(0.0, 0.0, 1.0))
                note("glTF's point lights fall off as 1 / d^2; a light's falloff (c0 + c1 d + c2 "
                     "d^2) is written as "
                     "its colour at 1 m with that falloff");
            const glm::dvec3 f = l.falloff;
            const double at_one_metre = f.x + f.y + f.z > 0.0 ? 1.0 / (f.x + f.y + f.z) : 1.0;
            tinygltf::Node node;
            node.name = l.name.empty() ? "light" : l.name;
            node.translation = to_vector(l.position);
            node.extensions["KHR_lights_punctual"] = Value(
                Value::Object{{"light", Value(point_light(node.name, l.colour * at_one_metre))}});
            nodes.push_back(add_node(std::move(node)));
        }
        return nodes;
    }

    // What the document has that glTF does not, kept in the scene's extras for a reader that
    // wants it, and said.
    void scene_settings() {
        const Settings &s = doc_.settings();
        Value::Object extras;
        if (!s.skybox.empty()) {
            extras["skybox"] = Value(s.skybox);
            note("glTF has no skybox: its name is in the scene's extras (animator.skybox); set it "
                 "as the world's "
                 "environment in Blender");
        }
        if (s.cel_shading) {
            extras["cel_shading"] = Value(true);
            note("glTF has no cel shading: the materials are the plain ones, and the scene's "
                 "extras say "
                 "animator.cel_shading");
        }
        if (s.ambient != glm::dvec3(0.0))
            extras["ambient"] =
                Value(Value::Array{Value(s.ambient.x), Value(s.ambient.y), Value(s.ambient.z)});
        extras["gravity"] = Value(s.gravity);
        if (!extras.empty())
            model_.scenes[0].extras = Value(Value::Object{{"animator", Value(extras)}});
    }

    // glTF's up is +Y. An animation whose down axis is X or Z is turned as a whole to match.
    std::vector<int> world_root(const std::vector<int> &nodes) {
        const Axis down = doc_.settings().down_axis;
        if (down == Axis::Y) return nodes;
        tinygltf::Node root;
        root.name = "animator world";
        const glm::dquat turn = down == Axis::X
                                    ? glm::angleAxis(glm::radians(90.0), glm::dvec3(0, 0, 1))
                                    : glm::angleAxis(glm::radians(-90.0), glm::dvec3(1, 0, 0));
        root.rotation = to_vector(turn);
        root.children = nodes;
        return {add_node(std::move(root))};
    }

    const Timeline &timeline_;
    const Document &doc_;
    const std::vector<std::shared_ptr<const Mesh>> &meshes_;
    const AssetPaths &assets_;
    std::filesystem::path document_;
    MotionKeyOptions options_;
    tinygltf::Model model_;
    GltfExportReport report_;
    std::vector<int> model_nodes_;
    std::map<std::string, int> textures_;
    std::map<std::tuple<double, double, double, double, double, double, double, int, double, double,
                        double, double>,
             int>
        materials_;
    std::map<std::tuple<const Mesh *, std::array<double, 9>, bool>, tinygltf::Primitive> geometries_;
    std::map<std::tuple<const Mesh *, std::array<double, 9>, bool, int>, int> gltf_meshes_;
};

} // namespace

GltfExportReport export_gltf(const Timeline &timeline,
                             const std::vector<std::shared_ptr<const Mesh>> &meshes,
                             const AssetPaths &assets, const std::filesystem::path &document,
                             const std::filesystem::path &out, const MotionKeyOptions &options) {
    std::string extension = out.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(), ::tolower);
    if (extension != ".glb" && extension != ".gltf")
        throw ExportError(out.string() + ": a glTF file ends in .glb (binary) or .gltf (text)");
    if (options.until > timeline.baked_until() + 1e-9 || options.from < 0.0 ||
        options.from > options.until)
        throw ExportError(out.string() + ": the export's times must lie within what is baked");
    GltfBuilder builder(timeline, meshes, assets, document, options);
    GltfExportReport report = builder.build();

    // Beside the file, then renamed over it: a failure leaves any previous file whole.
    const std::filesystem::path partial =
        out.parent_path() / ("." + out.filename().string() + ".partial");
    {
        std::ofstream stream(partial, std::ios::binary);
        if (!stream) throw ExportError(out.string() + ": cannot be written");
        tinygltf::TinyGLTF writer;
        const bool ok =
            writer.WriteGltfSceneToStream(&builder.model(), stream, true, extension == ".glb");
        stream.close();
        if (!ok || !stream) {
            std::error_code ignored;
            std::filesystem::remove(partial, ignored);
            throw ExportError(out.string() + ": writing failed");
        }
    }
    std::error_code ec;
    std::filesystem::rename(partial, out, ec);
    if (ec) {
        std::filesystem::remove(partial, ec);
        throw ExportError(out.string() + ": cannot be written (" + ec.message() + ")");
    }
    return report;
}

} // namespace animator
