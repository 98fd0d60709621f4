#pragma once
/// \file SplitMix.hpp
/// \brief A tiny seeded generator whose sequence is the same on every platform and standard library
/// (std::uniform_real_distribution is not), so a seed always gives the same particles.

#include <cstdint>

namespace hikiln::dem {

/// \brief SplitMix64 (Steele, Lea & Flood 2014): 64-bit state, one multiply-xorshift per draw.
class SplitMix64 {
public:
  /// \brief Generator started from `seed`.
  explicit SplitMix64(std::uint64_t seed) : _state(seed) {}
  /// \brief Next 64 random bits.
  std::uint64_t next() {
    std::uint64_t z = (_state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  /// \brief Uniform double in [0, 1) with 53 random bits.
  double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }

private:
  std::uint64_t _state;
};

} // namespace hikiln::dem
