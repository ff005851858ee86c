#include "channel_check.hpp"

#include <animator/plugin_cpp.hpp>

#include <cmath>
#include <sstream>

namespace interp {

namespace {

[[noreturn]] void fail(const char *plugin_id, const std::string &message) {
    throw ani::Failure(ANI_ERR_INVALID_ARGUMENT, std::string(plugin_id) + ": " + message);
}

std::string number(double x) {
    std::ostringstream out;
    out.precision(17);
    out << x;
    return out.str();
}

std::string handled_kinds(uint32_t mask) {
    std::string out;
    for (int32_t kind = ANI_CHANNEL_POSITION; kind <= ANI_CHANNEL_CAMERA_ROTATION; ++kind) {
        if (!(mask & (1u << kind))) continue;
        if (!out.empty()) out += ", ";
        out += channel_kind_name(kind);
    }
    return out;
}

// A quaternion this far from unit length is not a rotation the host meant; closer ones are
// rounding, which slerp normalises away.
constexpr double kUnitTolerance = 1e-4;

} // namespace

const char *channel_kind_name(int32_t kind) {
    switch (kind) {
    case ANI_CHANNEL_POSITION: return "position";
    case ANI_CHANNEL_ANGLES: return "angles";
    case ANI_CHANNEL_SCALE: return "scale";
    case ANI_CHANNEL_CAMERA_POSITION: return "camera position";
    case ANI_CHANNEL_CAMERA_ROTATION: return "camera rotation";
    default: return "unknown";
    }
}

int channel_components(int32_t kind) { return kind == ANI_CHANNEL_CAMERA_ROTATION ? 4 : 3; }

void check_channel(const char *plugin_id, const ani_channel *channel,
                   uint32_t handled_mask, bool uses_initial_rate) {
    if (channel == nullptr) fail(plugin_id, "the channel is null");
    if (channel->struct_size < sizeof(ani_channel))
        throw ani::Failure(ANI_ERR_VERSION, std::string(plugin_id) + ": the channel has size " +
                                                std::to_string(channel->struct_size) +
                                                ", smaller than the " +
                                                std::to_string(sizeof(ani_channel)) + " it needs");
    const int32_t kind = channel->kind;
    const bool known = kind >= ANI_CHANNEL_POSITION && kind <= ANI_CHANNEL_CAMERA_ROTATION;
    if (!known || !(handled_mask & (1u << kind)))
        fail(plugin_id, std::string("it does not handle channel kind ") + std::to_string(kind) +
                            " (" + channel_kind_name(kind) + "); it handles " +
                            handled_kinds(handled_mask));
    if (channel->key_count == 0) fail(plugin_id, "the channel has no key; it needs at least one");
    if (channel->keys == nullptr) fail(plugin_id, "the channel's keys are null");

    const int components = channel_components(kind);
    const ani_key *keys = channel->keys;
    for (uint32_t k = 0; k < channel->key_count; ++k) {
        // Named only in a message: evaluated for every model at every bake, the checks make no
        // string when nothing is wrong.
        const auto key = [k] { return "key " + std::to_string(k); };
        if (!std::isfinite(keys[k].time))
            fail(plugin_id, key() + " has a time that is not finite (" + number(keys[k].time) + ")");
        if (k > 0) {
            if (!(keys[k].time > keys[k - 1].time))
                fail(plugin_id, key() + " has time " + number(keys[k].time) + ", not after key " +
                                    std::to_string(k - 1) + "'s " + number(keys[k - 1].time) +
                                    ": key times must increase strictly");
            if (!std::isfinite(keys[k].time - keys[k - 1].time))
                fail(plugin_id, key() + " is too far in time from key " + std::to_string(k - 1));
        }
        for (int c = 0; c < components; ++c) {
            if (!std::isfinite(keys[k].value[c]))
                fail(plugin_id, key() + " has value[" + std::to_string(c) +
                                    "] that is not finite (" + number(keys[k].value[c]) + ")");
            if (kind == ANI_CHANNEL_ANGLES && !std::isfinite(keys[k].turn[c]))
                fail(plugin_id, key() + " has turn[" + std::to_string(c) + "] that is not finite");
        }
        if (kind == ANI_CHANNEL_CAMERA_ROTATION) {
            const double *q = keys[k].value;
            const double n = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
            if (!(std::fabs(n - 1.0) <= kUnitTolerance))
                fail(plugin_id, key() + " is not a unit quaternion (its length is " + number(n) + ")");
        }
    }
    if (uses_initial_rate)
        for (int c = 0; c < components; ++c)
            if (!std::isfinite(channel->initial_rate[c]))
                fail(plugin_id, "initial_rate[" + std::to_string(c) + "] is not finite");
}

void check_times(const char *plugin_id, const double *times, uint32_t count,
                 const double *values, const double *rates) {
    if (count == 0) return;
    if (times == nullptr) fail(plugin_id, "times is null");
    if (values == nullptr) fail(plugin_id, "values is null");
    if (rates == nullptr) fail(plugin_id, "rates is null");
    for (uint32_t i = 0; i < count; ++i) {
        if (!std::isfinite(times[i]))
            fail(plugin_id, "time " + std::to_string(i) + " is not finite (" + number(times[i]) + ")");
        if (i > 0 && times[i] < times[i - 1])
            fail(plugin_id, "time " + std::to_string(i) + " (" + number(times[i]) +
                                ") comes before time " + std::to_string(i - 1) + " (" +
                                number(times[i - 1]) + "): times must be in increasing order");
    }
}

void check_outputs(const char *plugin_id, const double *values, const double *rates,
                   uint32_t count) {
    for (size_t i = 0; i < 4 * static_cast<size_t>(count); ++i)
        if (!std::isfinite(values[i]) || !std::isfinite(rates[i]))
            fail(plugin_id, "the channel's numbers are too large: interpolating them at time " +
                                std::to_string(i / 4) + " overflows");
}

} // namespace interp
