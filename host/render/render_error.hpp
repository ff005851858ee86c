// A failure of the renderer: no GL context, a framebuffer that is not complete, a shader that
// does not compile. The message says what and, for a shader, the stage and the driver's log.
#pragma once

#include <stdexcept>

namespace animator {

struct RenderError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

} // namespace animator
