#include "scene_print.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstring>

namespace physics_custom {

namespace {
// xxHash64's round (a multiply-rotate-multiply of every word), in two accumulators started from
// different seeds, the second also taking each word's place in the stream.
constexpr uint64_t kPrime1 = 0x9e3779b185ebca87ull, kPrime2 = 0xc2b2ae3d27d4eb4full;
uint64_t mix(uint64_t acc, uint64_t w) {
    acc += w * kPrime2;
    acc = (acc << 31) | (acc >> 33);
    return acc * kPrime1;
}
} // namespace

// Each lane starts from its own pair of unrelated values.
ScenePrint::ScenePrint() {
    uint64_t sa = 0x60ea27eeadc0b5d6ull, sb = 0x61c8864e7a143579ull;
    for (std::size_t k = 0; k < kLanes; ++k) {
        a_[k] = sa = mix(sa, k + 1);
        b_[k] = sb = mix(sb, k + 1);
    }
}

// Word i of the stream goes to lane i mod 4: into a as it is, into b with its place mixed in.
void ScenePrint::fold() {
    uint64_t a0 = a_[0], a1 = a_[1], a2 = a_[2], a3 = a_[3];
    uint64_t b0 = b_[0], b1 = b_[1], b2 = b_[2], b3 = b_[3];
    const std::size_t n = static_cast<std::size_t>(filled_);
    std::size_t i = 0;
    uint64_t at = count_;
    for (; i + kLanes <= n; i += kLanes, at += kLanes) {
        a0 = mix(a0, words_[i]);
        b0 = mix(b0, words_[i] ^ (at * kPrime1));
        a1 = mix(a1, words_[i + 1]);
        b1 = mix(b1, words_[i + 1] ^ ((at + 1) * kPrime1));
        a2 = mix(a2, words_[i + 2]);
        b2 = mix(b2, words_[i + 2] ^ ((at + 2) * kPrime1));
        a3 = mix(a3, words_[i + 3]);
        b3 = mix(b3, words_[i + 3] ^ ((at + 3) * kPrime1));
    }
    a_ = {a0, a1, a2, a3};
    b_ = {b0, b1, b2, b3};
    for (; i < n; ++i, ++at) { // (only at the end: a block is a whole number of turns)
        const std::size_t k = static_cast<std::size_t>(at % kLanes);
        a_[k] = mix(a_[k], words_[i]);
        b_[k] = mix(b_[k], words_[i] ^ (at * kPrime1));
    }
    count_ = at;
    filled_ = 0;
}

bool ScenePrint::operator==(const ScenePrint &o) const {
    ScenePrint x = *this, y = o;
    x.fold();
    y.fold();
    return !x.unknown_ && !y.unknown_ && x.a_ == y.a_ && x.b_ == y.b_ && x.count_ == y.count_;
}

void ScenePrint::add(double x) {
    if (std::isnan(x)) unknown_ = true;
    if (x == 0.0) x = 0.0; // -0 as 0
    uint64_t w = 0;
    std::memcpy(&w, &x, sizeof w);
    add_word(w);
}

void ScenePrint::add(const void *p) {
    add_word(static_cast<uint64_t>(reinterpret_cast<uintptr_t>(p)));
}

namespace {

void print_header(ScenePrint &print, const ani_physics_scene &scene) {
    print.add(scene.gravity);
    print.add(static_cast<double>(scene.down_axis));
    print.add(static_cast<double>(scene.model_count));
}

// Models [from, to) of the scene, in order.
void print_models(ScenePrint &print, const ani_physics_scene &scene, uint32_t from, uint32_t to,
                  const KeyedEvaluator &evaluate) {
    for (uint32_t i = from; i < to; ++i) {
        const ani_physics_model &m = scene.models[i];
        print.add(static_cast<const void *>(m.mesh));
        print.add(static_cast<const void *>(m.mesh ? m.mesh->positions : nullptr));
        print.add(m.mesh ? double(m.mesh->vertex_count) : -1.0);
        print.add(m.mesh ? double(m.mesh->triangle_count) : -1.0);
        print.add(m.group);
        if (m.desc) {
            print.add(double(m.desc->dynamics));
            print.add(double(m.desc->gravity));
            print.add(m.desc->mass);
            if (ANI_MODEL_DESC_HAS_BODY(m.desc)) {
                for (double x : {1.0, m.desc->restitution, m.desc->friction, double(m.desc->rotates),
                                 m.desc->angular_velocity.x, m.desc->angular_velocity.y,
                                 m.desc->angular_velocity.z})
                    print.add(x);
            } else {
                print.add(0.0);
            }
        } else {
            print.add(-1.0);
        }
        print.add(m.keyed_span_count);
        for (uint32_t k = 0; k < m.keyed_span_count; ++k) {
            print.add(m.keyed_spans[k].begin);
            print.add(m.keyed_spans[k].end);
        }
        const bool has_keys =
            m.struct_size >= offsetof(ani_physics_model, key_count) + sizeof(m.key_count) &&
            m.key_times;
        print.add(has_keys ? m.key_count : 0);
        for (uint32_t k = 0; has_keys && k < m.key_count; ++k) {
            print.add(m.key_times[k]);
            ani_model_state s{};
            ani_vec3 v{};
            const bool known = evaluate ? evaluate(i, m.key_times[k], s, v)
                                        : scene.evaluate_keyed(scene.host_context, i,
                                                               m.key_times[k], &s, &v) == ANI_OK;
            if (!known) print.unknowable(); // equal to nothing
            for (double x : {s.center.x, s.center.y, s.center.z, s.angles.x, s.angles.y, s.angles.z,
                             s.scale.x, s.scale.y, s.scale.z, v.x, v.y, v.z})
                print.add(x);
        }
    }
}

} // namespace

ScenePrint scene_print(const ani_physics_scene &scene, const KeyedEvaluator &evaluate) {
    ScenePrint print;
    print_header(print, scene);
    print_models(print, scene, 0, scene.model_count, evaluate);
    return print;
}

ScenePrinter::ScenePrinter(const ani_physics_scene &scene) : scene_(&scene) {
    print_header(print_, scene);
}

bool ScenePrinter::step(uint32_t models) {
    const uint32_t to = next_ + std::min(models, scene_->model_count - next_);
    print_models(print_, *scene_, next_, to, {});
    next_ = to;
    return done();
}

} // namespace physics_custom
