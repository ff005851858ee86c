// What a scene must keep for a bake to go on with it (event_bake.hpp, BakeInProgress): the host
// builds the scene anew for every bake call, so a slice that continues a bake is recognised by
// comparing what the bake depends on: the models, their meshes, physics flags, keyed spans, key
// times and the states at their keys, and gravity.
#pragma once

#include <animator/physics.h>

#include <array>
#include <cstdint>
#include <functional>

namespace physics_custom {

// All of it, model after model, folded into hashes as it is read (nothing kept: the numbers of
// a gas of 100,000 balls took 25 MB, written at every bake's start, a tenth of the bake's time at
// that size; docs/performance.md, the gas), with how many numbers went in. The words are dealt to
// four lanes in turn, each lane two 64-bit hashes (a word goes into both of its lane's), a block
// of words at a time with the lanes held in registers, so that eight chains of multiplications
// run side by side (two chains, word after word through memory, took 3.7% of a bake of 100,000
// balls). Two prints of different scenes are equal only if both hashes of a lane collide at once
// (about 2^-128 for unrelated numbers; not a defence against a scene made to collide).
class ScenePrint {
  public:
    static constexpr int kLanes = 4;
    ScenePrint();
    // Adds a number (0 and -0 alike, as == has them; a NaN makes the print equal to no other)
    // and an address (a mesh and its positions: the same view is the same mesh).
    void add(double x);
    void add(const void *p);
    void unknowable() { unknown_ = true; } // a key that could not be evaluated
    // A key that could not be evaluated, or a number that is NaN: equal to no other print.
    bool unknown() const { return unknown_; }
    // Two prints of everything added.
    bool operator==(const ScenePrint &o) const;
    bool operator!=(const ScenePrint &o) const { return !(*this == o); }

  private:
    static constexpr int kBlock = 64;
    void add_word(uint64_t w) {
        words_[filled_++] = w;
        if (filled_ == kBlock) fold();
    }
    void fold(); // the words waiting into the lanes
    std::array<uint64_t, kLanes> a_{}, b_{};
    uint64_t count_ = 0; // words folded
    bool unknown_ = false;
    int filled_ = 0;
    std::array<uint64_t, kBlock> words_{};
};

// The keys' state of model m at t and their velocity there, or false when they cannot say.
using KeyedEvaluator = std::function<bool(uint32_t m, double t, ani_model_state &, ani_vec3 &)>;

// A key that cannot be evaluated makes a print equal to no other (the bake starts anew). Keys are
// evaluated by the scene's evaluate_keyed, or by `evaluate` when given.
ScenePrint scene_print(const ani_physics_scene &scene, const KeyedEvaluator &evaluate = {});

// The same print made a part at a time, its models in order (a gas's is made by the lane's
// reporting thread while it waits: sink_aside.hpp). The scene's keys are evaluated by its
// evaluate_keyed ([thread: any]).
class ScenePrinter {
  public:
    explicit ScenePrinter(const ani_physics_scene &scene);
    // Adds the next `models` models (or as many as are left); true once every model is in.
    bool step(uint32_t models);
    bool done() const { return next_ == scene_->model_count; }
    const ScenePrint &print() const { return print_; }

  private:
    const ani_physics_scene *scene_;
    ScenePrint print_;
    uint32_t next_ = 0;
};

} // namespace physics_custom
