// Writes frames as numbered PNG files (DIR/frame_00000.png, ...) on worker threads. Encoding, not
// drawing, bounds frame export (docs/rendering.md: about 114 ms per 720p frame at stb's default
// compression 8, 0.2 ms to read it back), so frames are compressed at a lower level while the
// renderer draws the next ones. A few buffers are recycled, so an export of any length allocates
// no frame buffers after the first.
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
    // `threads` 0 uses every core. `compression` is stb's zlib level, 5 (fastest, the default)
    // to 9; stb's own default is 8. The folder must exist.
    PngFrameWriter(std::filesystem::path folder, int width, int height, unsigned threads = 0,
                   int compression = 5);
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
    int width_, height_;
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
// stb's zlib level `compression` (5 to 9), on this thread. Throws RenderError when it cannot.
void write_png(const std::filesystem::path &file, int width, int height,
               const std::vector<std::uint8_t> &rgb, int compression = 5);

// The number of frames `animator render` writes for [from, to] seconds at `fps`: one at `from`,
// then one every 1/fps up to `to` (the command line's and the editor's Render dialog's count).
int render_frame_count(double from, double to, double fps);

} // namespace animator
