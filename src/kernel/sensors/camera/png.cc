// stb_image_write lays out the PNG (chunks, CRCs, row filters) and zlib deflates it: stb's own
// deflate took 3.5 ms for a flat 320 x 240 picture and 11 ms for one with read noise, zlib at its
// fastest with no row filter 0.3 and 2.2 ms, for pictures as small or smaller (measured on this
// machine), and the record takes every picture by default. stb's implementation is compiled here,
// static, so that its deflate can be zlib's (STBIW_ZLIB_COMPRESS).
#include "sensors/camera/png.h"

#include <zlib.h>

#include <cstdlib>

namespace {

// STBIW_ZLIB_COMPRESS's contract: a malloc'd zlib stream (stb frees it), its length in *out_length.
unsigned char* ZlibCompress(unsigned char* data, int length, int* out_length, int /*quality*/) {
  uLongf size = compressBound(static_cast<uLong>(length));
  auto* out = static_cast<unsigned char*>(std::malloc(size));
  if (!out || compress2(out, &size, data, static_cast<uLong>(length), Z_BEST_SPEED) != Z_OK) {
    std::free(out);
    return nullptr;
  }
  *out_length = static_cast<int>(size);
  return out;
}

}  // namespace

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wsign-compare"
#pragma GCC diagnostic ignored "-Wconversion"
#define STB_IMAGE_WRITE_STATIC
#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STBIW_ZLIB_COMPRESS ZlibCompress
#include <stb/stb_image_write.h>
#pragma GCC diagnostic pop

namespace sanet::sensors {

std::vector<std::uint8_t> EncodePng(const ImageReading& picture) {
  // No row filter: on rendered pictures the filters cost more than they save. Set once (threads).
  [[maybe_unused]] static const bool unfiltered = (stbi_write_force_png_filter = 0, true);
  std::vector<std::uint8_t> png;
  stbi_write_png_to_func(
      [](void* to, void* bytes, int size) {
        auto& out = *static_cast<std::vector<std::uint8_t>*>(to);
        out.insert(out.end(), static_cast<std::uint8_t*>(bytes), static_cast<std::uint8_t*>(bytes) + size);
      },
      &png, picture.width, picture.height, 3, picture.data.data(), picture.width * 3);
  return png;
}

}  // namespace sanet::sensors
