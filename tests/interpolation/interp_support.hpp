// Shared by the interpolation tests: an interpolator plugin loaded through the host exactly as
// the program loads it, channels and keys built in one line, and evaluation into vectors.
#pragma once

#include "plugin/instance.hpp"
#include "plugin/registry.hpp"

#include <animator/interpolator.h>
#include <catch2/catch.hpp>

#include <array>
#include <memory>
#include <string>
#include <vector>

namespace interp_test {

ani_key key(double time, std::array<double, 4> value, std::array<double, 4> turn = {0, 0, 0, 0});

// A channel over `keys` (which must outlive it).
ani_channel channel(ani_channel_kind kind, const std::vector<ani_key> &keys,
                    std::array<double, 4> initial_rate = {0, 0, 0, 0});

struct Evaluation {
    ani_status_code code = ANI_OK;
    std::string message;
    std::vector<double> values; // 4 per time
    std::vector<double> rates;  // 4 per time
    double value(size_t i, int c) const { return values[4 * i + static_cast<size_t>(c)]; }
    double rate(size_t i, int c) const { return rates[4 * i + static_cast<size_t>(c)]; }
};

class Interpolator {
  public:
    // Loads plugin `id` from the build's plugin folder; REQUIREs that it is found.
    explicit Interpolator(const std::string &id);
    const ani_interpolator_api &api() const { return instance_->api<ani_interpolator_api>(); }
    animator::PluginInstance &instance() { return *instance_; }
    void set_param(const std::string &id, double value) { instance_->set_param(id, {value, 0, 0, 0}); }

    Evaluation evaluate(const ani_channel &channel, const std::vector<double> &times) const;
    // One time alone.
    Evaluation at(const ani_channel &channel, double time) const { return evaluate(channel, {time}); }

  private:
    animator::PluginRegistry registry_;
    std::unique_ptr<animator::PluginInstance> instance_;
};

// x within an absolute `margin` (Catch's Approx, without its default relative slack).
inline Approx close(double x, double margin = 1e-12) { return Approx(x).epsilon(0.0).margin(margin); }

// Times from `from` to `to` in `steps` equal steps (steps + 1 times).
std::vector<double> linspace(double from, double to, int steps);

} // namespace interp_test
