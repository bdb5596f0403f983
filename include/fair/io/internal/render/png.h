// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// 8-bit RGB PNG encoding and decoding in memory through libpng, and base64 (RFC 4648) for the
// data URI of the SVG wrapper.
//
// libpng reports errors by longjmp to the setjmp point of the call. The functions calling
// setjmp (encode_png_c, decode_png_c) therefore hold no C++ object with a destructor between
// setjmp and the libpng calls: they work on plain pointers, and the C++ wrappers below turn
// their status into typed errors.

#ifndef FAIR_IO_INTERNAL_RENDER_PNG_H
#define FAIR_IO_INTERNAL_RENDER_PNG_H

#include <fair/Errors.h>

#include <png.h>

#include <csetjmp>
#include <cstddef>
#include <cstring>
#include <string>
#include <vector>

namespace fair {
namespace io {
namespace internal {
namespace render {

constexpr int max_png_side = 1 << 14;  // larger images are rejected before allocating width*height*3

struct Png_sink {
  std::string* bytes;
  bool failed;
};

inline void png_sink_write(png_structp png, png_bytep data, png_size_t length) {
  Png_sink* sink = static_cast<Png_sink*>(png_get_io_ptr(png));
  try {
    sink->bytes->append(reinterpret_cast<const char*>(data), length);
  } catch (...) {
    sink->failed = true;
    png_error(png, "out of memory");
  }
}

inline void png_sink_flush(png_structp) {}

inline void png_quiet_warning(png_structp, png_const_charp) {}

/// Returns 0 on success. `rgb` holds height rows of 3 * width bytes.
inline int encode_png_c(const unsigned char* rgb, int width, int height, Png_sink* sink) {
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, png_quiet_warning);
  if (!png) return 1;
  png_infop info = png_create_info_struct(png);
  if (!info) {
    png_destroy_write_struct(&png, nullptr);
    return 1;
  }
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    return 2;
  }
  png_set_write_fn(png, sink, png_sink_write, png_sink_flush);
  png_set_IHDR(png, info, static_cast<png_uint_32>(width), static_cast<png_uint_32>(height), 8, PNG_COLOR_TYPE_RGB,
               PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_write_info(png, info);
  for (int y = 0; y < height; ++y)
    png_write_row(png, const_cast<png_bytep>(rgb + static_cast<std::size_t>(y) * 3 * width));
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  return 0;
}

/// The PNG file content of an 8-bit RGB image (rows top to bottom, 3 bytes per pixel).
inline std::string encode_png(const std::vector<unsigned char>& rgb, int width, int height) {
  fair::internal::require(width > 0 && height > 0 && width <= max_png_side && height <= max_png_side &&
                              rgb.size() == static_cast<std::size_t>(width) * height * 3,
                          "write_png: an image of ", width, " x ", height, " pixels needs ",
                          3.0 * width * height, " bytes, got ", rgb.size());
  std::string bytes;
  Png_sink sink{&bytes, false};
  const int status = encode_png_c(rgb.data(), width, height, &sink);
  if (status != 0) throw Error(fair::internal::message("write_png: libpng failed (status ", status, ")"));
  return bytes;
}

struct Png_source {
  const unsigned char* data;
  std::size_t size, at;
};

inline void png_source_read(png_structp png, png_bytep out, png_size_t length) {
  Png_source* src = static_cast<Png_source*>(png_get_io_ptr(png));
  if (length > src->size - src->at) png_error(png, "truncated PNG data");
  std::memcpy(out, src->data + src->at, length);
  src->at += length;
}

/// Returns 0 on success; fills width, height and the RGB bytes.
inline int decode_png_c(Png_source* src, int* width, int* height, std::vector<unsigned char>* rgb) {
  if (src->size < 8 || png_sig_cmp(src->data, 0, 8) != 0) return 3;
  png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, png_quiet_warning);
  if (!png) return 1;
  png_infop info = png_create_info_struct(png);
  if (!info) {
    png_destroy_read_struct(&png, nullptr, nullptr);
    return 1;
  }
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_read_struct(&png, &info, nullptr);
    return 2;
  }
  png_set_read_fn(png, src, png_source_read);
  png_set_user_limits(png, max_png_side, max_png_side);
  png_read_png(png, info,
               PNG_TRANSFORM_STRIP_16 | PNG_TRANSFORM_PACKING | PNG_TRANSFORM_EXPAND | PNG_TRANSFORM_STRIP_ALPHA |
                   PNG_TRANSFORM_GRAY_TO_RGB,
               nullptr);
  const png_uint_32 w = png_get_image_width(png, info), h = png_get_image_height(png, info);
  if (png_get_channels(png, info) != 3 || png_get_bit_depth(png, info) != 8) {
    png_destroy_read_struct(&png, &info, nullptr);
    return 4;
  }
  png_bytepp rows = png_get_rows(png, info);
  *width = static_cast<int>(w);
  *height = static_cast<int>(h);
  rgb->resize(static_cast<std::size_t>(w) * h * 3);  // at most max_png_side^2 * 3 bytes (user limits)
  for (png_uint_32 y = 0; y < h; ++y) std::memcpy(rgb->data() + static_cast<std::size_t>(y) * 3 * w, rows[y], 3 * w);
  png_destroy_read_struct(&png, &info, nullptr);
  return 0;
}

/// Decodes PNG file content to 8-bit RGB. \throws Parse_error on data that is not a PNG.
inline void decode_png(const std::string& bytes, const std::string& where, int& width, int& height,
                       std::vector<unsigned char>& rgb) {
  Png_source src{reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size(), 0};
  const int status = decode_png_c(&src, &width, &height, &rgb);
  if (status == 3) throw Parse_error(where, 0, "not a PNG file (bad signature)");
  if (status != 0) throw Parse_error(where, 0, fair::internal::message("unreadable PNG data (libpng status ", status, ")"));
}

/// Base64 (RFC 4648, with padding) of `bytes`.
inline std::string base64(const std::string& bytes) {
  static const char* table = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  std::size_t i = 0;
  for (; i + 2 < bytes.size(); i += 3) {
    const unsigned v = (static_cast<unsigned char>(bytes[i]) << 16) | (static_cast<unsigned char>(bytes[i + 1]) << 8) |
                       static_cast<unsigned char>(bytes[i + 2]);
    out += table[(v >> 18) & 63];
    out += table[(v >> 12) & 63];
    out += table[(v >> 6) & 63];
    out += table[v & 63];
  }
  if (i < bytes.size()) {
    const bool two = i + 1 < bytes.size();
    const unsigned v = (static_cast<unsigned char>(bytes[i]) << 16) |
                       (two ? static_cast<unsigned char>(bytes[i + 1]) << 8 : 0u);
    out += table[(v >> 18) & 63];
    out += table[(v >> 12) & 63];
    out += two ? table[(v >> 6) & 63] : '=';
    out += '=';
  }
  return out;
}

} // namespace render
} // namespace internal
} // namespace io
} // namespace fair

#endif // FAIR_IO_INTERNAL_RENDER_PNG_H
