#include "bullet_support.hpp"

#include <catch2/catch.hpp>

#include <mutex>

namespace animator::bullet_test {

const double kSteps[3] = {1.0 / 60.0, 1.0 / 240.0, 1.0 / 1000.0};

namespace {
std::mutex log_mutex;
std::vector<std::string> log_lines;
} // namespace

Environment &env() {
    static Environment e({test::bin_dir().parent_path() / "assets"}, {test::bin_dir()},
                         [](ani_log_level, const std::string &plugin, const std::string &message) {
                             std::lock_guard<std::mutex> lock(log_mutex);
                             log_lines.push_back(plugin + ": " + message);
                         });
    return e;
}

std::vector<std::string> take_log() {
    std::lock_guard<std::mutex> lock(log_mutex);
    std::vector<std::string> out;
    out.swap(log_lines);
    return out;
}

void check_converges(const char *what, const double (&errors)[3], const double (&bounds)[3],
                     double noise) {
    INFO(what << ": errors " << errors[0] << ", " << errors[1] << ", " << errors[2]
              << " at steps 1/60, 1/240, 1/1000; bounds " << bounds[0] << ", " << bounds[1] << ", "
              << bounds[2]);
    for (int k = 0; k < 3; ++k) CHECK(errors[k] <= bounds[k]);
    for (int k = 1; k < 3; ++k) CHECK((errors[k] < errors[k - 1] || errors[k] <= noise));
}

} // namespace animator::bullet_test
