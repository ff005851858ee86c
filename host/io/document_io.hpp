// Opening and saving documents through file-format plugins: the stage between a file on disk
// and the document model. The format is chosen by probing (reading) or by extension (saving).
#pragma once

#include "document/document.hpp"
#include "plugin/registry.hpp"

#include <filesystem>
#include <stdexcept>
#include <string>

namespace animator {

// A file could not be read or written; the message starts with the file's path.
struct DocumentIoError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

struct OpenedDocument {
    Document document;
    std::string format_id; // the plugin that read it
    // What it warned about while reading (a renamed node, a dropped shear), "file:line: ...", as
    // it also said them in the log.
    std::vector<std::string> warnings;
};

// The warnings of `more` that `said` has not said already: a reader says "file:line: W" where the
// host, loading the same document's meshes, would say W again (a mesh not found).
std::vector<std::string> not_said_before(std::vector<std::string> more, const std::vector<std::string> &said);

// Reads `path` with the file-format plugin that is surest it reads it. Throws DocumentIoError.
OpenedDocument open_document(PluginRegistry &plugins, const std::filesystem::path &path);

// Writes `doc` to `path` with the plugin that writes its extension. A failure leaves any
// previous file intact (the plugin's promise, see sdk file_format.h). Throws DocumentIoError.
void save_document(PluginRegistry &plugins, const Document &doc, const std::filesystem::path &path);

} // namespace animator
