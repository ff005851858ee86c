// animator plugin SDK: optional C++ helpers for writing a plugin in C++.
//
// Header-only, so nothing of the host's C++ crosses the boundary: each plugin library compiles
// its own copy. `guarded` turns exceptions into a status code plus message, as the ABI requires
// of every C++ entry point; `ParamStore` implements get_param/set_param over a plugin's
// parameter descriptors (`store_get_param`/`store_set_param` for an instance that holds one);
// `ANI_PLUGIN_ENTRY` defines the entry of a library that lists its plugins and needs no set-up.
#ifndef ANIMATOR_SDK_PLUGIN_CPP_HPP
#define ANIMATOR_SDK_PLUGIN_CPP_HPP

#include "animator/plugin.h"

#include <cstring>
#include <exception>
#include <new>
#include <string>
#include <vector>

namespace ani {

// Thrown inside a plugin to fail with a particular status code.
struct Failure : std::exception {
    Failure(ani_status_code c, std::string m) : code(c), message(std::move(m)) {}
    const char *what() const noexcept override { return message.c_str(); }
    ani_status_code code;
    std::string message;
};

inline ani_status_code set_status(ani_status *status, ani_status_code code, const char *message) {
    return ani_status_set(status, code, message);
}
inline ani_status_code set_status(ani_status *status, ani_status_code code,
                                  const std::string &message) {
    return ani_status_set(status, code, message.c_str());
}

// Runs fn(); returns ANI_OK, or the failure it threw as a status.
template <class Fn> ani_status_code guarded(ani_status *status, Fn &&fn) noexcept {
    try {
        fn();
        return set_status(status, ANI_OK, "");
    } catch (const Failure &f) {
        return set_status(status, f.code, f.message);
    } catch (const std::bad_alloc &) {
        return set_status(status, ANI_ERR_OUT_OF_MEMORY, "out of memory");
    } catch (const std::exception &e) {
        return set_status(status, ANI_ERR_FAILED, e.what());
    } catch (...) {
        return set_status(status, ANI_ERR_FAILED, "unknown error");
    }
}

// get_param and set_param for a plugin without parameters: every id is unknown. PluginId is a
// namespace-scope `constexpr char kId[] = "format.ani";`.
template <const char *PluginId>
ani_status_code no_param_get(void *, const char *id, ani_param_value *, ani_status *status) {
    return set_status(status, ANI_ERR_UNKNOWN_PARAM,
                      std::string(PluginId) + " has no parameter '" + (id ? id : "") + "'");
}
template <const char *PluginId>
ani_status_code no_param_set(void *, const char *id, const ani_param_value *, ani_status *status) {
    return no_param_get<PluginId>(nullptr, id, nullptr, status);
}

// The current values of a plugin instance's parameters, starting at their defaults.
class ParamStore {
  public:
    ParamStore(const ani_param_descriptor *params, uint32_t count) : params_(params, params + count) {
        for (const auto &p : params_) values_.push_back(p.default_value);
    }

    ani_status_code get(const char *id, ani_param_value *out, ani_status *status) const {
        const int i = index_of(id);
        if (i < 0) return unknown(id, status);
        *out = values_[static_cast<size_t>(i)];
        return set_status(status, ANI_OK, "");
    }

    ani_status_code set(const char *id, const ani_param_value *value, ani_status *status) {
        const int i = index_of(id);
        if (i < 0) return unknown(id, status);
        values_[static_cast<size_t>(i)] = *value;
        return set_status(status, ANI_OK, "");
    }

    double number(const char *id) const {
        const int i = index_of(id);
        if (i < 0) throw Failure(ANI_ERR_UNKNOWN_PARAM, std::string("no parameter '") + id + "'");
        return values_[static_cast<size_t>(i)].value[0];
    }

  private:
    int index_of(const char *id) const {
        if (id == nullptr) return -1;
        for (size_t i = 0; i < params_.size(); ++i)
            if (std::strcmp(params_[i].id, id) == 0) return static_cast<int>(i);
        return -1;
    }
    static ani_status_code unknown(const char *id, ani_status *status) {
        return set_status(status, ANI_ERR_UNKNOWN_PARAM,
                          std::string("no parameter '") + (id ? id : "(null)") + "'");
    }

    std::vector<ani_param_descriptor> params_;
    std::vector<ani_param_value> values_;
};

// get_param and set_param for an instance type whose `params` member is a ParamStore.
template <class Instance>
ani_status_code store_get_param(void *instance, const char *id, ani_param_value *value, ani_status *status) {
    if (instance == nullptr || value == nullptr)
        return set_status(status, ANI_ERR_INVALID_ARGUMENT, "get_param: null instance or value");
    return static_cast<const Instance *>(instance)->params.get(id, value, status);
}
template <class Instance>
ani_status_code store_set_param(void *instance, const char *id, const ani_param_value *value, ani_status *status) {
    if (instance == nullptr || value == nullptr)
        return set_status(status, ANI_ERR_INVALID_ARGUMENT, "set_param: null instance or value");
    return static_cast<Instance *>(instance)->params.set(id, value, status);
}

// The parts of an entry for a library whose plugins are a fixed list and that needs no set-up.
template <const ani_plugin_descriptor *const *List, uint32_t Count> struct ListedPlugins {
    static ani_status_code init(const ani_host *, ani_status *status) { return set_status(status, ANI_OK, ""); }
    static void deinit() {}
    static uint32_t count() { return Count; }
    static const ani_plugin_descriptor *get(uint32_t index) { return index < Count ? List[index] : nullptr; }
};

} // namespace ani

// Defines the library's entry from a namespace-scope array of descriptor pointers, e.g.
//   const ani_plugin_descriptor *const kPlugins[] = {&descriptor};
//   ANI_PLUGIN_ENTRY(kPlugins)
#define ANI_PLUGIN_ENTRY(list)                                                                     \
    extern "C" {                                                                                   \
    ANI_DECLARE_ENTRY;                                                                             \
    const ani_plugin_entry animator_plugin_entry = {                                              \
        sizeof(ani_plugin_entry),                                                                  \
        {ANI_ABI_MAJOR, ANI_ABI_MINOR, 0},                                                         \
        ani::ListedPlugins<list, sizeof(list) / sizeof(list[0])>::init,                           \
        ani::ListedPlugins<list, sizeof(list) / sizeof(list[0])>::deinit,                         \
        ani::ListedPlugins<list, sizeof(list) / sizeof(list[0])>::count,                          \
        ani::ListedPlugins<list, sizeof(list) / sizeof(list[0])>::get,                            \
    };                                                                                             \
    }

#endif // ANIMATOR_SDK_PLUGIN_CPP_HPP
