# The off-screen renderer and the image comparison of the render check (VIS-2): OSMesa
# (Debian libosmesa6-dev; Mesa's software OpenGL on llvmpipe, so frames need no GPU or display)
# and stb_image_write for PNG output (Debian libstb-dev, a header whose implementation is
# compiled once, in src/stb_image_write_impl.cpp).
# The top-level CMakeLists.txt may already have looked OSMesa up; look it up here otherwise.
if(NOT TARGET PkgConfig::OSMESA)
  find_package(PkgConfig REQUIRED)
  pkg_check_modules(OSMESA REQUIRED IMPORTED_TARGET osmesa)
endif()
find_path(ROTORCERT_STB_INCLUDE_DIR stb_image_write.h PATH_SUFFIXES stb REQUIRED)

add_library(rotorcert_render STATIC
  src/camera.cpp
  src/image.cpp
  src/osmesa_renderer.cpp
  src/stb_image_write_impl.cpp)
add_library(rotorcert::render ALIAS rotorcert_render)
target_link_libraries(rotorcert_render PUBLIC rotorcert::gltf PRIVATE PkgConfig::OSMESA)
# SYSTEM: stb's own warnings must not fail the -Werror build.
target_include_directories(rotorcert_render SYSTEM PRIVATE ${ROTORCERT_STB_INCLUDE_DIR})
rotorcert_warnings(rotorcert_render)

target_link_libraries(render_check_test_render_image PRIVATE rotorcert_render)
# The PNG round trip reads files back with stb_image, compiled in that test.
target_include_directories(render_check_test_render_image SYSTEM PRIVATE ${ROTORCERT_STB_INCLUDE_DIR})
target_link_libraries(render_check_test_render_osmesa PRIVATE rotorcert_render)
