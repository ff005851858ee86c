#include "plugin/descriptor_check.hpp"

#include <animator/file_format.h>
#include <animator/interpolator.h>
#include <animator/physics.h>
#include <animator/shading.h>

#include <cmath>
#include <set>
#include <sstream>

namespace animator {

namespace {

bool id_chars(std::string_view id, bool allow_dash) {
    for (char c : id) {
        const bool ok = (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_' || c == '.' ||
                        (allow_dash && c == '-');
        if (!ok) return false;
    }
    return true;
}

bool integral(double x) { return std::isfinite(x) && std::floor(x) == x; }

std::string check_instance_api(const ani_instance_api &api) {
    if (api.struct_size != sizeof(ani_instance_api))
        return "its instance interface has size " + std::to_string(api.struct_size) +
               ", expected " + std::to_string(sizeof(ani_instance_api));
    if (!api.create || !api.destroy || !api.get_param || !api.set_param)
        return "its instance interface lacks create, destroy, get_param or set_param";
    return "";
}

// The kind's interface must be exactly the size this host knows (the ABI check already refused
// newer minor versions) and have every function the kind needs.
template <class Api> std::string check_api_size(const void *api, const char *what) {
    const auto size = *static_cast<const uint32_t *>(api);
    if (size != sizeof(Api))
        return std::string("its ") + what + " interface has size " + std::to_string(size) +
               ", expected " + std::to_string(sizeof(Api));
    return check_instance_api(static_cast<const Api *>(api)->instance);
}

std::string check_kind_api(int kind, const void *api) {
    if (!api) return "it has no interface (api is null)";
    std::string problem;
    switch (kind) {
    case ANI_KIND_PHYSICS: {
        if (!(problem = check_api_size<ani_physics_api>(api, "physics")).empty()) return problem;
        if (!static_cast<const ani_physics_api *>(api)->bake) return "its physics interface lacks bake";
        return "";
    }
    case ANI_KIND_INTERPOLATOR: {
        if (!(problem = check_api_size<ani_interpolator_api>(api, "interpolator")).empty())
            return problem;
        const auto *a = static_cast<const ani_interpolator_api *>(api);
        if (!a->evaluate) return "its interpolator interface lacks evaluate";
        if (a->channel_mask == 0) return "its interpolator handles no channel kind";
        return "";
    }
    case ANI_KIND_SHADING: {
        if (!(problem = check_api_size<ani_shading_api>(api, "shading")).empty()) return problem;
        if (!static_cast<const ani_shading_api *>(api)->get_program)
            return "its shading interface lacks get_program";
        return "";
    }
    case ANI_KIND_FILE_FORMAT: {
        if (!(problem = check_api_size<ani_file_format_api>(api, "file format")).empty())
            return problem;
        const auto *a = static_cast<const ani_file_format_api *>(api);
        if (!(a->flags & (ANI_FORMAT_CAN_READ | ANI_FORMAT_CAN_WRITE)))
            return "its file format can neither read nor write";
        if ((a->flags & ANI_FORMAT_CAN_READ) && (!a->probe || !a->read || !a->release))
            return "its file format reads but lacks probe, read or release";
        if ((a->flags & ANI_FORMAT_CAN_WRITE) && !a->write)
            return "its file format writes but lacks write";
        if (a->extension_count == 0 || !a->extensions) return "its file format names no extension";
        for (uint32_t i = 0; i < a->extension_count; ++i)
            if (!a->extensions[i] || !a->extensions[i][0]) return "its file format has an empty extension";
        return "";
    }
    default:
        return "its kind " + std::to_string(kind) + " is not one of physics (1), interpolator (2), "
               "shading (3), file format (4)";
    }
}

} // namespace

bool valid_plugin_id(std::string_view id) {
    return id.size() >= 3 && id.size() <= 64 && id.find('.') != std::string_view::npos &&
           id.front() != '.' && id.back() != '.' && id_chars(id, true);
}

bool valid_param_id(std::string_view id) {
    return !id.empty() && id.size() <= 64 && id_chars(id, false);
}

const char *kind_name(int kind) {
    switch (kind) {
    case ANI_KIND_PHYSICS: return "physics";
    case ANI_KIND_INTERPOLATOR: return "interpolator";
    case ANI_KIND_SHADING: return "shading";
    case ANI_KIND_FILE_FORMAT: return "file_format";
    default: return "";
    }
}

int kind_from_name(std::string_view name) {
    for (int k = ANI_KIND_PHYSICS; k <= ANI_KIND_FILE_FORMAT; ++k)
        if (name == kind_name(k)) return k;
    return 0;
}

std::string check_param_descriptor(const ani_param_descriptor &p) {
    if (p.struct_size != sizeof(ani_param_descriptor))
        return "a parameter descriptor has size " + std::to_string(p.struct_size) + ", expected " +
               std::to_string(sizeof(ani_param_descriptor));
    if (!p.id || !valid_param_id(p.id))
        return std::string("parameter id '") + (p.id ? p.id : "(null)") +
               "' is not lower-case letters, digits, '_' and '.'";
    const std::string who = std::string("parameter '") + p.id + "'";
    if (!p.name || !p.name[0]) return who + " has no name";
    if (!std::isfinite(p.min_value) || !std::isfinite(p.max_value))
        return who + " has a min or max that is not finite";
    if (p.min_value > p.max_value) return who + " has min > max";
    if (!std::isfinite(p.step) || p.step < 0.0) return who + " has a step that is not finite and >= 0";
    for (double v : p.default_value.value)
        if (!std::isfinite(v)) return who + " has a default that is not finite";
    switch (p.kind) {
    case ANI_PARAM_FLOAT:
    case ANI_PARAM_ANGLE:
    case ANI_PARAM_TIME:
        break;
    case ANI_PARAM_INT:
        if (!integral(p.min_value) || !integral(p.max_value))
            return who + " is an integer with a min or max that is not an integer";
        break;
    case ANI_PARAM_BOOL:
        if (p.min_value != 0.0 || p.max_value != 1.0) return who + " is a bool whose range is not 0..1";
        break;
    case ANI_PARAM_ENUM:
        if (p.enum_count == 0 || !p.enum_labels) return who + " is an enum without labels";
        for (uint32_t i = 0; i < p.enum_count; ++i)
            if (!p.enum_labels[i] || !p.enum_labels[i][0]) return who + " has an empty enum label";
        if (p.min_value != 0.0 || p.max_value != static_cast<double>(p.enum_count - 1))
            return who + " is an enum whose range is not 0..enum_count-1";
        break;
    case ANI_PARAM_COLOUR:
        break;
    default:
        return who + " has an unknown kind " + std::to_string(p.kind);
    }
    if (auto problem = check_param_value(p, p.default_value); !problem.empty())
        return who + " has an invalid default: " + problem;
    return "";
}

std::string check_param_value(const ani_param_descriptor &p, const ani_param_value &value) {
    std::ostringstream out;
    const double v = value.value[0];
    if (p.kind == ANI_PARAM_COLOUR) {
        for (double c : value.value)
            if (!(c >= 0.0 && c <= 1.0)) return "colour components must be in [0, 1]";
        return "";
    }
    if (!std::isfinite(v)) return "the value is not a finite number";
    if ((p.kind == ANI_PARAM_INT || p.kind == ANI_PARAM_BOOL || p.kind == ANI_PARAM_ENUM) &&
        !integral(v)) {
        out << v << " is not a whole number";
        return out.str();
    }
    if (v < p.min_value || v > p.max_value) {
        out << v << " is outside " << p.min_value << " .. " << p.max_value;
        return out.str();
    }
    return "";
}

std::string check_plugin_descriptor(const ani_plugin_descriptor &d) {
    if (d.struct_size != sizeof(ani_plugin_descriptor))
        return "its descriptor has size " + std::to_string(d.struct_size) + ", expected " +
               std::to_string(sizeof(ani_plugin_descriptor));
    if (!d.id || !valid_plugin_id(d.id))
        return std::string("its id '") + (d.id ? d.id : "(null)") +
               "' is not of the form 'kind.name' in lower-case letters, digits, '_', '-', '.'";
    const std::string who = std::string("plugin '") + d.id + "'";
    if (!d.name || !d.name[0]) return who + " has no name";
    if (!d.description) return who + " has no description";
    if (d.param_count > 0 && !d.params) return who + " has parameters but no descriptors";
    std::set<std::string> seen;
    for (uint32_t i = 0; i < d.param_count; ++i) {
        if (auto problem = check_param_descriptor(d.params[i]); !problem.empty())
            return who + ": " + problem;
        if (!seen.insert(d.params[i].id).second)
            return who + " has two parameters with id '" + d.params[i].id + "'";
    }
    if (auto problem = check_kind_api(d.kind, d.api); !problem.empty()) return who + ": " + problem;
    return "";
}

} // namespace animator
