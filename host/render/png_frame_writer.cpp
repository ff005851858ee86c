#include "render/png_frame_writer.hpp"

#include "render/render_error.hpp"

#include <png.h>

#include <algorithm>
#include <cmath>
#include <csetjmp>
#include <cstdio>
#include <memory>

namespace animator {

namespace {

// Writes an RGB image (rows top first) as a PNG file with libpng at zlib level `level`, every
// row with the Up filter: on rendered frames as small as stb's encoder at its lowest level with
// Paeth, or smaller, in a third of its time (docs/rendering.md, `animator render`). False when the
// file cannot be written (libpng's errors come back through its longjmp, caught here).
bool encode_png(const std::filesystem::path &file, int width, int height, const std::uint8_t *rgb,
                int level) {
    const std::unique_ptr<std::FILE, int (*)(std::FILE *)> out(std::fopen(file.c_str(), "wb"),
                                                                &std::fclose);
    if (!out) return false;
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png ? png_create_info_struct(png) : nullptr;
    if (!info) {
        png_destroy_write_struct(&png, nullptr);
        return false;
    }
    // (Nothing with a destructor lives between here and libpng's calls: its longjmp skips them.)
    if (setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        return false;
    }
    png_init_io(png, out.get());
    png_set_compression_level(png, level);
    png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_UP);
    png_set_IHDR(png, info, static_cast<png_uint_32>(width), static_cast<png_uint_32>(height), 8,
                 PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_BASE,
                 PNG_FILTER_TYPE_BASE);
    png_write_info(png, info);
    const std::size_t row = static_cast<std::size_t>(width) * 3;
    for (int y = 0; y < height; ++y)
        png_write_row(png, rgb + static_cast<std::size_t>(y) * row);
    png_write_end(png, info);
    png_destroy_write_struct(&png, &info);
    return std::fflush(out.get()) == 0 && !std::ferror(out.get());
}

} // namespace

PngFrameWriter::PngFrameWriter(std::filesystem::path folder, int width, int height,
                               unsigned threads, int compression)
    : folder_(std::move(folder)), width_(width), height_(height),
      compression_(std::clamp(compression, 1, 9)) {
    if (threads == 0) threads = std::max(1u, std::thread::hardware_concurrency());
    // Two buffers per worker: one being encoded while the next waits, so drawing never stalls
    // behind a single slow frame.
    buffers_.resize(static_cast<size_t>(threads) * 2);
    for (auto &b : buffers_) free_.push_back(&b);
    for (unsigned i = 0; i < threads; ++i) workers_.emplace_back([this] { work(); });
}

PngFrameWriter::~PngFrameWriter() {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        stopping_ = true;
    }
    changed_.notify_all();
    for (std::thread &t : workers_) t.join();
}

int render_frame_count(double from, double to, double fps) {
    return static_cast<int>(std::floor((to - from) * fps + 1e-9)) + 1;
}

std::string PngFrameWriter::file_name(int index) {
    char name[32];
    (void)std::snprintf(name, sizeof name, "frame_%05d.png", index);
    return name;
}

std::vector<std::uint8_t> &PngFrameWriter::next_buffer() {
    std::unique_lock<std::mutex> lock(mutex_);
    changed_.wait(lock, [this] { return !free_.empty(); });
    filling_ = free_.back();
    free_.pop_back();
    filling_->resize(static_cast<size_t>(width_) * static_cast<size_t>(height_) * 3);
    return *filling_;
}

void PngFrameWriter::write(int index) {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        if (!filling_) throw RenderError("PngFrameWriter::write without next_buffer");
        queue_.push_back({filling_, index});
        filling_ = nullptr;
    }
    changed_.notify_all();
}

void PngFrameWriter::finish() {
    std::unique_lock<std::mutex> lock(mutex_);
    changed_.wait(lock, [this] { return queue_.empty() && busy_ == 0; });
    if (!first_error_.empty()) throw RenderError(first_error_);
}

void PngFrameWriter::work() {
    std::unique_lock<std::mutex> lock(mutex_);
    for (;;) {
        changed_.wait(lock, [this] { return stopping_ || !queue_.empty(); });
        if (queue_.empty()) return; // stopping, and nothing left to write
        const Job job = queue_.front();
        queue_.pop_front();
        ++busy_;
        lock.unlock();
        const std::filesystem::path file = folder_ / file_name(job.index);
        const bool ok = encode_png(file, width_, height_, job.pixels->data(), compression_);
        lock.lock();
        if (!ok && first_error_.empty()) first_error_ = file.string() + ": cannot be written";
        free_.push_back(job.pixels);
        --busy_;
        changed_.notify_all();
    }
}

void write_png(const std::filesystem::path &file, int width, int height,
               const std::vector<std::uint8_t> &rgb, int compression) {
    if (rgb.size() != static_cast<size_t>(width) * static_cast<size_t>(height) * 3)
        throw RenderError(file.string() + ": the image has not width x height RGB pixels");
    if (!encode_png(file, width, height, rgb.data(), std::clamp(compression, 1, 9)))
        throw RenderError(file.string() + ": cannot be written");
}

} // namespace animator
