#include "plugin/registry.hpp"

#include "plugin/descriptor_check.hpp"

#include <dlfcn.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <set>
#include <sstream>

namespace fs = std::filesystem;

namespace animator {

namespace {

std::string version_text(const ani_version &v) {
    return std::to_string(v.major) + "." + std::to_string(v.minor);
}

struct ManifestEntry {
    std::string id;
    int kind = 0;
};

// `animator-plugin-manifest 1` then one `<id> <kind>` per line. A manifest that cannot be read
// is ignored: the library is then opened to learn what it holds.
bool read_manifest(const fs::path &path, std::vector<ManifestEntry> &entries) {
    std::ifstream in(path);
    std::string header;
    if (!in || !std::getline(in, header) || header != "animator-plugin-manifest 1") return false;
    std::string line;
    while (std::getline(in, line)) {
        std::istringstream words(line);
        ManifestEntry e;
        std::string kind;
        if (!(words >> e.id)) continue;
        if (!(words >> kind) || (e.kind = kind_from_name(kind)) == 0) return false;
        entries.push_back(e);
    }
    return true;
}

} // namespace

struct PluginRegistry::Library {
    fs::path path;
    bool has_manifest = false;
    std::vector<ManifestEntry> manifest;
    enum class State { Unopened, Loaded, Refused } state = State::Unopened;
    const ani_plugin_entry *entry = nullptr; // once loaded

    bool may_provide_id(const std::string &id) const {
        if (!has_manifest) return true;
        return std::any_of(manifest.begin(), manifest.end(), [&](auto &e) { return e.id == id; });
    }
    bool may_provide_kind(int kind) const {
        if (!has_manifest) return true;
        return std::any_of(manifest.begin(), manifest.end(), [&](auto &e) { return e.kind == kind; });
    }
};

PluginRegistry::PluginRegistry(const std::vector<fs::path> &dirs, LogSink log) : log_(std::move(log)) {
    if (!log_) {
        log_ = [](ani_log_level level, const std::string &plugin, const std::string &message) {
            static const char *names[] = {"debug", "info", "warning", "error"};
            if (level < ANI_LOG_INFO) return;
            std::cerr << "[" << plugin << "] " << names[level] << ": " << message << "\n";
        };
    }
    host_.struct_size = sizeof host_;
    host_.abi = ani_version{ANI_ABI_MAJOR, ANI_ABI_MINOR, 0};
    host_.host_name = "animator";
    host_.host_version = ani_version{0, 1, 0};
    host_.host_data = this;
    host_.log = &PluginRegistry::host_log;
    host_.get_extension = &PluginRegistry::host_get_extension;
    discover(dirs);
}

PluginRegistry::~PluginRegistry() {
    // Plugins may keep state until the end; libraries stay mapped (never dlclose'd).
    for (auto &lib : libraries_)
        if (lib->state == Library::State::Loaded) lib->entry->deinit();
}

void PluginRegistry::capture_warnings(const std::string &plugin_id, std::vector<std::string> *into) {
    std::lock_guard<std::mutex> lock(log_mutex_);
    capture_id_ = plugin_id;
    capture_ = into;
}

void PluginRegistry::host_log(const ani_host *host, ani_log_level level, const char *plugin_id,
                              const char *message) {
    if (!host || !host->host_data) return;
    auto *self = static_cast<PluginRegistry *>(host->host_data);
    std::lock_guard<std::mutex> lock(self->log_mutex_);
    if (level < ANI_LOG_DEBUG || level > ANI_LOG_ERROR) level = ANI_LOG_ERROR;
    self->log_(level, plugin_id ? plugin_id : "?", message ? message : "");
    if (level == ANI_LOG_WARNING && self->capture_ && plugin_id && self->capture_id_ == plugin_id)
        self->capture_->push_back(message ? message : "");
}

const void *PluginRegistry::host_get_extension(const ani_host *host, const char *extension_id) {
    if (!host || !host->host_data || !extension_id) return nullptr;
    const auto *self = static_cast<const PluginRegistry *>(host->host_data);
    auto it = self->extensions_.find(extension_id);
    return it == self->extensions_.end() ? nullptr : it->second;
}

std::vector<fs::path> PluginRegistry::default_search_dirs() {
    std::vector<fs::path> dirs;
    std::error_code ec;
    const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    if (!ec) dirs.push_back(exe.parent_path());
    if (const char *env = std::getenv("ANIMATOR_PLUGIN_PATH")) {
        std::istringstream parts(env);
        std::string part;
        while (std::getline(parts, part, ':'))
            if (!part.empty()) dirs.emplace_back(part);
    }
    return dirs;
}

void PluginRegistry::discover(const std::vector<fs::path> &dirs) {
    std::set<fs::path> seen;
    for (const fs::path &dir : dirs) {
        std::error_code ec;
        std::vector<fs::path> found;
        for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
            const std::string name = it->path().filename().string();
            if (name.rfind("animator-", 0) == 0 && it->path().extension() == ".so")
                found.push_back(it->path());
        }
        std::sort(found.begin(), found.end()); // a stable order, whatever the file system's
        for (const fs::path &path : found) {
            const fs::path canonical = fs::weakly_canonical(path, ec);
            if (!seen.insert(ec ? path : canonical).second) continue;
            auto lib = std::make_unique<Library>();
            lib->path = path;
            lib->has_manifest = read_manifest(fs::path(path.string() + ".plugins"), lib->manifest);
            libraries_.push_back(std::move(lib));
        }
    }
}

void PluginRegistry::refuse(Library &library, const std::string &reason, void *handle) {
    library.state = Library::State::Refused;
    refusals_.push_back(LibraryRefusal{library.path, reason});
    log_(ANI_LOG_WARNING, "host", "refused plugin library " + library.path.string() + ": " + reason);
    if (handle) dlclose(handle); // init() was never called: nothing of it can be in use
}

void PluginRegistry::open(Library &library) {
    if (library.state != Library::State::Unopened) return;
    void *handle = dlopen(library.path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle) {
        const char *error = dlerror();
        refuse(library, std::string("cannot be opened: ") + (error ? error : "unknown error"), nullptr);
        return;
    }
    const auto *entry = static_cast<const ani_plugin_entry *>(dlsym(handle, ANI_ENTRY_SYMBOL));
    if (!entry) {
        refuse(library, std::string("has no entry symbol '") + ANI_ENTRY_SYMBOL + "'", handle);
        return;
    }
    if (entry->abi.major != ANI_ABI_MAJOR || entry->abi.minor > ANI_ABI_MINOR) {
        refuse(library, "was built for plugin ABI " + version_text(entry->abi) +
                            ", this host has ABI " +
                            version_text(ani_version{ANI_ABI_MAJOR, ANI_ABI_MINOR, 0}),
               handle);
        return;
    }
    if (entry->struct_size != sizeof(ani_plugin_entry) || !entry->init || !entry->deinit ||
        !entry->plugin_count || !entry->plugin_descriptor) {
        refuse(library, "has an incomplete entry (size " + std::to_string(entry->struct_size) +
                            ", expected " + std::to_string(sizeof(ani_plugin_entry)) +
                            ", and every function set)",
               handle);
        return;
    }

    const uint32_t count = entry->plugin_count();
    if (count == 0 || count > 1024) {
        refuse(library, "declares " + std::to_string(count) + " plugins", handle);
        return;
    }
    std::set<std::string> ids;
    std::vector<const ani_plugin_descriptor *> descriptors;
    for (uint32_t i = 0; i < count; ++i) {
        const ani_plugin_descriptor *d = entry->plugin_descriptor(i);
        if (!d) {
            refuse(library, "returns no descriptor for plugin " + std::to_string(i), handle);
            return;
        }
        if (auto problem = check_plugin_descriptor(*d); !problem.empty()) {
            refuse(library, "has an invalid plugin: " + problem, handle);
            return;
        }
        if (!ids.insert(d->id).second) {
            refuse(library, std::string("declares plugin id '") + d->id + "' twice", handle);
            return;
        }
        for (const auto &other : plugins_)
            if (other->id == d->id) {
                refuse(library, std::string("declares plugin id '") + d->id +
                                    "', already provided by " + other->library.string(),
                       handle);
                return;
            }
        if (library.has_manifest && !library.may_provide_id(d->id)) {
            refuse(library, std::string("declares plugin id '") + d->id +
                                "', which its manifest does not name",
                   handle);
            return;
        }
        descriptors.push_back(d);
    }

    ani_status status{};
    if (entry->init(&host_, &status) != ANI_OK) {
        refuse(library, std::string("failed to initialise: ") + status.message, handle);
        return;
    }
    library.state = Library::State::Loaded;
    library.entry = entry;
    for (const ani_plugin_descriptor *d : descriptors) {
        auto info = std::make_unique<PluginInfo>();
        info->id = d->id;
        info->kind = d->kind;
        info->name = d->name;
        info->version = d->version;
        info->description = d->description;
        info->library = library.path;
        info->descriptor = d;
        info->abi = entry->abi;
        plugins_.push_back(std::move(info));
    }
}

void PluginRegistry::load_all() {
    for (auto &lib : libraries_) open(*lib);
}

const PluginInfo *PluginRegistry::find(const std::string &id) {
    auto loaded_with_id = [&]() -> const PluginInfo * {
        for (const auto &p : plugins_)
            if (p->id == id) return p.get();
        return nullptr;
    };
    if (const PluginInfo *p = loaded_with_id()) return p;
    // First the libraries whose manifest names the id, then those without a manifest.
    for (bool manifest_pass : {true, false})
        for (auto &lib : libraries_) {
            if (lib->has_manifest != manifest_pass || !lib->may_provide_id(id)) continue;
            open(*lib);
            if (const PluginInfo *p = loaded_with_id()) return p;
        }
    return nullptr;
}

std::vector<const PluginInfo *> PluginRegistry::find_kind(int kind) {
    for (auto &lib : libraries_)
        if (lib->may_provide_kind(kind)) open(*lib);
    std::vector<const PluginInfo *> out;
    for (const auto &p : plugins_)
        if (p->kind == kind) out.push_back(p.get());
    return out;
}

std::vector<const PluginInfo *> PluginRegistry::loaded() const {
    std::vector<const PluginInfo *> out;
    for (const auto &p : plugins_) out.push_back(p.get());
    return out;
}

std::vector<fs::path> PluginRegistry::libraries_found() const {
    std::vector<fs::path> out;
    for (const auto &lib : libraries_) out.push_back(lib->path);
    return out;
}

std::vector<fs::path> PluginRegistry::libraries_opened() const {
    std::vector<fs::path> out;
    for (const auto &lib : libraries_)
        if (lib->state != Library::State::Unopened) out.push_back(lib->path);
    return out;
}

} // namespace animator
