// Writes frames as numbered PNG files (DIR/frame_00000.png, ...) on worker threads, with libpng at
// a low zlib level (docs/rendering.md, `animator render`: about 11 ms a 1280x720 frame, a third of
// stb's encoder at its lowest level), while the renderer draws the next ones. A few buffers are
// recycled, so an export of any length allocates no frame buffers after the first.
#pragma once

#include <condition_variable>
#include <cstdint>
#include <deque>
#include <filesystem>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace animator {

class PngFrameWriter {
  public:
    // `threads` 0 uses every core. `compression` is zlib's level, 1 (fastest) to 9 (smallest);
    // 3, the default, makes files smaller than stb's encoder did at its lowest level. The folder
    // must exist.
    PngFrameWriter(std::filesystem::path folder, int width, int height, unsigned threads = 0,
                   int compression = 3);
    // Waits for every frame handed over (errors then go unreported: call finish() first).
    ~PngFrameWriter();
    PngFrameWriter(const PngFrameWriter &) = delete;
    PngFrameWriter &operator=(const PngFrameWriter &) = delete;

    // A buffer to fill with the next frame (width * height * 3 bytes of RGB, rows top first);
    // blocks while every buffer is still being encoded.
    std::vector<std::uint8_t> &next_buffer();
    // Hands the buffer from next_buffer() over to be written as frame `index`.
    void write(int index);
    // Waits until every frame handed over is written. Throws RenderError naming the first file
    // that could not be written.
    void finish();

    static std::string file_name(int index); // "frame_00000.png"

  private:
    struct Job {
        std::vector<std::uint8_t> *pixels;
        int index;
    };
    void work();

    std::filesystem::path folder_;
    int width_, height_, compression_;
    std::vector<std::vector<std::uint8_t>> buffers_;
    std::vector<std::vector<std::uint8_t> *> free_;
    std::vector<std::uint8_t> *filling_ = nullptr;
    std::deque<Job> queue_;
    std::size_t busy_ = 0;
    bool stopping_ = false;
    std::string first_error_;
    std::mutex mutex_;
    std::condition_variable changed_;
    std::vector<std::thread> workers_;
};

// Writes one image (width * height * 3 bytes of RGB, rows top first) as the PNG file `file`, at
// zlib's level `compression` (1 to 9), on this thread. Throws RenderError when it cannot.
void write_png(const std::filesystem::path &file, int width, int height,
               const std::vector<std::uint8_t> &rgb, int compression = 3);

// The number of frames `animator render` writes for [from, to] seconds at `fps`: one at `from`,
// then one every 1/fps up to `to` (the command line's and the editor's Render dialog's count).
int render_frame_count(double from, double to, double fps);

} // namespace animator
