#include "render/png_frame_writer.hpp"

#include "render/render_error.hpp"

#include <stb_image_write.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace animator {

PngFrameWriter::PngFrameWriter(std::filesystem::path folder, int width, int height,
                               unsigned threads, int compression)
    : folder_(std::move(folder)), width_(width), height_(height) {
    if (threads == 0) threads = std::max(1u, std::thread::hardware_concurrency());
    // stb reads these globals when it encodes; every writer in the program shares them. Its zlib
    // works at level 5 at least. Paeth on every row makes files as small as stb's own choice per
    // row on rendered frames, in two thirds of the time (measured: 34 ms against 51 ms for a
    // 1280x720 frame of simple.lua at level 5; 59 ms at stb's default 8).
    stbi_write_png_compression_level = std::clamp(compression, 5, 9);
    stbi_write_force_png_filter = 4;
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
        const int ok =
            stbi_write_png(file.c_str(), width_, height_, 3, job.pixels->data(), width_ * 3);
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
    stbi_write_png_compression_level = std::clamp(compression, 5, 9);
    stbi_write_force_png_filter = 4;
    if (!stbi_write_png(file.c_str(), width, height, 3, rgb.data(), width * 3))
        throw RenderError(file.string() + ": cannot be written");
}

} // namespace animator
