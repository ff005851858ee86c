#include "io/document_io.hpp"

#include "document/document_view.hpp"
#include "plugin/instance.hpp"

#include <animator/file_format.h>

#include <algorithm>
#include <fstream>
#include <memory>

namespace fs = std::filesystem;

namespace animator {

namespace {

std::string lower_extension(const fs::path &path) {
    std::string ext = path.extension().string();
    if (!ext.empty() && ext[0] == '.') ext.erase(0, 1);
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return ext;
}

std::string known_extensions(const std::vector<const PluginInfo *> &formats, uint32_t flag) {
    std::string out;
    for (const PluginInfo *info : formats) {
        const auto &api = *static_cast<const ani_file_format_api *>(info->descriptor->api);
        if (!(api.flags & flag)) continue;
        for (uint32_t i = 0; i < api.extension_count; ++i)
            out += (out.empty() ? "." : ", .") + std::string(api.extensions[i]);
    }
    return out.empty() ? "none" : out;
}

} // namespace

std::vector<std::string> not_said_before(std::vector<std::string> more, const std::vector<std::string> &said) {
    auto ends_with = [](const std::string &s, const std::string &end) {
        return s.size() >= end.size() && s.compare(s.size() - end.size(), end.size(), end) == 0;
    };
    more.erase(std::remove_if(more.begin(), more.end(),
                              [&](const std::string &w) {
                                  return std::any_of(said.begin(), said.end(),
                                                     [&](const std::string &s) { return ends_with(s, ": " + w); });
                              }),
               more.end());
    return more;
}

OpenedDocument open_document(PluginRegistry &plugins, const fs::path &path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw DocumentIoError(path.string() + ": cannot open the file");
    unsigned char head[512];
    in.read(reinterpret_cast<char *>(head), sizeof head);
    const auto head_size = static_cast<size_t>(in.gcount());

    const auto formats = plugins.find_kind(ANI_KIND_FILE_FORMAT);
    const PluginInfo *best = nullptr;
    std::unique_ptr<PluginInstance> best_instance;
    int best_score = 0;
    for (const PluginInfo *info : formats) {
        const auto &api = *static_cast<const ani_file_format_api *>(info->descriptor->api);
        if (!(api.flags & ANI_FORMAT_CAN_READ)) continue;
        auto instance = std::make_unique<PluginInstance>(*info, plugins.host());
        const int score = api.probe(instance->handle(), path.c_str(), head, head_size);
        if (score > best_score) {
            best = info;
            best_score = score;
            best_instance = std::move(instance);
        }
    }
    if (!best)
        throw DocumentIoError(path.string() + ": no file-format plugin reads this file (readable: " +
                              known_extensions(formats, ANI_FORMAT_CAN_READ) + ")");

    const auto &api = best_instance->api<ani_file_format_api>();
    const ani_document_view *view = nullptr;
    ani_status status{};
    std::vector<std::string> warnings;
    struct Capture { // the reader's warnings, while it reads
        PluginRegistry &plugins;
        ~Capture() { plugins.capture_warnings("", nullptr); }
    } capture{plugins};
    plugins.capture_warnings(best->id, &warnings);
    if (api.read(best_instance->handle(), path.c_str(), &view, &status) != ANI_OK || !view)
        throw DocumentIoError(status.message[0] ? std::string(status.message)
                                                : path.string() + ": could not be read");
    try {
        OpenedDocument opened{document_from_view(*view), best->id, std::move(warnings)};
        api.release(best_instance->handle(), view);
        return opened;
    } catch (const DocumentError &e) {
        api.release(best_instance->handle(), view);
        throw DocumentIoError(path.string() + ": " + e.what());
    }
}

void save_document(PluginRegistry &plugins, const Document &doc, const fs::path &path) {
    const std::string ext = lower_extension(path);
    const auto formats = plugins.find_kind(ANI_KIND_FILE_FORMAT);
    for (const PluginInfo *info : formats) {
        const auto &api = *static_cast<const ani_file_format_api *>(info->descriptor->api);
        if (!(api.flags & ANI_FORMAT_CAN_WRITE)) continue;
        for (uint32_t i = 0; i < api.extension_count; ++i) {
            if (ext != api.extensions[i]) continue;
            PluginInstance instance(*info, plugins.host());
            DocumentView view(doc);
            ani_status status{};
            if (api.write(instance.handle(), path.c_str(), &view.view(), &status) != ANI_OK)
                throw DocumentIoError(path.string() + ": " + status.message);
            return;
        }
    }
    throw DocumentIoError(path.string() + ": no file-format plugin writes '." + ext +
                          "' files (writable: " + known_extensions(formats, ANI_FORMAT_CAN_WRITE) + ")");
}

} // namespace animator
