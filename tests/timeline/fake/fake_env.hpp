// The plugins of this build and the test backends beside them (fake/*.cpp: physics.test_*), with
// a quiet log, for the host's tests of what a backend reports.
#pragma once

#include "io/environment.hpp"

#include "support.hpp"

namespace fake_backends {

inline animator::Environment &env() {
    static animator::Environment e(
        {animator::test::bin_dir().parent_path() / "assets"},
        {animator::test::bin_dir(), ANIMATOR_FAKE_PLUGIN_DIR},
        [](ani_log_level, const std::string &, const std::string &) {});
    return e;
}

} // namespace fake_backends
