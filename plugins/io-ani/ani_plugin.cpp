// The .ani file-format plugin (id format.ani): the plugin boundary around ani_reader.cpp and
// ani_writer.cpp.
#include "ani_text.hpp"

#include <animator/file_format.h>
#include <animator/plugin_cpp.hpp>

#include <cstring>
#include <map>
#include <memory>

namespace {

constexpr char kPluginId[] = "format.ani";

struct AniInstance {
    const ani_host *host = nullptr;
    std::map<const ani_document_view *, std::unique_ptr<ani::OwnedDocument>> read_documents;
};

void *ani_create(const ani_host *host, ani_status *status) {
    AniInstance *self = nullptr;
    ani::guarded(status, [&] {
        self = new AniInstance();
        self->host = host;
    });
    return self;
}

void ani_destroy(void *instance) { delete static_cast<AniInstance *>(instance); }

int32_t ani_probe(void *, const char *path, const unsigned char *head, size_t head_size) {
    const size_t magic = std::strlen(ani_format::kMagic);
    if (head_size >= magic && std::memcmp(head, ani_format::kMagic, magic) == 0) return 100;
    const size_t n = path ? std::strlen(path) : 0;
    if (n >= 4 && std::strcmp(path + n - 4, ".ani") == 0) return 50; // read it to say what is wrong
    return 0;
}

ani_status_code ani_read(void *instance, const char *path, const ani_document_view **document,
                         ani_status *status) {
    return ani::guarded(status, [&] {
        auto doc = std::make_unique<ani::OwnedDocument>();
        std::string error;
        if (!ani_format::read_ani(path, static_cast<AniInstance *>(instance)->host, *doc, error)) throw ani::Failure(ANI_ERR_PARSE, error);
        *document = &doc->view;
        static_cast<AniInstance *>(instance)->read_documents[&doc->view] = std::move(doc);
    });
}

void ani_release(void *instance, const ani_document_view *document) {
    static_cast<AniInstance *>(instance)->read_documents.erase(document);
}

ani_status_code ani_write(void *, const char *path, const ani_document_view *document,
                          ani_status *status) {
    return ani::guarded(status, [&] {
        std::string error;
        if (!ani_format::write_ani(path, *document, error))
            throw ani::Failure(ANI_ERR_IO, std::string(path) + ": " + error);
    });
}

const char *const ani_extensions[] = {"ani"};

const ani_file_format_api ani_api = {
    sizeof(ani_file_format_api),
    {sizeof(ani_instance_api), ani_create, ani_destroy, ani::no_param_get<kPluginId>, ani::no_param_set<kPluginId>},
    ANI_FORMAT_CAN_READ | ANI_FORMAT_CAN_WRITE,
    ani_extensions,
    1,
    ani_probe,
    ani_read,
    ani_release,
    ani_write,
};

const ani_plugin_descriptor ani_descriptor = {
    sizeof(ani_plugin_descriptor),
    kPluginId,
    ANI_KIND_FILE_FORMAT,
    "Animator animation (.ani)",
    {1, 0, 0},
    "Reads and writes animations in the versioned, line-oriented .ani text format.",
    nullptr,
    0,
    &ani_api,
};

const ani_plugin_descriptor *const kPlugins[] = {&ani_descriptor};

} // namespace

ANI_PLUGIN_ENTRY(kPlugins)
