// common/util/random.hpp hash32, stream_key and CounterStream's k-th uniform.
uint hash32(uint x) {
  x ^= x >> 16;
  x *= 0x7feb352du;
  x ^= x >> 15;
  x *= 0x846ca68bu;
  return x ^ (x >> 16);
}
uint stream_key(uint a, uint b, uint c) { return hash32(hash32(hash32(a) ^ b) ^ c); }
uint stream_key(uint a, uint b, uint c, uint d) { return hash32(stream_key(a, b, c) ^ d); }
double uniform_at(uint key, uint k) { return double(hash32(key ^ hash32(k)) >> 8) * (1.0lf / 16777216.0lf); }
