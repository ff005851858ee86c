// Writing .ani files, atomically: the text goes to a temporary file beside the target, which is
// flushed to disk and then renamed over the target. A failure at any point removes the
// temporary file and leaves the previous file as it was.
#include "ani_text.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <sstream>
#include <string>

namespace ani_format {

namespace {

std::string str(const char *s) { return s ? s : ""; }
std::string vec(const ani_vec3 &v) { return number(v.x) + " " + number(v.y) + " " + number(v.z); }
const char *boolean(int32_t b) { return b ? "true" : "false"; }

bool identity(const double (&m)[9]) {
    for (int i = 0; i < 9; ++i)
        if (m[i] != (i % 4 == 0 ? 1.0 : 0.0)) return false;
    return true;
}

// Version 2 added lights, ambient, render, rest and joint: a document without them is written
// as version 1, which older readers take.
int version_needed(const ani_document_view &doc) {
    if (ANI_DOCUMENT_VIEW_HAS_LIGHTS(&doc) &&
        (doc.light_count > 0 || doc.ambient.x != 0.2 || doc.ambient.y != 0.2 || doc.ambient.z != 0.2 ||
         str(doc.render_output) != "" || doc.render_width != 0 || doc.render_height != 0))
        return 2;
    for (uint32_t i = 0; i < doc.model_count; ++i)
        if (ANI_MODEL_DESC_HAS_SHAPE(&doc.models[i]) && (!identity(doc.models[i].rest) || doc.models[i].has_joint))
            return 2;
    return 1;
}

std::string to_text(const ani_document_view &doc) {
    std::ostringstream out;
    const ani_settings_view &s = doc.settings;
    const int version = version_needed(doc);
    out << kMagic << " " << version << "\n"
        << "# An animation of animator: see docs/ani-format.md.\n\n"
        << "settings\n"
        << "  max_time_ms " << s.max_time_ms << "\n"
        << "  gravity " << number(s.gravity) << "\n"
        << "  down " << "xyz"[s.down_axis >= 0 && s.down_axis <= 2 ? s.down_axis : 1] << "\n"
        << "  cel_shading " << boolean(s.cel_shading) << "\n"
        << "  skybox " << quote(str(s.skybox)) << "\n"
        << "  physics_backend " << quote(str(s.physics_backend)) << "\n"
        << "  interpolation " << quote(str(s.interpolation)) << "\n";
    for (uint32_t i = 0; i < doc.param_count; ++i) {
        const ani_param_setting &p = doc.params[i];
        out << "  param " << quote(str(p.plugin_id)) << " " << quote(str(p.param_id));
        for (double v : p.value.value) out << " " << number(v);
        out << "\n";
    }
    if (version >= 2) {
        out << "  ambient " << vec(doc.ambient) << "\n";
        for (uint32_t i = 0; i < doc.light_count; ++i) {
            const ani_light &l = doc.lights[i];
            out << "  light " << quote(str(l.name)) << " position " << vec(l.position) << " colour "
                << vec(l.colour) << " falloff " << vec(l.falloff) << "\n";
        }
        if (str(doc.render_output) != "" || doc.render_width != 0 || doc.render_height != 0)
            out << "  render " << quote(str(doc.render_output)) << " " << doc.render_width << " "
                << doc.render_height << "\n";
    }
    out << "end\n";

    for (uint32_t i = 0; i < doc.model_count; ++i) {
        const ani_model_desc &m = doc.models[i];
        out << "\nmodel " << quote(str(m.name)) << "\n"
            << "  mesh " << quote(str(m.mesh)) << "\n";
        if (m.parent >= 0 && static_cast<uint32_t>(m.parent) < doc.model_count)
            out << "  parent " << quote(str(doc.models[m.parent].name)) << "\n";
        out << "  kd " << vec(m.kd) << "\n"
            << "  ks " << vec(m.ks) << "\n"
            << "  shininess " << number(m.shininess) << "\n"
            << "  texture " << quote(str(m.texture)) << "\n"
            << "  tint " << number(m.tint) << "\n"
            << "  reflectivity " << number(m.reflectivity) << "\n"
            << "  transparency " << number(m.transparency) << "\n"
            << "  refractive_index " << number(m.refractive_index) << "\n"
            << "  dynamics " << boolean(m.dynamics) << "\n"
            << "  gravity " << boolean(m.gravity) << "\n"
            << "  mass " << number(m.mass) << "\n"
            << "  velocity " << vec(m.initial_velocity) << "\n";
        // Rigid-body settings (ABI 1.3); a shorter view has the defaults.
        const bool body = ANI_MODEL_DESC_HAS_BODY(&m);
        out << "  restitution " << number(body ? m.restitution : 1.0) << "\n"
            << "  friction " << number(body ? m.friction : 0.0) << "\n"
            << "  rotates " << boolean(body ? m.rotates : 0) << "\n"
            << "  angular_velocity " << vec(body ? m.angular_velocity : ani_vec3{0.0, 0.0, 0.0}) << "\n"
            << "  collision_sound " << quote(str(m.collision_sound)) << "\n"
            << "  moving_sound " << quote(str(m.moving_sound)) << "\n";
        if (ANI_MODEL_DESC_HAS_SHAPE(&m)) {
            if (!identity(m.rest)) { // row by row
                out << "  rest";
                for (int r = 0; r < 3; ++r)
                    for (int c = 0; c < 3; ++c) out << " " << number(m.rest[3 * c + r]);
                out << "\n";
            }
            if (m.has_joint)
                out << "  joint x " << number(m.joint_min.x) << " " << number(m.joint_max.x) << " y "
                    << number(m.joint_min.y) << " " << number(m.joint_max.y) << " z " << number(m.joint_min.z)
                    << " " << number(m.joint_max.z) << "\n";
        }
        out << "end\n";
    }

    for (uint32_t k = 0; k < doc.keyframe_count; ++k) {
        const ani_keyframe_view &kf = doc.keyframes[k];
        const ani_quat &q = kf.camera.rotation;
        out << "\nkeyframe " << kf.time_ms << "\n";
        if (kf.camera_keyed)
            out << "  camera position " << vec(kf.camera.position) << " rotation " << number(q.w) << " "
                << number(q.x) << " " << number(q.y) << " " << number(q.z) << " fov "
                << number(kf.camera.fov_degrees) << "\n";
        for (uint32_t m = 0; m < doc.model_count; ++m) {
            if (!kf.keyed[m]) continue;
            const ani_model_state &st = kf.states[m];
            out << "  state " << quote(str(doc.models[m].name)) << " center " << vec(st.center)
                << " angles " << vec(st.angles) << " scale " << vec(st.scale) << " turn "
                << vec(st.turn) << "\n";
        }
        out << "end\n";
    }
    return out.str();
}

// The line of `text` longer than the reader takes, or 0: a name or a string of more than 1 MiB.
size_t first_long_line(const std::string &text) {
    size_t line = 1;
    for (size_t start = 0; start < text.size(); ++line) {
        size_t end = text.find('\n', start);
        if (end == std::string::npos) end = text.size();
        if (end - start > kMaxLineBytes) return line;
        start = end + 1;
    }
    return 0;
}

} // namespace

bool write_ani(const char *path, const ani_document_view &doc, std::string &error) {
    // Nothing is written that the reader would refuse (ani_text.hpp).
    const std::string why = size_beyond_limits(doc.model_count, doc.keyframe_count, doc.param_count);
    if (!why.empty()) {
        error = "the document is too large for an .ani file: " + why;
        return false;
    }
    const std::string text = to_text(doc);
    if (const size_t line = first_long_line(text)) {
        error = "line " + std::to_string(line) + " would be longer than the " +
                std::to_string(kMaxLineBytes) + " bytes a reader takes (a name or string that long?)";
        return false;
    }
    std::string tmp = std::string(path) + ".tmp-XXXXXX";
    const int fd = mkstemp(tmp.data());
    if (fd < 0) {
        error = std::string("cannot create a temporary file beside it: ") + std::strerror(errno);
        return false;
    }
    auto give_up = [&](const char *what) {
        error = std::string(what) + ": " + std::strerror(errno) + " (the previous file is unchanged)";
        close(fd);
        unlink(tmp.c_str());
        return false;
    };
    // mkstemp makes the file 0600; a saved animation is as readable as any other file.
    const mode_t mask = umask(0);
    umask(mask);
    if (fchmod(fd, 0666 & ~mask) != 0) return give_up("cannot set the file's permissions");
    size_t done = 0;
    while (done < text.size()) {
        const ssize_t n = write(fd, text.data() + done, text.size() - done);
        if (n < 0) {
            if (errno == EINTR) continue;
            return give_up("cannot write");
        }
        done += static_cast<size_t>(n);
    }
    if (fsync(fd) != 0) return give_up("cannot flush to disk");
    if (close(fd) != 0) {
        error = std::string("cannot close: ") + std::strerror(errno) + " (the previous file is unchanged)";
        unlink(tmp.c_str());
        return false;
    }
    if (rename(tmp.c_str(), path) != 0) {
        error = std::string("cannot replace the file: ") + std::strerror(errno) +
                " (the previous file is unchanged)";
        unlink(tmp.c_str());
        return false;
    }
    return true;
}

} // namespace ani_format
