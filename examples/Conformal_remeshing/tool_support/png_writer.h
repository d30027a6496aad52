// Copyright (c) 2026 CGAL Conformal Remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A PNG writer for the tools' pictures: RGB, 8 bits. The image data is compressed by zlib when
// the tools are built with it (CONFORMAL_REMESHING_TOOLS_WITH_ZLIB, set by CMake when zlib is
// found), and written in stored (uncompressed) deflate blocks otherwise, which every PNG reader
// accepts too.

#ifndef CGAL_CONFORMAL_REMESHING_TOOLS_PNG_WRITER_H
#define CGAL_CONFORMAL_REMESHING_TOOLS_PNG_WRITER_H

#include <algorithm>
#include <array>
#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

#ifdef CONFORMAL_REMESHING_TOOLS_WITH_ZLIB
#include <zlib.h>
#endif

namespace Conformal_remeshing_tools {

struct Rgb_image
{
  int width = 0, height = 0;
  std::vector<std::uint8_t> pixels; // row by row, 3 bytes a pixel

  Rgb_image(int w, int h, std::array<std::uint8_t, 3> background = {{255, 255, 255}})
    : width(w), height(h), pixels(std::size_t(w) * std::size_t(h) * 3)
  {
    for(std::size_t i = 0; i < pixels.size(); ++i)
      pixels[i] = background[i % 3];
  }

  void set(int x, int y, std::array<std::uint8_t, 3> c)
  {
    if(x < 0 || y < 0 || x >= width || y >= height)
      return;
    const std::size_t i = (std::size_t(y) * std::size_t(width) + std::size_t(x)) * 3;
    pixels[i] = c[0];
    pixels[i + 1] = c[1];
    pixels[i + 2] = c[2];
  }
};

namespace internal {

inline std::uint32_t crc32(const std::uint8_t* data, std::size_t n, std::uint32_t crc = 0)
{
  static std::array<std::uint32_t, 256> table = [] {
    std::array<std::uint32_t, 256> t{};
    for(std::uint32_t i = 0; i < 256; ++i)
    {
      std::uint32_t c = i;
      for(int k = 0; k < 8; ++k)
        c = (c & 1) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
      t[i] = c;
    }
    return t;
  }();
  crc = ~crc;
  for(std::size_t i = 0; i < n; ++i)
    crc = table[(crc ^ data[i]) & 0xFF] ^ (crc >> 8);
  return ~crc;
}

inline void put32(std::vector<std::uint8_t>& out, std::uint32_t v)
{
  for(int s = 24; s >= 0; s -= 8)
    out.push_back(std::uint8_t(v >> s));
}

inline void write_chunk(std::ostream& out, const char* type, const std::vector<std::uint8_t>& data)
{
  std::vector<std::uint8_t> chunk;
  chunk.reserve(12 + data.size()); // length, type, data, CRC
  put32(chunk, std::uint32_t(data.size()));
  chunk.insert(chunk.end(), type, type + 4);
  chunk.insert(chunk.end(), data.begin(), data.end());
  put32(chunk, crc32(chunk.data() + 4, chunk.size() - 4));
  out.write(reinterpret_cast<const char*>(chunk.data()), std::streamsize(chunk.size()));
}

// The zlib stream of `raw`: compressed by zlib when available, else in stored blocks.
inline std::vector<std::uint8_t> zlib_stream(const std::vector<std::uint8_t>& raw)
{
#ifdef CONFORMAL_REMESHING_TOOLS_WITH_ZLIB
  uLongf size = compressBound(uLong(raw.size()));
  std::vector<std::uint8_t> packed(size);
  if(compress2(packed.data(), &size, raw.data(), uLong(raw.size()), 9) == Z_OK)
  {
    packed.resize(size);
    return packed;
  }
#endif
  std::vector<std::uint8_t> zlib = {0x78, 0x01};
  for(std::size_t offset = 0; offset < raw.size() || offset == 0;)
  {
    const std::size_t n = std::min<std::size_t>(65535, raw.size() - offset);
    const bool last = offset + n == raw.size();
    zlib.push_back(last ? 1 : 0);
    zlib.push_back(std::uint8_t(n & 0xFF));
    zlib.push_back(std::uint8_t(n >> 8));
    zlib.push_back(std::uint8_t(~n & 0xFF));
    zlib.push_back(std::uint8_t((~n >> 8) & 0xFF));
    zlib.insert(zlib.end(), raw.begin() + std::ptrdiff_t(offset), raw.begin() + std::ptrdiff_t(offset + n));
    offset += n;
    if(last)
      break;
  }
  std::uint32_t a = 1, b = 0; // Adler-32 of the uncompressed data
  for(std::uint8_t byte : raw)
  {
    a = (a + byte) % 65521;
    b = (b + a) % 65521;
  }
  put32(zlib, (b << 16) | a);
  return zlib;
}

} // namespace internal

inline bool write_png(std::ostream& out, const Rgb_image& image)
{
  static const std::uint8_t signature[8] = {137, 80, 78, 71, 13, 10, 26, 10};
  out.write(reinterpret_cast<const char*>(signature), 8);

  std::vector<std::uint8_t> header;
  internal::put32(header, std::uint32_t(image.width));
  internal::put32(header, std::uint32_t(image.height));
  header.insert(header.end(), {8, 2, 0, 0, 0}); // 8 bits, RGB, deflate, no filter, no interlace
  internal::write_chunk(out, "IHDR", header);

  // Scanlines, each after a filter byte 0, in one zlib stream.
  std::vector<std::uint8_t> raw;
  const std::size_t row = std::size_t(image.width) * 3;
  for(int y = 0; y < image.height; ++y)
  {
    raw.push_back(0);
    raw.insert(raw.end(), image.pixels.begin() + std::ptrdiff_t(y * row), image.pixels.begin() + std::ptrdiff_t((y + 1) * row));
  }
  internal::write_chunk(out, "IDAT", internal::zlib_stream(raw));
  internal::write_chunk(out, "IEND", {});
  return bool(out);
}

} // namespace Conformal_remeshing_tools

#endif // CGAL_CONFORMAL_REMESHING_TOOLS_PNG_WRITER_H
