// Copyright (c) 2026 CGAL Conformal Remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The barycentric coordinates of each face's corners in the input face the face lies in, for
// the welded patch and its flat regions. Almost every face of a patch is an input face itself,
// its corners at (1, 0, 0), (0, 1, 0) and (0, 0, 1), or a face of a retriangulated flat region,
// which has no input face of its own and keeps zeros; only the faces split along the welded
// boundary have other coordinates. Those alone are stored, so that a face takes 4 bytes instead
// of 72: the patches are kept, with their flattenings, until the output is glued, and on a large
// part 72 bytes a face would be a tenth of the run's memory.

#ifndef CGAL_CONFORMAL_REMESHING_INTERNAL_WELDING_CORNER_COORDINATES_H
#define CGAL_CONFORMAL_REMESHING_INTERNAL_WELDING_CORNER_COORDINATES_H

#include <array>
#include <cstdint>
#include <cstring>
#include <vector>

namespace CGAL {
namespace Conformal_remeshing {
namespace internal {
namespace welding {

/// The corner coordinates of a sequence of faces, read by value with `operator[]`. The stored
/// form is public for the patch jobs' serialization: `slot[f]` is `identity_slot`, `zero_slot`
/// or the index in `stored` of face `f`'s coordinates.
struct Corner_coordinates
{
  typedef std::array<std::array<double, 3>, 3> Value;
  static constexpr std::uint32_t identity_slot = 0xffffffffu, zero_slot = 0xfffffffeu;

  std::vector<std::uint32_t> slot;
  std::vector<Value> stored;

  static Value identity() { return {{{{1., 0., 0.}}, {{0., 1., 0.}}, {{0., 0., 1.}}}}; }

  std::size_t size() const { return slot.size(); }

  /// The coordinates of face `f`, bit for bit those it was given.
  Value operator[](std::size_t f) const
  {
    switch(slot[f])
    {
    case identity_slot: return identity();
    case zero_slot: return Value{};
    default: return stored[slot[f]];
    }
  }

  /// `n` faces, each an input face itself.
  void assign_identity(std::size_t n) { slot.assign(n, identity_slot); stored.clear(); }

  void set(std::size_t f, const Value& v)
  {
    const std::uint32_t kind = kind_of(v);
    if(kind != 0)
      slot[f] = kind;
    else if(slot[f] < zero_slot)
      stored[slot[f]] = v;
    else
      slot[f] = store(v);
  }

  void push_back(const Value& v)
  {
    const std::uint32_t kind = kind_of(v);
    slot.push_back(kind != 0 ? kind : store(v));
  }

  void shrink_to_fit()
  {
    slot.shrink_to_fit();
    stored.shrink_to_fit();
  }

private:
  // identity_slot or zero_slot when `v` is that value bit for bit (-0. is not 0. here), else 0.
  static std::uint32_t kind_of(const Value& v)
  {
    const Value one = identity(), none{};
    if(std::memcmp(&v, &one, sizeof v) == 0)
      return identity_slot;
    if(std::memcmp(&v, &none, sizeof v) == 0)
      return zero_slot;
    return 0;
  }

  std::uint32_t store(const Value& v)
  {
    stored.push_back(v);
    return std::uint32_t(stored.size() - 1);
  }
};

} // namespace welding
} // namespace internal
} // namespace Conformal_remeshing
} // namespace CGAL

#endif // CGAL_CONFORMAL_REMESHING_INTERNAL_WELDING_CORNER_COORDINATES_H
