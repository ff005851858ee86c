// What an interpolator checks before it evaluates anything, so that a bad channel gives a
// message instead of NaN or infinity in the animation. Each check throws
// ani::Failure(ANI_ERR_INVALID_ARGUMENT, message) naming the plugin and the problem.
#pragma once

#include <animator/interpolator.h>

#include <cstdint>
#include <string>

namespace interp {

// "position", "angles", ... or "unknown".
const char *channel_kind_name(int32_t kind);
// How many of value[0..3] a channel kind uses: 4 for the camera's rotation, 3 otherwise.
int channel_components(int32_t kind);

// The channel is non-null and of a known size; its kind is one of `handled_mask` (bit 1 << kind);
// it has at least one key; its key times are finite and strictly increasing with finite gaps;
// the values it uses are finite; ANGLES turns are finite; CAMERA_ROTATION values are unit
// quaternions (to 1e-4); and, when `uses_initial_rate`, initial_rate[0..2] is finite.
void check_channel(const char *plugin_id, const ani_channel *channel,
                   uint32_t handled_mask, bool uses_initial_rate);

// The evaluate call's other arguments: when count > 0 no pointer is null, and the times are
// finite and in non-decreasing order.
void check_times(const char *plugin_id, const double *times, uint32_t count,
                 const double *values, const double *rates);

// Every value and rate written is finite; enormous (finite) inputs can still overflow.
void check_outputs(const char *plugin_id, const double *values, const double *rates,
                   uint32_t count);

} // namespace interp
