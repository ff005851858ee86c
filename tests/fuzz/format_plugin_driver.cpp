#include "format_plugin_driver.hpp"

#include "document/document_view.hpp"

#include <animator/file_format.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace animator::fuzz {

namespace {

[[noreturn]] void give_up(const std::string &what) {
    std::fprintf(stderr, "fuzz harness: %s\n", what.c_str());
    std::abort();
}

} // namespace

FormatPluginDriver::FormatPluginDriver(const ani_plugin_entry &entry, const ani_host *host)
    : entry_(entry), host_(host) {
    ani_status status{};
    if (entry_.init(host_, &status) != ANI_OK)
        give_up(std::string("init failed: ") + status.message);
    for (uint32_t i = 0; i < entry_.plugin_count() && !api_; ++i) {
        const ani_plugin_descriptor *d = entry_.plugin_descriptor(i);
        if (d && d->kind == ANI_KIND_FILE_FORMAT)
            api_ = static_cast<const ani_file_format_api *>(d->api);
    }
    if (!api_ || !(api_->flags & ANI_FORMAT_CAN_READ))
        give_up("the library has no file format that reads");
    instance_ = api_->instance.create(host_, &status);
    if (!instance_) give_up(std::string("create failed: ") + status.message);
}

FormatPluginDriver::~FormatPluginDriver() {
    api_->instance.destroy(instance_);
    entry_.deinit();
}

void FormatPluginDriver::open(const std::string &path, const unsigned char *head,
                              size_t head_size) {
    // The host offers a plugin the first 512 bytes and reads with the most confident one.
    if (api_->probe(instance_, path.c_str(), head, std::min<size_t>(head_size, 512)) <= 0) return;
    const ani_document_view *view = nullptr;
    ani_status status{};
    if (api_->read(instance_, path.c_str(), &view, &status) != ANI_OK) {
        if (view) give_up("a failed read returned a document");
        if (std::strncmp(status.message, path.c_str(), path.size()) != 0)
            give_up(std::string("a read failed with a message that does not name the file: ") +
                    status.message);
        return;
    }
    if (!view) give_up("a successful read returned no document");
    try {
        (void)document_from_view(*view);
    } catch (const DocumentError &e) {
        // The host would refuse it naming the file but no line: a reader checks what it reads.
        give_up(std::string("the host refuses a document the reader accepted: ") + e.what());
    }
    api_->release(instance_, view);
}

} // namespace animator::fuzz
