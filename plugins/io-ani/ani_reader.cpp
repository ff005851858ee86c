// Reading .ani files: strict, and every error names the file, the line and what was expected.
#include "ani_text.hpp"

#include <animator/assets.h>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>
#include <set>
#include <stdexcept>

namespace ani_format {

namespace {

struct ParseError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

class Reader {
  public:
    Reader(const char *path, std::istream &in, const ani_assets_ext *assets, const ani_host *host)
        : path_(path), in_(in), assets_(assets), host_(host) {}

    void read(ani::OwnedDocument &doc);

  private:
    [[noreturn]] void fail(const std::string &what) const { fail_at(line_, what); }
    [[noreturn]] void fail_at(std::int64_t line, const std::string &what) const {
        throw ParseError(std::string(path_) + ":" + std::to_string(line) + ": " + what);
    }
    bool next_line();
    bool read_line(std::string &text);
    // Before a block or line that adds a model, a keyframe or a parameter value.
    void check_size(size_t models, size_t keyframes, size_t params) const {
        const std::string why = size_beyond_limits(models, keyframes, params);
        if (!why.empty()) fail("the document grows past its limits here: " + why);
    }
    std::string got(size_t i) const {
        return i < tokens_.size() ? "'" + tokens_[i].text + "'" : "the end of the line";
    }
    void expect_count(size_t n, const char *what) const {
        if (tokens_.size() < n) fail(std::string("expected ") + what + " after '" + tokens_[0].text +
                                     "', got the end of the line");
        if (tokens_.size() > n) fail("unexpected " + got(n) + " after '" + tokens_[0].text + "'");
    }
    void expect_word(size_t i, const char *word) const {
        if (i >= tokens_.size() || tokens_[i].quoted || tokens_[i].text != word)
            fail(std::string("expected '") + word + "', got " + got(i));
    }
    double number(size_t i, const char *what) const;
    std::int64_t integer(size_t i, const char *what) const;
    bool boolean(size_t i, const char *what) const;
    std::string string(size_t i, const char *what) const;
    ani_vec3 vec3(size_t i, const char *what) const {
        return ani_vec3{number(i, what), number(i + 1, what), number(i + 2, what)};
    }
    ani_vec3 colour(size_t i, const char *what) const;
    double unit(size_t i, const char *what) const;
    double positive(size_t i, const char *what) const;
    // Each key once per block.
    void once(std::set<std::string> &seen) const {
        if (!seen.insert(tokens_[0].text).second) fail("'" + tokens_[0].text + "' is given twice");
    }

    void read_settings(ani::OwnedDocument &doc);
    void read_model(ani::OwnedDocument &doc);
    void read_keyframe(ani::OwnedDocument &doc);

    const char *path_;
    std::istream &in_;
    const ani_assets_ext *assets_; // null when the host has no asset folders
    const ani_host *host_;
    std::int64_t line_ = 0; // an int would wrap after 2^31 blank lines
    std::vector<Token> tokens_;
    std::map<std::string, int> model_index_;
};

// std::getline without its unbounded string: a line longer than kMaxLineBytes is refused at
// its number once that many bytes are read, so a file of one 1 GB line costs 1 MiB.
bool Reader::read_line(std::string &text) {
    text.clear();
    std::streambuf &buf = *in_.rdbuf();
    bool any = false;
    for (int c = buf.sbumpc(); c != std::char_traits<char>::eof(); c = buf.sbumpc()) {
        any = true;
        if (c == '\n') return true;
        if (text.size() == kMaxLineBytes)
            fail_at(line_ + 1, "the line is longer than " + std::to_string(kMaxLineBytes) +
                                   " bytes; an .ani line holds one key and its values");
        text.push_back(static_cast<char>(c));
    }
    return any;
}

bool Reader::next_line() {
    std::string text;
    while (read_line(text)) {
        ++line_;
        std::string error;
        if (!tokenize(text, tokens_, error)) fail(error);
        if (!tokens_.empty()) return true;
    }
    return false;
}

double Reader::number(size_t i, const char *what) const {
    if (i >= tokens_.size() || tokens_[i].quoted)
        fail(std::string("expected a number for ") + what + ", got " + got(i));
    const std::string &t = tokens_[i].text;
    char *end = nullptr;
    errno = 0;
    const double v = std::strtod(t.c_str(), &end);
    if (end == t.c_str() || *end != '\0')
        fail(std::string("expected a number for ") + what + ", got '" + t + "'");
    if (!std::isfinite(v) || errno == ERANGE)
        fail(std::string("expected a finite number for ") + what + ", got '" + t + "'");
    return v;
}

std::int64_t Reader::integer(size_t i, const char *what) const {
    if (i >= tokens_.size() || tokens_[i].quoted)
        fail(std::string("expected a whole number for ") + what + ", got " + got(i));
    const std::string &t = tokens_[i].text;
    char *end = nullptr;
    errno = 0;
    const long long v = std::strtoll(t.c_str(), &end, 10);
    if (end == t.c_str() || *end != '\0' || errno == ERANGE)
        fail(std::string("expected a whole number for ") + what + ", got '" + t + "'");
    return v;
}

bool Reader::boolean(size_t i, const char *what) const {
    if (i < tokens_.size() && !tokens_[i].quoted) {
        if (tokens_[i].text == "true") return true;
        if (tokens_[i].text == "false") return false;
    }
    fail(std::string("expected true or false for ") + what + ", got " + got(i));
}

std::string Reader::string(size_t i, const char *what) const {
    if (i >= tokens_.size() || !tokens_[i].quoted)
        fail(std::string("expected a quoted string for ") + what + ", got " + got(i));
    return tokens_[i].text;
}

ani_vec3 Reader::colour(size_t i, const char *what) const {
    const ani_vec3 c = vec3(i, what);
    for (double x : {c.x, c.y, c.z})
        if (x < 0.0) fail(std::string("expected ") + what + " components >= 0 (1 is full)");
    return c;
}

double Reader::unit(size_t i, const char *what) const {
    const double v = number(i, what);
    if (v < 0.0 || v > 1.0) fail(std::string("expected ") + what + " in [0, 1], got " + got(i));
    return v;
}

double Reader::positive(size_t i, const char *what) const {
    const double v = number(i, what);
    if (v <= 0.0) fail(std::string("expected ") + what + " > 0, got " + got(i));
    return v;
}

void Reader::read(ani::OwnedDocument &doc) {
    if (!next_line()) fail_at(1, "the file is empty; expected 'animator-ani 1'");
    expect_word(0, kMagic);
    expect_count(2, "the format version");
    const std::int64_t version = integer(1, "the format version");
    if (version > kVersion)
        fail("format version " + std::to_string(version) +
             " was written by a newer animator; this one reads versions 1 to " +
             std::to_string(kVersion));
    if (version < 1) fail("expected a format version >= 1, got " + std::to_string(version));

    doc.default_settings(); // docs/ani-format.md

    bool seen_settings = false;
    while (next_line()) {
        const std::string &word = tokens_[0].text;
        if (tokens_[0].quoted) fail("expected 'settings', 'model' or 'keyframe', got " + got(0));
        if (word == "settings") {
            if (seen_settings) fail("a second 'settings' block; expected one at most");
            if (!doc.models.empty() || !doc.keyframes.empty())
                fail("'settings' must come before the models and keyframes");
            seen_settings = true;
            expect_count(1, "nothing");
            read_settings(doc);
        } else if (word == "model") {
            if (!doc.keyframes.empty()) fail("models must come before the keyframes");
            read_model(doc);
        } else if (word == "keyframe") {
            read_keyframe(doc);
        } else {
            fail("expected 'settings', 'model' or 'keyframe', got " + got(0));
        }
    }
    if (doc.keyframes.empty()) fail_at(line_ + 1, "the file ends without a 'keyframe 0' block");
    doc.finish();
}

void Reader::read_settings(ani::OwnedDocument &doc) {
    ani_settings_view &s = doc.view.settings;
    std::set<std::string> seen;
    std::set<std::pair<std::string, std::string>> params_seen;
    while (true) {
        if (!next_line()) fail("the file ends inside 'settings'; expected 'end'");
        const std::string key = tokens_[0].quoted ? "" : tokens_[0].text;
        if (key == "end") {
            expect_count(1, "nothing");
            return;
        }
        if (key != "param" && key != "light") once(seen);
        if (key == "max_time_ms") {
            expect_count(2, "a time in milliseconds");
            const std::int64_t t = integer(1, "max_time_ms");
            if (t < 1000 || t > 300000000)
                fail("expected max_time_ms between 1000 (1 s) and 300000000 (300000 s), got " + got(1));
            s.max_time_ms = t;
        } else if (key == "gravity") {
            expect_count(2, "a number");
            s.gravity = number(1, "gravity");
        } else if (key == "down") {
            expect_count(2, "x, y or z");
            const std::string &a = tokens_[1].text;
            if (tokens_[1].quoted || (a != "x" && a != "y" && a != "z"))
                fail("expected x, y or z for down, got " + got(1));
            s.down_axis = a == "x" ? ANI_AXIS_X : a == "y" ? ANI_AXIS_Y : ANI_AXIS_Z;
        } else if (key == "cel_shading") {
            expect_count(2, "true or false");
            s.cel_shading = boolean(1, "cel_shading") ? 1 : 0;
        } else if (key == "skybox") {
            expect_count(2, "a quoted name");
            s.skybox = doc.keep(string(1, "skybox"));
        } else if (key == "physics_backend") {
            expect_count(2, "a quoted plugin id");
            const std::string id = string(1, "physics_backend");
            if (id.empty()) fail("expected a plugin id for physics_backend, got \"\"");
            s.physics_backend = doc.keep(id);
        } else if (key == "interpolation") {
            expect_count(2, "a quoted plugin id");
            const std::string id = string(1, "interpolation");
            if (id.empty()) fail("expected a plugin id for interpolation, got \"\"");
            s.interpolation = doc.keep(id);
        } else if (key == "param") {
            check_size(doc.models.size(), doc.keyframes.size(), doc.params.size() + 1);
            if (tokens_.size() < 4 || tokens_.size() > 7)
                fail("expected 'param \"plugin.id\" \"param_id\"' and 1 to 4 numbers");
            ani_param_setting p{};
            const std::string plugin = string(1, "the plugin id");
            const std::string param = string(2, "the parameter id");
            if (!params_seen.insert({plugin, param}).second)
                fail("parameter " + plugin + " " + param + " is given twice");
            p.plugin_id = doc.keep(plugin);
            p.param_id = doc.keep(param);
            for (size_t i = 3; i < tokens_.size(); ++i) p.value.value[i - 3] = number(i, "the value");
            doc.params.push_back(p);
        } else if (key == "ambient") {
            expect_count(4, "three numbers");
            doc.view.ambient = colour(1, "ambient");
        } else if (key == "light") {
            // light "NAME" position X Y Z colour R G B falloff C0 C1 C2
            expect_count(14, "'\"NAME\" position X Y Z colour R G B falloff C0 C1 C2'");
            if (doc.lights.size() >= ANI_MAX_LIGHTS)
                fail("a scene has at most " + std::to_string(ANI_MAX_LIGHTS) + " lights");
            expect_word(2, "position");
            expect_word(6, "colour");
            expect_word(10, "falloff");
            ani_light l{};
            l.name = doc.keep(string(1, "the light name"));
            l.position = vec3(3, "the light position");
            l.colour = colour(7, "the light colour");
            l.falloff = colour(11, "the light falloff");
            if (!(l.falloff.x + l.falloff.y + l.falloff.z > 0.0)) fail("expected a falloff that is not all 0");
            doc.lights.push_back(l);
        } else if (key == "render") {
            expect_count(4, "'\"FILE\" WIDTH HEIGHT'");
            doc.view.render_output = doc.keep(string(1, "the render output"));
            const std::int64_t w = integer(2, "the render width"), h = integer(3, "the render height");
            if (w < 0 || h < 0 || w > 16384 || h > 16384)
                fail("expected a render size of 0 (the default) or 1 to 16384 pixels");
            doc.view.render_width = static_cast<int32_t>(w);
            doc.view.render_height = static_cast<int32_t>(h);
        } else {
            fail("unknown settings key " + got(0) + "; expected max_time_ms, gravity, down, "
                 "cel_shading, skybox, physics_backend, interpolation, param, ambient, light, render or end");
        }
    }
}

void Reader::read_model(ani::OwnedDocument &doc) {
    expect_count(2, "a quoted model name");
    const std::string name = string(1, "the model name");
    if (name.empty()) fail("a model needs a non-empty name");
    if (model_index_.count(name)) fail("a model named \"" + name + "\" already exists");
    check_size(doc.models.size() + 1, doc.keyframes.size(), doc.params.size());
    const std::int64_t header_line = line_;

    ani_model_desc m = doc.default_model(name, "");
    bool have_mesh = false;

    std::set<std::string> seen;
    while (true) {
        if (!next_line()) fail("the file ends inside model \"" + name + "\"; expected 'end'");
        const std::string key = tokens_[0].quoted ? "" : tokens_[0].text;
        if (key == "end") {
            expect_count(1, "nothing");
            break;
        }
        once(seen);
        if (key == "mesh") {
            expect_count(2, "a quoted mesh id");
            const std::string mesh = string(1, "mesh"); // "" makes an empty: a node without geometry
            char where[2048];
            if (!mesh.empty() && assets_ &&
                !assets_->resolve(host_, ANI_ASSET_MESH, mesh.c_str(), path_, where, sizeof where))
                fail("unknown mesh \"" + mesh + "\" (" + where + ")");
            m.mesh = doc.keep(mesh);
            have_mesh = true;
        } else if (key == "parent") {
            expect_count(2, "the quoted name of an earlier model");
            const std::string parent = string(1, "parent");
            auto it = model_index_.find(parent);
            if (it == model_index_.end())
                fail("expected the name of an earlier model for parent, got \"" + parent + "\"");
            m.parent = it->second;
        } else if (key == "kd") {
            expect_count(4, "three numbers");
            m.kd = colour(1, "kd");
        } else if (key == "ks") {
            expect_count(4, "three numbers");
            m.ks = colour(1, "ks");
        } else if (key == "shininess") {
            expect_count(2, "a number");
            m.shininess = number(1, "shininess");
            if (m.shininess < 0.0) fail("expected shininess >= 0, got " + got(1));
        } else if (key == "texture") {
            expect_count(2, "a quoted texture name");
            m.texture = doc.keep(string(1, "texture"));
        } else if (key == "tint") {
            expect_count(2, "a number");
            m.tint = unit(1, "tint");
        } else if (key == "reflectivity") {
            expect_count(2, "a number");
            m.reflectivity = unit(1, "reflectivity");
        } else if (key == "transparency") {
            expect_count(2, "a number");
            m.transparency = unit(1, "transparency");
        } else if (key == "refractive_index") {
            expect_count(2, "a number");
            m.refractive_index = positive(1, "refractive_index");
        } else if (key == "dynamics") {
            expect_count(2, "true or false");
            m.dynamics = boolean(1, "dynamics") ? 1 : 0;
        } else if (key == "gravity") {
            expect_count(2, "true or false");
            m.gravity = boolean(1, "gravity") ? 1 : 0;
        } else if (key == "mass") {
            expect_count(2, "a number");
            m.mass = positive(1, "mass");
        } else if (key == "velocity") {
            expect_count(4, "three numbers");
            m.initial_velocity = vec3(1, "velocity");
        } else if (key == "restitution") { // rigid-body settings: absent in older files (defaults)
            expect_count(2, "a number");
            m.restitution = unit(1, "restitution");
        } else if (key == "friction") {
            expect_count(2, "a number");
            m.friction = number(1, "friction");
            if (m.friction < 0.0) fail("expected friction >= 0, got " + got(1));
        } else if (key == "rotates") {
            expect_count(2, "true or false");
            m.rotates = boolean(1, "rotates") ? 1 : 0;
        } else if (key == "angular_velocity") {
            expect_count(4, "three numbers");
            m.angular_velocity = vec3(1, "angular_velocity");
        } else if (key == "collision_sound") {
            expect_count(2, "a quoted sound name");
            m.collision_sound = doc.keep(string(1, "collision_sound"));
        } else if (key == "moving_sound") {
            expect_count(2, "a quoted sound name");
            m.moving_sound = doc.keep(string(1, "moving_sound"));
        } else if (key == "rest") { // row by row
            expect_count(10, "nine numbers, row by row");
            for (int r = 0; r < 3; ++r)
                for (int c = 0; c < 3; ++c) m.rest[3 * c + r] = number(static_cast<size_t>(1 + 3 * r + c), "rest");
            const double *a = m.rest;
            const double det = a[0] * (a[4] * a[8] - a[7] * a[5]) - a[3] * (a[1] * a[8] - a[7] * a[2]) +
                               a[6] * (a[1] * a[5] - a[4] * a[2]);
            if (!(det > 1e-12)) fail("expected a rest shape with determinant > 0 (no mirror, no flattening)");
        } else if (key == "joint") {
            // joint x MIN MAX y MIN MAX z MIN MAX
            expect_count(10, "'x MIN MAX y MIN MAX z MIN MAX'");
            expect_word(1, "x");
            expect_word(4, "y");
            expect_word(7, "z");
            m.has_joint = 1;
            m.joint_min = {number(2, "the joint range"), number(5, "the joint range"), number(8, "the joint range")};
            m.joint_max = {number(3, "the joint range"), number(6, "the joint range"), number(9, "the joint range")};
            if (!(m.joint_min.x <= m.joint_max.x && m.joint_min.y <= m.joint_max.y && m.joint_min.z <= m.joint_max.z))
                fail("expected each joint range as MIN MAX with MIN <= MAX");
        } else {
            fail("unknown model key " + got(0) + "; expected mesh, parent, kd, ks, shininess, "
                 "texture, tint, reflectivity, transparency, refractive_index, dynamics, gravity, "
                 "mass, velocity, restitution, friction, rotates, angular_velocity, collision_sound, "
                 "moving_sound, rest, joint or end");
        }
    }
    if (!have_mesh) fail_at(header_line, "model \"" + name + "\" has no 'mesh'");
    model_index_[name] = static_cast<int>(doc.models.size());
    doc.models.push_back(m);
}

void Reader::read_keyframe(ani::OwnedDocument &doc) {
    expect_count(2, "a time in milliseconds");
    const std::int64_t t = integer(1, "the keyframe time");
    if (doc.keyframes.empty() && t != 0) fail("expected the first keyframe at 0 ms, got " + got(1));
    if (!doc.keyframes.empty() && t <= doc.keyframes.back().time_ms)
        fail("expected keyframe times to increase: " + std::to_string(t) + " ms comes after " +
             std::to_string(doc.keyframes.back().time_ms) + " ms");
    if (t > doc.view.settings.max_time_ms)
        fail("keyframe " + std::to_string(t) + " ms is past the max time " +
             std::to_string(doc.view.settings.max_time_ms) + " ms");
    check_size(doc.models.size(), doc.keyframes.size() + 1, doc.params.size());
    const std::int64_t header_line = line_;

    ani_keyframe_view k{};
    k.struct_size = sizeof k;
    k.time_ms = t;
    std::vector<ani_model_state> states(doc.models.size());
    std::vector<int32_t> have(doc.models.size(), 0);
    bool have_camera = false;
    while (true) {
        if (!next_line()) fail("the file ends inside keyframe " + std::to_string(t) + "; expected 'end'");
        const std::string key = tokens_[0].quoted ? "" : tokens_[0].text;
        if (key == "end") {
            expect_count(1, "nothing");
            break;
        }
        if (key == "camera") {
            if (have_camera) fail("'camera' is given twice");
            // camera position X Y Z rotation W X Y Z fov DEGREES
            expect_count(12, "'position X Y Z rotation W X Y Z fov DEGREES'");
            expect_word(1, "position");
            expect_word(5, "rotation");
            expect_word(10, "fov");
            k.camera.position = vec3(2, "the camera position");
            ani_quat q{number(6, "the camera rotation"), number(7, "the camera rotation"),
                       number(8, "the camera rotation"), number(9, "the camera rotation")};
            // Kept as written, so that a document reads back exactly as it was saved.
            const double n = std::sqrt(q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z);
            if (std::abs(n - 1.0) > 1e-6) fail("expected a unit quaternion for the camera rotation");
            k.camera.rotation = q;
            k.camera.fov_degrees = number(11, "the camera fov");
            if (!(k.camera.fov_degrees > 0.0 && k.camera.fov_degrees < 180.0))
                fail("expected a camera fov in (0, 180) degrees, got " + got(11));
            have_camera = true;
        } else if (key == "state") {
            // state "NAME" center X Y Z angles X Y Z scale X Y Z turn X Y Z
            expect_count(18, "'\"NAME\" center X Y Z angles X Y Z scale X Y Z turn X Y Z'");
            const std::string name = string(1, "the model name");
            auto it = model_index_.find(name);
            if (it == model_index_.end()) fail("no model named \"" + name + "\" is declared before");
            const auto m = static_cast<size_t>(it->second);
            if (have[m]) fail("model \"" + name + "\" has two states in this keyframe");
            expect_word(2, "center");
            expect_word(6, "angles");
            expect_word(10, "scale");
            expect_word(14, "turn");
            ani_model_state st{};
            st.center = vec3(3, "the center");
            st.angles = vec3(7, "the angles");
            for (double a : {st.angles.x, st.angles.y, st.angles.z})
                if (!(a >= 0.0 && a < 360.0)) fail("expected angles in [0, 360) degrees");
            st.scale = vec3(11, "the scale");
            for (double x : {st.scale.x, st.scale.y, st.scale.z})
                if (!(x > 0.0)) fail("expected a scale > 0");
            st.turn = vec3(15, "the rotation direction");
            states[m] = st;
            have[m] = 1;
        } else {
            fail("unknown keyframe key " + got(0) + "; expected camera, state or end");
        }
    }
    // Only the keyframe at t = 0 must key everything (the initial placement); later keyframes
    // key the models and camera they list.
    if (t == 0 && !have_camera) fail_at(header_line, "keyframe 0 has no 'camera' line");
    for (size_t m = 0; m < have.size(); ++m)
        if (t == 0 && !have[m])
            fail_at(header_line, std::string("keyframe ") + std::to_string(t) + " has no state for model \"" +
                 doc.models[m].name + "\"");
    k.camera_keyed = have_camera ? 1 : 0;
    doc.keyframes.push_back(k);
    doc.states.push_back(std::move(states));
    doc.keyed.push_back(std::move(have));
}

} // namespace

bool read_ani(const char *path, const ani_host *host, ani::OwnedDocument &doc, std::string &error) {
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        error = std::string(path) + ": cannot open the file: " + std::strerror(errno);
        return false;
    }
    try {
        const auto *assets = host && host->get_extension
                                 ? static_cast<const ani_assets_ext *>(host->get_extension(host, ANI_EXT_ASSETS))
                                 : nullptr;
        Reader(path, in, assets, host).read(doc);
        return true;
    } catch (const ParseError &e) {
        error = e.what();
        return false;
    }
}

} // namespace ani_format
