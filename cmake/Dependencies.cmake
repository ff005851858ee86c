# Every dependency comes from a Debian package (tools/install-deps.sh installs them); nothing is
# downloaded by the build.

find_package(PkgConfig REQUIRED)
find_package(Threads REQUIRED)

# What the file readers need: meshes (assimp), images (stb), Lua scenes, and GLM. The fuzz
# build (ANIMATOR_FUZZ, docs/fuzzing.md) builds only the readers, so it stops here.
find_package(glm REQUIRED)
find_package(assimp REQUIRED)
pkg_check_modules(STB REQUIRED IMPORTED_TARGET stb)
# Lua built as C++: its errors are exceptions, so C++ destructors run when a scene fails.
pkg_check_modules(LUA REQUIRED IMPORTED_TARGET lua5.4-c++)
if(ANIMATOR_FUZZ)
  return()
endif()

# Physics: Bullet in double precision, to match the custom solver's doubles.
pkg_check_modules(BULLET REQUIRED IMPORTED_TARGET bullet-float64)
# Boost.Math (headers only; sdk/src): the Jacobi elliptic functions and elliptic integrals of the exact
# torque-free rotation (plugins/physics-custom/free_rotation.cpp).
find_package(Boost 1.71 REQUIRED)
# Windowing and OpenGL.
find_package(glfw3 3.3 REQUIRED)
# Xlib: the editor reads the X server's time of each click (host/editor/click_times.hpp).
find_package(X11 REQUIRED)
find_package(OpenGL REQUIRED COMPONENTS OpenGL EGL) # EGL: off-screen rendering without a display
# meshoptimizer: the renderer's levels of detail (host/render/mesh_lod.hpp).
find_package(meshoptimizer REQUIRED)
find_package(PNG REQUIRED) # libpng: rendered frames written as PNG (render/png_frame_writer.hpp)
# Dear ImGui (static, with the GLFW and OpenGL3 backends) and stb.
pkg_check_modules(IMGUI REQUIRED IMPORTED_TARGET imgui stb)
find_package(SFML 2.5 COMPONENTS audio system REQUIRED)
find_package(Catch2 2 REQUIRED)
find_package(CLI11 REQUIRED)
# JSON (headers only): `animator info --json`.
find_package(nlohmann_json 3 REQUIRED)
# glTF: `animator export` (host/export, docs/export.md).
find_package(TinyGLTF REQUIRED)

# glad: the OpenGL 3.3 core loader, generated at build time by Debian's python3-glad.
find_program(GLAD_EXECUTABLE glad REQUIRED)
set(GLAD_OUT ${CMAKE_BINARY_DIR}/glad)
add_custom_command(
  OUTPUT ${GLAD_OUT}/src/gl.c ${GLAD_OUT}/include/glad/gl.h
  COMMAND ${GLAD_EXECUTABLE} --quiet --reproducible --api gl:core=3.3 --out-path ${GLAD_OUT} c
  COMMENT "Generating the OpenGL 3.3 core loader with glad"
  VERBATIM)
add_library(glad STATIC ${GLAD_OUT}/src/gl.c)
target_include_directories(glad PUBLIC ${GLAD_OUT}/include)
target_link_libraries(glad PUBLIC ${CMAKE_DL_LIBS})
