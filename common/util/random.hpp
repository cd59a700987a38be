// Seeded randomness (docs/conventions.md): every random choice takes its seed from the scene seed
// and the name of the thing it seeds, so that adding a new random consumer never shifts
// another one's numbers.
#pragma once

#include <cstdint>
#include <initializer_list>
#include <random>
#include <string_view>

namespace plumbago {

// FNV-1a of the name, mixed with the seed (splitmix64 finalizer).
inline uint64_t named_seed(uint32_t seed, std::string_view name) {
  uint64_t h = 1469598103934665603ull;
  for (unsigned char c : name) h = (h ^ c) * 1099511628211ull;
  uint64_t z = h ^ (uint64_t(seed) * 0x9E3779B97F4A7C15ull);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

// lowbias32 (C. Wellons, "Prospecting for hash functions", 2018): a bijection of 32-bit
// integers whose output bits each flip with probability close to 1/2 for any input bit.
constexpr uint32_t hash32(uint32_t x) {
  x ^= x >> 16;
  x *= 0x7feb352du;
  x ^= x >> 15;
  x *= 0x846ca68bu;
  return x ^ (x >> 16);
}

// One key from several integers, each folded in through hash32: integer operations only,
// so that a shader can make the same key from the same numbers.
constexpr uint32_t stream_key(std::initializer_list<uint32_t> parts) {
  uint32_t key = 0;
  for (uint32_t p : parts) key = hash32(key ^ p);
  return key;
}

// named_seed folded to 32 bits, for a CounterStream.
inline uint32_t named_key(uint32_t seed, std::string_view name) {
  uint64_t s = named_seed(seed, name);
  return uint32_t(s ^ (s >> 32));
}

// A counter-based stream (Salmon et al. 2011, "Parallel random numbers: as easy as 1, 2, 3"):
// number k of the stream with key K is hash32(K ^ hash32(k)), so the numbers of any stream
// can be drawn where it is needed, in any order, with no state handed along: one thread
// per stroke on the GPU draws what the CPU draws. Uniforms have 24 bits, exact in float.
class CounterStream {
 public:
  explicit CounterStream(uint32_t key) : key_(key) {}
  // Uniform in [0, 1).
  double uniform() { return double(hash32(key_ ^ hash32(counter_++)) >> 8) * (1.0 / 16777216.0); }

 private:
  uint32_t key_, counter_ = 0;
};

// std::mt19937_64 is fully specified by the standard, so its sequence is the same on
// every platform. Use std::uniform_real_distribution only through uniform() below:
// the standard distributions are not portable across library implementations.
class Rng {
 public:
  Rng(uint32_t seed, std::string_view name) : engine_(named_seed(seed, name)) {}
  // Uniform in [0, 1).
  double uniform() { return double(engine_() >> 11) * (1.0 / 9007199254740992.0); }
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
  uint64_t next() { return engine_(); }

 private:
  std::mt19937_64 engine_;
};

}  // namespace plumbago
