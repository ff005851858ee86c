// The plugin host: finds plugin libraries, opens the ones that are needed, checks what they
// declare, and refuses broken ones with a message naming the file and the reason while the
// others keep working. Libraries are never unloaded (a plugin's code may still be referenced).
//
// Discovery: files named `animator-*.so` in the folder of the executable and in the folders of
// ANIMATOR_PLUGIN_PATH (separated by ':'). Beside each library, a manifest `<library>.plugins`
// (written by the build) names the plugins it provides, so a plugin can be found by id without
// opening every library. A library without a manifest is opened when a plugin cannot be found
// otherwise.
#pragma once

#include <animator/plugin.h>

#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace animator {

struct PluginInfo {
    std::string id;
    int kind = 0; // ani_plugin_kind
    std::string name;
    ani_version version{};
    std::string description;
    std::filesystem::path library;
    const ani_plugin_descriptor *descriptor = nullptr; // lives in the library
    ani_version abi{}; // the plugin ABI its library was built for (a minor version this host's or older)
};

struct LibraryRefusal {
    std::filesystem::path library;
    std::string reason;
};

class PluginRegistry {
  public:
    using LogSink = std::function<void(ani_log_level, const std::string &plugin_id,
                                       const std::string &message)>;

    // Searches `dirs` in order. The log sink receives what plugins log (default: stderr).
    explicit PluginRegistry(const std::vector<std::filesystem::path> &dirs, LogSink log = {});
    ~PluginRegistry();
    PluginRegistry(const PluginRegistry &) = delete;
    PluginRegistry &operator=(const PluginRegistry &) = delete;

    // The executable's folder, then ANIMATOR_PLUGIN_PATH.
    static std::vector<std::filesystem::path> default_search_dirs();

    // While `into` is set, the warnings plugin `plugin_id` logs are kept there too, besides the
    // log (open_document: what a reader says about the file it reads). nullptr stops it.
    void capture_warnings(const std::string &plugin_id, std::vector<std::string> *into);

    // Opens every library found (for `animator plugins`).
    void load_all();
    // The plugin with this id, opening only the library that provides it; null if none does.
    const PluginInfo *find(const std::string &id);
    // Every plugin of a kind, opening only libraries that may provide one.
    std::vector<const PluginInfo *> find_kind(int kind);

    std::vector<const PluginInfo *> loaded() const;
    const std::vector<LibraryRefusal> &refusals() const { return refusals_; }
    std::vector<std::filesystem::path> libraries_found() const;
    std::vector<std::filesystem::path> libraries_opened() const;

    const ani_host *host() const { return &host_; }
    // Offers plugins an optional host feature (host->get_extension(host, id)); `extension` must
    // outlive the registry's use.
    void provide_extension(const std::string &id, const void *extension) { extensions_[id] = extension; }

  private:
    struct Library;
    void discover(const std::vector<std::filesystem::path> &dirs);
    void open(Library &library);
    void refuse(Library &library, const std::string &reason, void *handle);
    static void host_log(const ani_host *host, ani_log_level level, const char *plugin_id,
                         const char *message);
    static const void *host_get_extension(const ani_host *host, const char *extension_id);

    std::vector<std::unique_ptr<Library>> libraries_;
    std::vector<std::unique_ptr<PluginInfo>> plugins_;
    std::vector<LibraryRefusal> refusals_;
    std::map<std::string, const void *> extensions_;
    LogSink log_;
    std::mutex log_mutex_;
    std::string capture_id_;                      // capture_warnings()
    std::vector<std::string> *capture_ = nullptr;
    ani_host host_{};
};

} // namespace animator
