#include "support.hpp"

#include <cstdio>
#include <fstream>
#include <sstream>
#include <sys/wait.h>
#include <unistd.h>

namespace fs = std::filesystem;

namespace animator::test {

fs::path bin_dir() { return ANIMATOR_BIN_DIR; }
fs::path source_dir() { return ANIMATOR_SOURCE_DIR; }

fs::path fresh_dir(const std::string &name) {
    // One per process: ctest runs the cases of one file as parallel processes, and two of them
    // wiping and filling the same folder broke each other (motion_paths_test, under ctest -j2).
    const fs::path dir =
        fs::path(ANIMATOR_TEST_TMP_DIR) / (name + "." + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

CommandResult run_animator(const std::string &args, const std::string &env) {
    const std::string command =
        (env.empty() ? "" : env + " ") + (bin_dir() / "animator").string() + " " + args + " 2>&1";
    CommandResult result;
    FILE *pipe = popen(command.c_str(), "r");
    if (!pipe) return result;
    char buf[4096];
    size_t n;
    while ((n = fread(buf, 1, sizeof buf, pipe)) > 0) result.out.append(buf, n);
    const int status = pclose(pipe);
    result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return result;
}

std::string read_file(const fs::path &path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream out;
    out << in.rdbuf();
    return out.str();
}

size_t count_in(const std::string &text, const std::string &needle) {
    size_t n = 0;
    for (size_t at = text.find(needle); at != std::string::npos; at = text.find(needle, at + 1)) ++n;
    return n;
}

void write_file(const fs::path &path, const std::string &text) {
    std::ofstream(path, std::ios::binary) << text;
}

Document random_document(std::mt19937 &rng, int models, int keyframes) {
    std::uniform_real_distribution<double> any(-1e3, 1e3), unit(0.0, 1.0), angle(0.0, 359.999),
        positive(0.01, 100.0);
    auto vec = [&] { return glm::dvec3(any(rng), any(rng), any(rng)); };
    auto colour = [&] { return glm::dvec3(unit(rng), unit(rng), unit(rng)); };
    auto state = [&] {
        ModelState s;
        s.center = vec();
        s.angles = glm::dvec3(angle(rng), angle(rng), angle(rng));
        s.scale = glm::dvec3(positive(rng), positive(rng), positive(rng));
        s.turn = glm::dvec3(any(rng), 0.0, -any(rng));
        return s;
    };
    auto camera = [&] {
        CameraState c;
        c.position = vec();
        c.rotation = glm::normalize(glm::dquat(any(rng), any(rng), any(rng), any(rng)));
        c.fov_degrees = 10.0 + 100.0 * unit(rng);
        return c;
    };

    Document doc;
    Settings s;
    s.max_time_ms = 1000 + static_cast<std::int64_t>(unit(rng) * 1e6) + keyframes * 1000;
    s.gravity = positive(rng);
    s.down_axis = static_cast<Axis>(rng() % 3);
    s.cel_shading = rng() % 2;
    s.skybox = rng() % 2 ? "sunset" : "";
    s.physics_backend = rng() % 2 ? "physics.custom" : "physics.bullet";
    s.interpolation = rng() % 2 ? "interpolation.linear" : "interpolation.smooth";
    s.params["physics.bullet"]["step"] = {1.0 / 240.0, 0.0, 0.0, 0.0};
    s.params["shading.phong"]["cel_outline_colour"] = {unit(rng), unit(rng), unit(rng), 1.0};
    // Version 2's keys in documents of 3 models or more (smaller ones stay version 1 files).
    const bool scene_keys = models >= 3;
    if (scene_keys) {
        for (int l = 0, n = static_cast<int>(rng() % (Settings::kMaxLights + 1)); l < n; ++l)
            s.lights.push_back(Light{"light " + std::to_string(l), vec(), 2.0 * colour(),
                                     glm::dvec3(1.0 + unit(rng), unit(rng), unit(rng))});
        s.ambient = colour();
        s.render_output = rng() % 2 ? "out \"still\".png" : "";
        s.render_width = static_cast<int>(rng() % 4000);
        s.render_height = static_cast<int>(rng() % 4000);
    }
    doc.set_settings(s);
    for (int i = 0; i < models; ++i) {
        Model m;
        m.name = "model \"" + std::to_string(i) + "\" \\ é";
        m.mesh = i % 2 ? "sphere" : "meshes/odd name.obj";
        m.parent = i > 0 && rng() % 3 == 0 ? static_cast<int>(rng() % static_cast<unsigned>(i)) : -1;
        m.material.kd = colour();
        m.material.ks = colour();
        m.material.shininess = positive(rng);
        m.texture = rng() % 2 ? "checker" : "";
        m.tint = unit(rng);
        m.reflectivity = unit(rng);
        m.transparency = unit(rng);
        m.refractive_index = 1.0 + unit(rng);
        m.dynamics = rng() % 2;
        m.gravity = rng() % 2;
        m.mass = positive(rng);
        m.initial_velocity = vec();
        m.restitution = unit(rng);
        m.friction = positive(rng);
        m.rotates = rng() % 2;
        m.angular_velocity = vec();
        m.collision_sound = rng() % 2 ? "click" : "";
        m.moving_sound = rng() % 2 ? "hum" : "";
        if (scene_keys && rng() % 2) {
            m.material.kd *= 3.0; // colours above 1 (the course allowed them)
            m.rest[1][0] = any(rng) / 1e3; // a shear keeps the determinant 1
            m.rest[2][1] = any(rng) / 1e3;
            m.joint = JointRange{glm::dvec3(-unit(rng) * 180.0, 0.0, -1.0), glm::dvec3(unit(rng) * 180.0, 0.0, 1.0)};
        }
        doc.add_model(m, state());
    }
    doc.set_camera(0, camera());
    std::int64_t t = 0;
    for (int k = 1; k < keyframes; ++k) {
        t += 1 + static_cast<std::int64_t>(rng() % 1000);
        // Later keyframes key a random part of the models and sometimes the camera.
        Keyframe kf;
        kf.time_ms = t;
        if (rng() % 2) kf.camera = camera();
        for (int i = 0; i < models; ++i)
            kf.states.push_back(rng() % 3 ? std::optional<ModelState>(state()) : std::nullopt);
        doc.insert_keyframe(kf);
    }
    return doc;
}

} // namespace animator::test
