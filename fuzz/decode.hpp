// Bit-exact decoding of fuzzer input into one batched call of an ABI operation.
//
// Input layout (every harness of an operation family):
//   byte 0    the operation: family_ops[byte % family_ops.size()]
//   byte 1    bit 0: scalar type (0 binary32, 1 binary64);
//             bits 1-3: n - 1, elements in the batch (1..8; SIMD tables see tails and full lanes);
//             bits 4-7: k = (byte >> 4) % 9, influences per element of n-way ops (0..8; 0 is the
//             empty set, EDGE-9)
//   then      raw little-endian words, 4 bytes (binary32) or 8 bytes (binary64) each, memcpy'd
//             into the scalar type: element 0's input arrays in ABI order (impl_abi.h), then
//             element 1's, ... Every bit pattern is a value: each NaN payload, signalling NaNs,
//             +-0, subnormals, +-Inf. n shrinks to the number of complete elements present;
//             trailing bytes are ignored. No complete element: the input is skipped.
// The implementation receives the decoded bits unchanged (NaN payloads included); the judge
// sees them as exact values (a NaN as NaN).
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <rotorcert/engine/abi_op.hpp>
#include <rotorcert/engine/cases.hpp>

namespace rotorcert::fuzz {

inline constexpr std::size_t kMaxElements = 8;
inline constexpr std::size_t kMaxInfluences = 8;  // the spec's n <= 8 (blend and skinning rules)

/// One decoded batch: the arrays as the implementation receives them, and the same values exactly.
struct Decoded {
  const engine::AbiOp* op = nullptr;
  bool f64 = false;
  std::size_t n = 0, k = 0;
  /// Per input array of the op, n elements back to back (ABI layout), as raw words: the bits of
  /// floats (binary32, 4 bytes each) or doubles (binary64, 8 bytes each).
  std::vector<std::vector<unsigned char>> raw;
  ref::Format format() const { return f64 ? ref::Format::binary64 : ref::Format::binary32; }

  /// Element e's inputs as exact values (label "fuzz"), made on first use: the oracle reads the
  /// judgement of most elements from its memo and never needs their MPFR values.
  const engine::Case& exact_case(std::size_t e) const;
  /// Element e's input words in array a, one double per word (every float and double is one).
  std::vector<double> words(std::size_t e, std::size_t a) const;

 private:
  friend bool decode(const std::uint8_t*, std::size_t, const std::vector<std::string>&, Decoded&);
  mutable std::vector<std::optional<engine::Case>> cases_;
};

/// Scalars of input array a for one element (k influences for per-influence arrays).
std::size_t element_count(const engine::AbiOp& op, std::size_t a, std::size_t k);

/// Decodes data as described above. False if it holds no complete element.
bool decode(const std::uint8_t* data, std::size_t size, const std::vector<std::string>& family_ops, Decoded& out);

/// The inverse, for seed corpora: one batch of `cases` (same k) of family_ops[op_index] in
/// `format`, each value rounded to the format (NaN payloads are written with header() and raw words).
std::vector<std::uint8_t> encode(const std::vector<std::string>& family_ops, const std::string& op, ref::Format format,
                                 const std::vector<engine::Case>& cases);

/// The header bytes of an input (for hand-made seeds whose words are written directly).
std::vector<std::uint8_t> header(const std::vector<std::string>& family_ops, const std::string& op, bool f64,
                                 std::size_t n, std::size_t k);

}  // namespace rotorcert::fuzz
