#include "scene_wire.hpp"

#include <cstring>
#include <stdexcept>
#include <type_traits>

namespace lua_scene {

namespace {

constexpr char kMagic[] = "animator-scene 2\n"; // a new layout gets a new number
constexpr char kResult = 'R', kError = 'E';

// Both ends are the same build of this plugin on the same machine: numbers go as their bytes.
class Writer {
  public:
    template <typename T> void put(T value) {
        static_assert(std::is_arithmetic_v<T>);
        out_.append(reinterpret_cast<const char *>(&value), sizeof value);
    }
    void put(bool value) { put<uint8_t>(value ? 1 : 0); }
    void put(const std::string &s) {
        put<uint64_t>(s.size());
        out_ += s;
    }
    void put(const ani_vec3 &v) {
        put(v.x);
        put(v.y);
        put(v.z);
    }
    std::string take() { return std::move(out_); }
    void raw(const char *bytes, size_t size) { out_.append(bytes, size); }

  private:
    std::string out_;
};

struct Malformed : std::runtime_error {
    using std::runtime_error::runtime_error;
};

class Reader {
  public:
    explicit Reader(const std::string &bytes) : bytes_(bytes) {}

    template <typename T> T get() {
        static_assert(std::is_arithmetic_v<T>);
        need(sizeof(T), "a number");
        T value;
        std::memcpy(&value, bytes_.data() + at_, sizeof value);
        at_ += sizeof value;
        return value;
    }
    bool get_bool() {
        const auto b = get<uint8_t>();
        if (b > 1) throw Malformed("a flag that is neither 0 nor 1");
        return b == 1;
    }
    std::string get_string() {
        const auto size = get<uint64_t>();
        need(size, "a string");
        std::string s = bytes_.substr(at_, static_cast<size_t>(size));
        at_ += static_cast<size_t>(size);
        return s;
    }
    ani_vec3 get_vec3() {
        ani_vec3 v;
        v.x = get<double>();
        v.y = get<double>();
        v.z = get<double>();
        return v;
    }
    // A count of items each at least `item_bytes` long: never more than what is left could hold,
    // so a lying count cannot make us reserve memory.
    size_t get_count(size_t item_bytes) {
        const auto n = get<uint64_t>();
        if (n > left() / item_bytes) throw Malformed("a count larger than the reply");
        return static_cast<size_t>(n);
    }
    void expect(const char *bytes, size_t size) {
        need(size, "the header");
        if (bytes_.compare(at_, size, bytes, size) != 0) throw Malformed("a wrong header");
        at_ += size;
    }
    size_t left() const { return bytes_.size() - at_; }

  private:
    void need(uint64_t size, const char *what) const {
        if (size > left()) throw Malformed(std::string("the reply ends inside ") + what);
    }
    const std::string &bytes_;
    size_t at_ = 0;
};

// The fewest bytes a model or a string can take: what a lying count is checked against.
constexpr size_t kStringBytes = sizeof(uint64_t);
constexpr size_t kModelBytes = 6 * kStringBytes + 2 * sizeof(int32_t) + 4 + 40 * sizeof(double);
constexpr size_t kLightBytes = kStringBytes + 9 * sizeof(double);

} // namespace

std::string encode_result(const SceneResult &r) {
    Writer w;
    w.raw(kMagic, sizeof kMagic - 1);
    w.put(kResult);
    w.put(r.max_time_ms);
    w.put(r.gravity);
    w.put(r.down_axis);
    w.put(r.cel_shading);
    w.put(r.skybox);
    w.put(r.backend);
    w.put(r.interpolation);
    w.put(r.camera.position);
    for (double q : {r.camera.rotation.w, r.camera.rotation.x, r.camera.rotation.y, r.camera.rotation.z}) w.put(q);
    w.put(r.camera.fov_degrees);
    w.put<uint64_t>(r.warnings.size());
    for (const auto &warning : r.warnings) w.put(warning);
    w.put<uint64_t>(r.lights.size());
    for (const SceneLight &l : r.lights) {
        w.put(l.name);
        w.put(l.position);
        w.put(l.colour);
        w.put(l.falloff);
    }
    w.put(r.ambient);
    w.put(r.render_output);
    w.put(r.render_width);
    w.put(r.render_height);
    w.put<uint64_t>(r.models.size());
    for (const SceneModel &m : r.models) {
        w.put(m.name);
        w.put(m.mesh);
        w.put(m.line);
        w.put(m.parent);
        w.put(m.kd);
        w.put(m.ks);
        w.put(m.shininess);
        w.put(m.texture);
        w.put(m.tint);
        w.put(m.reflectivity);
        w.put(m.transparency);
        w.put(m.refractive_index);
        w.put(m.dynamics);
        w.put(m.gravity);
        w.put(m.mass);
        w.put(m.initial_velocity);
        w.put(m.restitution);
        w.put(m.friction);
        w.put(m.rotates);
        w.put(m.angular_velocity);
        w.put(m.collision_sound);
        w.put(m.moving_sound);
        for (const ani_vec3 &v : {m.state.center, m.state.angles, m.state.scale, m.state.turn}) w.put(v);
        for (double x : m.rest) w.put(x);
        w.put(m.has_joint);
        w.put(m.joint_min);
        w.put(m.joint_max);
    }
    return w.take();
}

std::string encode_error(const std::string &message) {
    Writer w;
    w.raw(kMagic, sizeof kMagic - 1);
    w.put(kError);
    w.put(message);
    return w.take();
}

bool decode_reply(const std::string &bytes, const std::string &path, SceneResult &out, std::string &error) {
    try {
        Reader r(bytes);
        r.expect(kMagic, sizeof kMagic - 1);
        const char kind = r.get<char>();
        if (kind == kError) {
            error = r.get_string();
            if (error.empty()) throw Malformed("an error without a message"); // the user would see nothing
            if (r.left() != 0) throw Malformed("bytes after the error");
            return false;
        }
        if (kind != kResult) throw Malformed("an unknown kind of reply");
        SceneResult s;
        s.max_time_ms = r.get<int64_t>();
        s.gravity = r.get<double>();
        s.down_axis = r.get<int32_t>();
        s.cel_shading = r.get_bool();
        s.skybox = r.get_string();
        s.backend = r.get_string();
        s.interpolation = r.get_string();
        s.camera.position = r.get_vec3();
        s.camera.rotation.w = r.get<double>();
        s.camera.rotation.x = r.get<double>();
        s.camera.rotation.y = r.get<double>();
        s.camera.rotation.z = r.get<double>();
        s.camera.fov_degrees = r.get<double>();
        for (size_t n = r.get_count(kStringBytes); n > 0; --n) s.warnings.push_back(r.get_string());
        for (size_t n = r.get_count(kLightBytes); n > 0; --n) {
            SceneLight l;
            l.name = r.get_string();
            l.position = r.get_vec3();
            l.colour = r.get_vec3();
            l.falloff = r.get_vec3();
            s.lights.push_back(std::move(l));
        }
        s.ambient = r.get_vec3();
        s.render_output = r.get_string();
        s.render_width = r.get<int32_t>();
        s.render_height = r.get<int32_t>();
        const size_t model_count = r.get_count(kModelBytes);
        s.models.reserve(model_count);
        for (size_t i = 0; i < model_count; ++i) {
            SceneModel m;
            m.name = r.get_string();
            m.mesh = r.get_string();
            m.line = r.get<int32_t>();
            m.parent = r.get<int32_t>();
            // Parents come first: the document checks the rest of the tree.
            if (m.parent < -1 || m.parent >= static_cast<int32_t>(i)) throw Malformed("a model whose parent is not before it");
            m.kd = r.get_vec3();
            m.ks = r.get_vec3();
            m.shininess = r.get<double>();
            m.texture = r.get_string();
            m.tint = r.get<double>();
            m.reflectivity = r.get<double>();
            m.transparency = r.get<double>();
            m.refractive_index = r.get<double>();
            m.dynamics = r.get_bool();
            m.gravity = r.get_bool();
            m.mass = r.get<double>();
            m.initial_velocity = r.get_vec3();
            m.restitution = r.get<double>();
            m.friction = r.get<double>();
            m.rotates = r.get_bool();
            m.angular_velocity = r.get_vec3();
            m.collision_sound = r.get_string();
            m.moving_sound = r.get_string();
            m.state.center = r.get_vec3();
            m.state.angles = r.get_vec3();
            m.state.scale = r.get_vec3();
            m.state.turn = r.get_vec3();
            for (double &x : m.rest) x = r.get<double>();
            m.has_joint = r.get_bool();
            m.joint_min = r.get_vec3();
            m.joint_max = r.get_vec3();
            s.models.push_back(std::move(m));
        }
        if (r.left() != 0) throw Malformed("bytes after the scene");
        out = std::move(s);
        return true;
    } catch (const Malformed &e) {
        error = path + ": the scene reader's reply is malformed (" + e.what() + ")";
        return false;
    }
}

} // namespace lua_scene
