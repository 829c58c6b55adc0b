// The one translation unit that compiles tinygltf's implementation (Debian ships the header; the
// configuration macros come from render_check/CMakeLists.txt). Nothing else belongs here.
#define TINYGLTF_IMPLEMENTATION
#include <tiny_gltf.h>
