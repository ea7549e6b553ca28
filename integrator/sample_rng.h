// Random numbers as a pure function of (pixel, sample, seed): the same image for any thread
// count or tile order. A counter-based generator: a 64-bit hash of the key, then a
// splitmix64 sequence.
#pragma once

#include <cstdint>

namespace darc {

class SampleRng {
 public:
  SampleRng(uint32_t px, uint32_t py, uint32_t sample, uint32_t seed) {
    state_ = mix((uint64_t(px) << 32) ^ py);
    state_ = mix(state_ ^ (uint64_t(sample) << 32) ^ seed);
  }
  // Uniform in [0, 1).
  float next_float() { return float(next_u64() >> 40) * 0x1.0p-24f; }
  uint64_t next_u64() {
    state_ += 0x9E3779B97F4A7C15ull;
    return mix(state_);
  }

 private:
  static uint64_t mix(uint64_t z) {
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  uint64_t state_;
};

}  // namespace darc
