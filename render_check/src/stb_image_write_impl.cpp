// The one translation unit that compiles stb_image_write (Debian's libstb-dev ships the header;
// its include directory is a SYSTEM directory so that the library's own warnings do not fail the
// build under -Werror).
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb_image_write.h>
