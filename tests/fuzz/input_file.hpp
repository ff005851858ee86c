// The file a harness hands to a reader that takes a path: each input is written to one file in
// a folder of this process's own (several fuzzer processes may run at once), in /dev/shm when
// the machine has it, so that a million inputs never touch a disk. The folder is removed when
// the process exits normally.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace animator::fuzz {

// Writes `data` to "<this process's folder>/input<extension>" and returns that path. Aborts
// with a message if the file cannot be written: a harness that fuzzes nothing must not pass.
const std::string &write_input(const std::uint8_t *data, std::size_t size,
                               const std::string &extension);

} // namespace animator::fuzz
