// The ani_host a harness hands to a file-format plugin: what the tests' hosts offer (an assets
// extension over tests/data/assets and assets/, as tests/plugins/bad_corpus_test.cpp builds
// it), and a log that stays silent so libFuzzer's own output is readable.
#pragma once

#include <animator/plugin.h>

namespace animator::fuzz {

// Valid for the whole process.
const ani_host *fuzz_host();

} // namespace animator::fuzz
