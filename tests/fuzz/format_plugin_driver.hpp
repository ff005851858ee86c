// Drives a file-format plugin through its C entry the way the host opens a document
// (host/plugin/registry.cpp initialises the library and host/io/document_io.cpp probes, reads,
// builds the document and releases), so a harness fuzzes exactly what a user's file reaches.
#pragma once

#include <animator/file_format.h>

#include <string>

namespace animator::fuzz {

class FormatPluginDriver {
  public:
    // Initialises the library behind `entry` with `host` and creates an instance of its
    // file-format plugin. Aborts with a message on failure: a harness that cannot reach the
    // reader would otherwise pass while fuzzing nothing.
    FormatPluginDriver(const ani_plugin_entry &entry, const ani_host *host);
    ~FormatPluginDriver();
    FormatPluginDriver(const FormatPluginDriver &) = delete;
    FormatPluginDriver &operator=(const FormatPluginDriver &) = delete;

    // Opens the file at `path` whose first bytes are `head`: probe, then read, then the host's
    // document_from_view over the result (which touches every pointer the view holds), then
    // release. A refused file is fine if its message names the file, as every reader promises
    // (sdk file_format.h); a document the reader accepts must satisfy the host, which would
    // otherwise refuse it without a line. Anything else aborts, which libFuzzer reports.
    void open(const std::string &path, const unsigned char *head, size_t head_size);

  private:
    const ani_plugin_entry &entry_;
    const ani_host *host_;
    const ani_file_format_api *api_ = nullptr;
    void *instance_ = nullptr;
};

} // namespace animator::fuzz
