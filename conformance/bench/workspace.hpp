// Memory for benchmark data: buffer sets laid out in one reusable block, replicated for the
// streaming sizes.
//
// Layout of a buffer set: the op's arrays one after another (inputs in OpSpec order, outputs,
// status bytes), each starting on a 64-byte boundary. A benchmark uses `sets` consecutive copies
// of its set; the timed loop calls the op on set 0, 1, ..., sets-1, 0, ... For in-cache sizes
// there is one set. For streaming sizes (n >= kStreamingSize) there are enough sets to span
// stream_bytes (default twice the last-level cache), so each set was evicted by the others
// before its next use and every call reads its inputs from, and writes its outputs to, memory.
// The copies hold the same values (set 0 copied): only the addresses matter for streaming.
//
// Google Benchmark calls a benchmark's function several times (growing the iteration count
// until min_time is reached), so preparation is cached: the workspace remembers the key of the
// last benchmark it was prepared for. Benchmarks run one at a time, so one block suffices.
#pragma once

#include <cstddef>
#include <cstring>
#include <memory>
#include <new>
#include <string>

namespace rotorcert::bench {

inline constexpr std::size_t kAlign = 64;  // a cache line; also every SIMD width of x86

/// Offsets of consecutive arrays, each kAlign-aligned.
class SetLayout {
 public:
  std::size_t add(std::size_t bytes) {
    const std::size_t at = size_;
    size_ += (bytes + kAlign - 1) / kAlign * kAlign;
    return at;
  }
  std::size_t size() const { return size_; }

 private:
  std::size_t size_ = 0;
};

/// How many copies of a set of set_bytes a batch of n elements cycles through.
inline std::size_t set_count(std::size_t n, std::size_t set_bytes, std::size_t stream_bytes, std::size_t streaming_n) {
  if (n < streaming_n || set_bytes == 0) return 1;
  const std::size_t sets = (stream_bytes + set_bytes - 1) / set_bytes;
  return sets < 2 ? 2 : sets;
}

class Workspace {
 public:
  /// The block prepared for `key`, or nullptr when the last preparation was for another key.
  std::byte* reuse(const std::string& key) { return key == key_ && !key_.empty() ? data_.get() : nullptr; }

  /// A kAlign-aligned block of at least `bytes`, now owned by `key`; the contents are those of
  /// a previous benchmark (the caller fills it).
  std::byte* fresh(const std::string& key, std::size_t bytes) {
    if (bytes > capacity_) {
      data_.reset();  // free first: the old and the new block need not fit together
      data_.reset(static_cast<std::byte*>(::operator new[](bytes, std::align_val_t{kAlign})));
      capacity_ = bytes;
    }
    key_ = key;
    return data_.get();
  }

  /// Forgets the key (a preparation that failed must be redone, not reused).
  void forget() { key_.clear(); }

 private:
  struct Free {
    void operator()(std::byte* p) const { ::operator delete[](p, std::align_val_t{kAlign}); }
  };
  std::unique_ptr<std::byte[], Free> data_;
  std::size_t capacity_ = 0;
  std::string key_;
};

/// The one workspace of the process.
inline Workspace& workspace() {
  static Workspace w;
  return w;
}

/// Copies set 0 (the first set_bytes of base) over sets 1 .. sets-1.
inline void replicate(std::byte* base, std::size_t set_bytes, std::size_t sets) {
  for (std::size_t s = 1; s < sets; ++s) std::memcpy(base + s * set_bytes, base, set_bytes);
}

}  // namespace rotorcert::bench
