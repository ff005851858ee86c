// libFuzzer harness of image loading (host/assets/image.cpp): each input is written to a file
// and loaded as a texture or a skybox face is. stb_image is compiled into image.cpp from
// Debian's header, so it is instrumented and fuzzed with our code.
//
// One file name serves both formats: stb picks its decoder from the first bytes, never from
// the extension, so the seeds (PNG and BMP of each colour type) and the mutations of their
// magic numbers are what reach each decoder.
#include "assets/image.hpp"
#include "input_file.hpp"

#include <cstddef>
#include <cstdint>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
    const std::string &path = animator::fuzz::write_input(data, size, ".png");
    try {
        (void)animator::load_image(path);
    } catch (const animator::AssetError &) {
        // Refused with a message naming the file.
    }
    return 0;
}
