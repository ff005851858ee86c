# The fuzz build (ANIMATOR_FUZZ=ON, docs/fuzzing.md): every file reader under libFuzzer.
#
# libFuzzer sees the coverage only of code compiled with -fsanitize=fuzzer(-no-link), and
# clang's sanitizer objects do not mix with GCC's, so this is a build folder of its own, made
# with clang, holding only what the readers need: the SDK headers, the .ani and Lua plugins'
# sources, the document model they fill, the asset loader (meshes, images), the harnesses in
# tests/fuzz/ and a short run of each as a test. No editor, renderer, Bullet or sound.
#
#   CC=clang CXX=clang++ cmake -S . -B build-fuzz -DANIMATOR_FUZZ=ON
#   cmake --build build-fuzz -j2 && ctest --test-dir build-fuzz

if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang" OR NOT CMAKE_C_COMPILER_ID STREQUAL "Clang")
  message(FATAL_ERROR
    "ANIMATOR_FUZZ needs clang and its libFuzzer (got ${CMAKE_CXX_COMPILER_ID}); configure a "
    "fresh build folder with: CC=clang CXX=clang++ cmake -S . -B build-fuzz -DANIMATOR_FUZZ=ON")
endif()
if(ANIMATOR_SANITIZE)
  message(FATAL_ERROR "ANIMATOR_FUZZ brings its own sanitizers; leave ANIMATOR_SANITIZE off")
endif()

# The asset generator makes seeds (meshes, textures) at build time; it is not what is fuzzed,
# so it is added before the instrumentation is switched on.
add_subdirectory(tools/asset_gen)

# Everything from here on is instrumented for coverage (fuzzer-no-link: libFuzzer's main is
# linked into the harnesses only) and checked by the sanitizers, every finding fatal.
set(ANIMATOR_FUZZ_SANITIZERS "address,undefined" CACHE STRING
    "The fuzz build's sanitizers: address,undefined (what the tests run), or undefined alone for a long run of the mesh harness, which ASan slows 80-fold (docs/fuzzing.md)")
add_compile_options(-fsanitize=fuzzer-no-link,${ANIMATOR_FUZZ_SANITIZERS} -fno-sanitize-recover=all
                    -fno-omit-frame-pointer)
add_link_options(-fsanitize=${ANIMATOR_FUZZ_SANITIZERS})
if(NOT ANIMATOR_FUZZ_SANITIZERS MATCHES "address")
  # Without ASan, libstdc++'s own checks catch an index past the end of a container.
  add_compile_definitions(_GLIBCXX_ASSERTIONS)
endif()

add_subdirectory(sdk)
add_subdirectory(host) # the document model and the asset loader only (host/CMakeLists.txt)
add_subdirectory(plugins/io-ani)
add_subdirectory(plugins/io-lua)

enable_testing()
add_subdirectory(tests/fuzz)
