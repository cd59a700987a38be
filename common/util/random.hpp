// Seeded randomness (docs/conventions.md): every random choice takes its seed from the scene seed
// and the name of the thing it seeds, so that adding a new random consumer never shifts
// another one's numbers.
#pragma once

#include <cstdint>
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
