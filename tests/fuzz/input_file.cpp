#include "input_file.hpp"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <system_error>
#include <unistd.h>

namespace fs = std::filesystem;

namespace animator::fuzz {

namespace {

[[noreturn]] void give_up(const std::string &what) {
    std::fprintf(stderr, "fuzz harness: %s\n", what.c_str());
    std::abort();
}

class InputFolder {
  public:
    InputFolder() {
        std::error_code ec;
        const fs::path base =
            fs::is_directory("/dev/shm", ec) ? fs::path("/dev/shm") : fs::temp_directory_path();
        folder_ = base / ("animator-fuzz-" + std::to_string(::getpid()));
        fs::create_directories(folder_, ec);
        if (ec) give_up("cannot create " + folder_.string() + ": " + ec.message());
    }
    ~InputFolder() {
        std::error_code ec;
        fs::remove_all(folder_, ec);
    }
    InputFolder(const InputFolder &) = delete;
    InputFolder &operator=(const InputFolder &) = delete;

    const std::string &path_for(const std::string &extension) {
        auto it = paths_.find(extension);
        if (it == paths_.end())
            it = paths_.emplace(extension, (folder_ / ("input" + extension)).string()).first;
        return it->second;
    }

  private:
    fs::path folder_;
    std::map<std::string, std::string> paths_;
};

} // namespace

const std::string &write_input(const std::uint8_t *data, std::size_t size,
                               const std::string &extension) {
    static InputFolder folder;
    const std::string &path = folder.path_for(extension);
    std::FILE *f = std::fopen(path.c_str(), "wb");
    if (!f) give_up("cannot write " + path);
    const bool written = size == 0 || std::fwrite(data, 1, size, f) == size;
    if (std::fclose(f) != 0 || !written) give_up("cannot write " + path);
    return path;
}

} // namespace animator::fuzz
