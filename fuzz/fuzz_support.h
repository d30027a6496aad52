// Copyright (c) 2026 CGAL Conformal Remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What the libFuzzer targets share: stopping on a broken invariant, and reading values from the
// fuzzer's bytes.

#ifndef CGAL_CONFORMAL_REMESHING_FUZZ_SUPPORT_H
#define CGAL_CONFORMAL_REMESHING_FUZZ_SUPPORT_H

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace fuzz {

// Stops the fuzzer with a message: libFuzzer saves the input that broke the invariant.
[[noreturn]] inline void fail(const char* target, const char* what)
{
  std::fprintf(stderr, "%s: %s\n", target, what);
  std::abort();
}

// The fuzzer's bytes read in order; past the end every byte reads as 0, so that any input,
// however short, decodes to something.
class Bytes
{
public:
  Bytes(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}
  std::uint8_t next() { return at_ < size_ ? data_[at_++] : 0; }
  double signed_unit() { return (int(next()) - 128) / 128.; } // in [-1, 1)
  double raw_double() // any bit pattern: NaN, infinities, denormals, huge values
  {
    unsigned char raw[sizeof(double)];
    for(unsigned char& r : raw)
      r = next();
    double x = 0.;
    std::memcpy(&x, raw, sizeof(double));
    return x;
  }

private:
  const std::uint8_t* data_;
  std::size_t size_, at_ = 0;
};

} // namespace fuzz

#endif // CGAL_CONFORMAL_REMESHING_FUZZ_SUPPORT_H
