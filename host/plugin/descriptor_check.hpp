// Validation of what a plugin describes about itself, before the host trusts it: descriptors,
// the interface of each kind, parameter descriptors and parameter values. Each check returns ""
// when all is well, else a sentence saying what is wrong.
#pragma once

#include <animator/plugin.h>

#include <string>
#include <string_view>

namespace animator {

// "physics.custom": lower-case letters, digits, '_', '-', at least one '.', 3..64 characters.
bool valid_plugin_id(std::string_view id);
// "step", "band_count": lower-case letters, digits, '_', '.', 1..64 characters.
bool valid_param_id(std::string_view id);

std::string check_param_descriptor(const ani_param_descriptor &param);
std::string check_param_value(const ani_param_descriptor &param, const ani_param_value &value);
// The descriptor, its parameters and the interface of its kind.
std::string check_plugin_descriptor(const ani_plugin_descriptor &descriptor);

const char *kind_name(int kind);           // "physics", "interpolator", ...; "" if unknown
int kind_from_name(std::string_view name); // 0 if unknown

} // namespace animator
