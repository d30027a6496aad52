// Copyright (c) 2026 CGAL Conformal Remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What the planar stage remembers at planar points: a hash map keyed by a point's coordinates
// (the size field at the refinement's corners, the lifts the remesher made), and the size-field
// query with a search hint, which the refinement's criteria and the frontal insertion share.

#ifndef CGAL_CONFORMAL_REMESHING_INTERNAL_REMESHING_PLANAR_POINT_MAP_H
#define CGAL_CONFORMAL_REMESHING_INTERNAL_REMESHING_PLANAR_POINT_MAP_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Conformal_remeshing {
namespace internal {
namespace remeshing {

/// A hash of a planar point: a multiply-xorshift mix of its coordinates' bits, whose top bits
/// are the best mixed (+0. turns -0. into 0., as the two compare equal).
inline std::uint64_t planar_point_hash(double x, double y)
{
  const auto bits = [](double d) {
    d += 0.;
    std::uint64_t b;
    std::memcpy(&b, &d, sizeof b);
    return b;
  };
  const std::uint64_t h = (bits(x) * 0x9e3779b97f4a7c15ull) ^ (bits(y) * 0xc2b2ae3d27d4eb4full);
  return (h ^ (h >> 32)) * 0xbf58476d1ce4e5b9ull;
}

/// A map from planar points to what was computed there, for the searches that remember their
/// answers (the size field at the refinement's corners).
/// The entries lie in one array in the order they came, which is by neighbourhood, and the table
/// that finds them, open addressing with linear probing, holds 8 bytes a slot: the entry's
/// number and bits of its hash, so that a probe rarely opens an entry that is not the one. It
/// replaces `std::unordered_map`, whose lookups followed a bucket to a node in the heap and
/// divided by a prime. Keys compare with `==` (-0. equals 0.); no point is NaN. Pointers to values
/// stay valid until an insertion finds the map full; `reserve()` first to keep them over several.
template <typename Value>
class Planar_point_map
{
public:
  Planar_point_map() { rehash(16); }

  /// The value at `p`, or null.
  Value* find(const Epick::Point_2& p)
  {
    const Slot s = slots_[slot_of(p, planar_point_hash(p.x(), p.y()))];
    return s.entry == 0 ? nullptr : &entries_[s.entry - 1].value;
  }

  /// The value at `p` and `true` if it was inserted as `value` now, `false` if it was there.
  std::pair<Value*, bool> try_emplace(const Epick::Point_2& p, const Value& value)
  {
    reserve(entries_.size() + 1);
    const std::uint64_t h = planar_point_hash(p.x(), p.y());
    Slot& s = slots_[slot_of(p, h)];
    if(s.entry != 0)
      return {&entries_[s.entry - 1].value, false};
    entries_.push_back(Entry{p.x(), p.y(), value});
    s = Slot{std::uint32_t(entries_.size()), std::uint32_t(h)};
    return {&entries_.back().value, true};
  }

  /// Room for `n` points without moving the values (at most half the slots used).
  void reserve(std::size_t n)
  {
    if(n > entries_.capacity())
      entries_.reserve((std::max)(n, 2 * entries_.capacity()));
    if(2 * n > slots_.size())
    {
      std::size_t capacity = slots_.size();
      while(2 * n > capacity)
        capacity *= 2;
      rehash(capacity);
    }
  }

  std::size_t size() const { return entries_.size(); }

private:
  struct Slot
  {
    std::uint32_t entry; // 1 + the entry's index, 0 when the slot is free
    std::uint32_t tag;   // the low bits of the entry's hash
  };
  struct Entry
  {
    double x, y;
    Value value;
  };

  // The slot that holds `p` (whose hash is `h`), or the free one where its probe ends: the
  // probe starts at the slot the hash's top bits choose.
  std::size_t slot_of(const Epick::Point_2& p, std::uint64_t h) const
  {
    std::size_t i = std::size_t(h >> shift_);
    while(slots_[i].entry != 0
          && !(slots_[i].tag == std::uint32_t(h) && entries_[slots_[i].entry - 1].x == p.x() && entries_[slots_[i].entry - 1].y == p.y()))
      i = (i + 1) & mask_;
    return i;
  }

  void rehash(std::size_t capacity)
  {
    slots_.assign(capacity, Slot{0, 0});
    mask_ = capacity - 1;
    shift_ = 64;
    for(std::size_t c = capacity; c > 1; c /= 2)
      --shift_;
    for(std::size_t e = 0; e < entries_.size(); ++e)
    {
      const std::uint64_t h = planar_point_hash(entries_[e].x, entries_[e].y);
      std::size_t i = std::size_t(h >> shift_);
      while(slots_[i].entry != 0)
        i = (i + 1) & mask_;
      slots_[i] = Slot{std::uint32_t(e + 1), std::uint32_t(h)};
    }
  }

  std::vector<Slot> slots_;
  std::vector<Entry> entries_;
  std::size_t mask_ = 0;
  int shift_ = 64;
};

/// Where a size field found a point, for a query nearby to start from (an index the field
/// defines: the remesher's is a flat triangle).
typedef std::size_t Size_field_hint;
constexpr Size_field_hint no_size_field_hint = Size_field_hint(-1);

/// The size field at `p`: `size(p, hint)` when the field takes a hint (it starts its search from
/// `hint` and sets it to where it found `p`), else `size(p)`.
template <typename Size_field>
double size_field_at(const Size_field& size, const Epick::Point_2& p, Size_field_hint& hint)
{
  if constexpr(std::is_invocable_r_v<double, const Size_field&, const Epick::Point_2&, Size_field_hint&>)
    return size(p, hint);
  else
    return size(p);
}

} // namespace remeshing
} // namespace internal
} // namespace Conformal_remeshing
} // namespace CGAL

#endif // CGAL_CONFORMAL_REMESHING_INTERNAL_REMESHING_PLANAR_POINT_MAP_H
