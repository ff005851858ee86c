// One live instance of a plugin: created through its kind's instance interface, destroyed with
// the object. Parameter values are checked against the plugin's descriptors before they reach
// the plugin.
#pragma once

#include "plugin/registry.hpp"

#include <animator/instance.h>

#include <array>
#include <memory>
#include <stdexcept>
#include <string>

namespace animator {

// A plugin failed or refused something; the message names the plugin.
struct PluginError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

class PluginInstance {
  public:
    // Throws PluginError when the plugin cannot create an instance.
    PluginInstance(const PluginInfo &info, const ani_host *host);
    ~PluginInstance();
    PluginInstance(const PluginInstance &) = delete;
    PluginInstance &operator=(const PluginInstance &) = delete;

    const PluginInfo &info() const { return *info_; }
    void *handle() const { return handle_; }
    // The kind's interface, e.g. api<ani_physics_api>(); the caller knows the kind.
    template <class Api> const Api &api() const { return *static_cast<const Api *>(info_->descriptor->api); }

    // Throws PluginError for an unknown id, an invalid value, or the plugin's refusal.
    void set_param(const std::string &id, const std::array<double, 4> &value);
    std::array<double, 4> get_param(const std::string &id) const;
    const ani_param_descriptor *find_param(const std::string &id) const;

  private:
    const ani_instance_api &instance_api() const;
    const PluginInfo *info_;
    void *handle_ = nullptr;
};

} // namespace animator
