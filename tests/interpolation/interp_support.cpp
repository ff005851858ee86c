#include "interp_support.hpp"

#include "support.hpp"

#include <catch2/catch.hpp>

namespace interp_test {

ani_key key(double time, std::array<double, 4> value, std::array<double, 4> turn) {
    ani_key k{};
    k.time = time;
    for (size_t c = 0; c < 4; ++c) {
        k.value[c] = value[c];
        k.turn[c] = turn[c];
    }
    return k;
}

ani_channel channel(ani_channel_kind kind, const std::vector<ani_key> &keys,
                    std::array<double, 4> initial_rate) {
    ani_channel c{};
    c.struct_size = sizeof(ani_channel);
    c.kind = kind;
    c.keys = keys.data();
    c.key_count = static_cast<uint32_t>(keys.size());
    for (size_t i = 0; i < 4; ++i) c.initial_rate[i] = initial_rate[i];
    return c;
}

Interpolator::Interpolator(const std::string &id)
    : registry_({animator::test::bin_dir()},
                [](ani_log_level, const std::string &, const std::string &) {}) {
    const animator::PluginInfo *info = registry_.find(id);
    INFO("plugin " << id << " in " << animator::test::bin_dir());
    REQUIRE(info != nullptr);
    REQUIRE(info->kind == ANI_KIND_INTERPOLATOR);
    instance_ = std::make_unique<animator::PluginInstance>(*info, registry_.host());
}

Evaluation Interpolator::evaluate(const ani_channel &channel, const std::vector<double> &times) const {
    Evaluation out;
    out.values.assign(4 * times.size(), -1.0);
    out.rates.assign(4 * times.size(), -1.0);
    ani_status status{};
    out.code = api().evaluate(instance_->handle(), &channel, times.data(),
                              static_cast<uint32_t>(times.size()), out.values.data(),
                              out.rates.data(), &status);
    out.message = status.message;
    return out;
}

std::vector<double> linspace(double from, double to, int steps) {
    std::vector<double> out;
    for (int i = 0; i <= steps; ++i) out.push_back(from + (to - from) * i / steps);
    return out;
}

} // namespace interp_test
