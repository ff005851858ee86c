#include "plugin/instance.hpp"

#include "plugin/descriptor_check.hpp"

#include <cstring>

namespace animator {

const ani_instance_api &PluginInstance::instance_api() const {
    // Every kind's interface starts with struct_size then the ani_instance_api; the descriptor
    // check verified the sizes when the library was opened.
    struct Prefix {
        uint32_t struct_size;
        ani_instance_api instance;
    };
    return static_cast<const Prefix *>(info_->descriptor->api)->instance;
}

PluginInstance::PluginInstance(const PluginInfo &info, const ani_host *host) : info_(&info) {
    ani_status status{};
    handle_ = instance_api().create(host, &status);
    if (!handle_)
        throw PluginError("plugin '" + info.id + "' could not create an instance: " + status.message);
}

PluginInstance::~PluginInstance() {
    if (handle_) instance_api().destroy(handle_);
}

const ani_param_descriptor *PluginInstance::find_param(const std::string &id) const {
    const ani_plugin_descriptor &d = *info_->descriptor;
    for (uint32_t i = 0; i < d.param_count; ++i)
        if (id == d.params[i].id) return &d.params[i];
    return nullptr;
}

void PluginInstance::set_param(const std::string &id, const std::array<double, 4> &value) {
    const ani_param_descriptor *param = find_param(id);
    if (!param) throw PluginError("plugin '" + info_->id + "' has no parameter '" + id + "'");
    ani_param_value v{};
    std::memcpy(v.value, value.data(), sizeof v.value);
    if (auto problem = check_param_value(*param, v); !problem.empty())
        throw PluginError("parameter '" + id + "' of plugin '" + info_->id + "': " + problem);
    ani_status status{};
    if (instance_api().set_param(handle_, id.c_str(), &v, &status) != ANI_OK)
        throw PluginError("plugin '" + info_->id + "' refused parameter '" + id + "': " + status.message);
}

std::array<double, 4> PluginInstance::get_param(const std::string &id) const {
    ani_param_value v{};
    ani_status status{};
    if (instance_api().get_param(handle_, id.c_str(), &v, &status) != ANI_OK)
        throw PluginError("plugin '" + info_->id + "': parameter '" + id + "': " + status.message);
    std::array<double, 4> out{};
    std::memcpy(out.data(), v.value, sizeof v.value);
    return out;
}

} // namespace animator
