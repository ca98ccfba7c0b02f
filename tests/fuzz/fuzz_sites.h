// The site sets of the fuzz targets: a small set decoded from any bytes, rich in ties (shared by
// fuzz_vertices and fuzz_diagram).
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

#include "predicates/site.h"

namespace apollonius::fuzzing {

constexpr std::size_t kMaxSites = 12;  // the brute force is O(n^5): 12 sites keep an input in milliseconds

// Reads the input front to back; missing bytes read as 0, so that every input decodes.
class Byte_reader {
 public:
  Byte_reader(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}
  std::uint8_t byte() { return position_ < size_ ? data_[position_++] : 0; }
  template <class T>
  T bits() {
    std::uint8_t bytes[sizeof(T)];
    for (std::uint8_t& b : bytes) b = byte();
    T value;
    std::memcpy(&value, bytes, sizeof(T));
    return value;
  }

 private:
  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t position_ = 0;
};

// One value: a tag byte, then its payload. Small integers and eighths make lattices, ties and
// cospherical sets likely; repeats and one-ulp neighbours of earlier values make equal and nearly equal
// coordinates and weights; m * 2^e reaches huge, tiny and subnormal values; raw bits reach every double.
// Returns false for NaN or infinity, which the reader refuses too.
inline bool decode_value(Byte_reader& in, const std::vector<double>& earlier, double& value) {
  switch (in.byte() % 8) {
    case 0:
    case 1: value = static_cast<double>(static_cast<int>(in.byte() % 9) - 4); break;
    case 2: value = static_cast<double>(in.bits<std::int8_t>()) / 8; break;
    case 3: value = earlier.empty() ? 0.0 : earlier[in.byte() % earlier.size()]; break;
    case 4: {
      const std::uint8_t b = in.byte();
      const double base = earlier.empty() ? 0.0 : earlier[(b >> 1) % earlier.size()];
      value = std::nextafter(base, (b & 1) ? std::numeric_limits<double>::infinity() : -std::numeric_limits<double>::infinity());
      break;
    }
    case 5: {
      const int mantissa = in.bits<std::int8_t>();
      const int exponent = static_cast<int>(in.bits<std::uint16_t>() % 2201) - 1100;
      value = std::ldexp(static_cast<double>(mantissa), exponent);
      break;
    }
    default: value = in.bits<double>(); break;
  }
  return std::isfinite(value);
}

// Byte 0 gives the number of sites, 1 to kMaxSites; then x, y, z, w of each site in turn.
inline bool decode_sites(const std::uint8_t* data, std::size_t size, std::vector<Site>& sites) {
  Byte_reader in(data, size);
  const std::size_t n = 1 + in.byte() % kMaxSites;
  std::vector<double> values;
  for (std::size_t i = 0; i < 4 * n; ++i) {
    double value;
    if (!decode_value(in, values, value)) return false;
    values.push_back(value);
  }
  for (std::size_t i = 0; i < n; ++i) sites.push_back({values[4 * i], values[4 * i + 1], values[4 * i + 2], values[4 * i + 3]});
  return true;
}

// Beyond 2^-12 of the double range the octree's root box overflows (octree_diagram.h): a documented
// limitation, not a finding.
inline bool centres_reach_double_range_limit(const std::vector<Site>& sites) {
  const double limit = std::ldexp(std::numeric_limits<double>::max(), -12);
  for (const Site& s : sites)
    if (std::fabs(s.x) >= limit || std::fabs(s.y) >= limit || std::fabs(s.z) >= limit) return true;
  return false;
}

}  // namespace apollonius::fuzzing
