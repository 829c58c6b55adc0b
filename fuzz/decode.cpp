#include "decode.hpp"

#include <algorithm>
#include <cstring>
#include <stdexcept>

#include <rotorcert/reference/scalar.hpp>

namespace rotorcert::fuzz {

std::size_t element_count(const engine::AbiOp& op, std::size_t a, std::size_t k) {
  const engine::Array& arr = op.inputs[a];
  return static_cast<std::size_t>(arr.stride) * (arr.per_influence ? k : 1);
}

bool decode(const std::uint8_t* data, std::size_t size, const std::vector<std::string>& family_ops, Decoded& out) {
  if (size < 2 || family_ops.empty()) return false;
  const engine::AbiOp* op = engine::find_abi_op(family_ops[data[0] % family_ops.size()]);
  if (op == nullptr) return false;
  const bool f64 = (data[1] & 1) != 0;
  const std::size_t word = f64 ? 8 : 4;
  const std::size_t k = op->nway ? std::size_t(data[1] >> 4) % (kMaxInfluences + 1) : 0;
  std::size_t per_element = 0;
  for (std::size_t a = 0; a < op->inputs.size(); ++a) per_element += element_count(*op, a, k);
  // With k = 0 an n-way op has no input words at all (the empty influence set, EDGE-9).
  const std::size_t available = per_element == 0 ? kMaxElements : (size - 2) / (per_element * word);
  const std::size_t n = std::min<std::size_t>(std::size_t((data[1] >> 1) & 7) + 1, available);
  if (n == 0) return false;

  out.op = op;
  out.f64 = f64;
  out.n = n;
  out.k = k;
  out.raw.assign(op->inputs.size(), {});
  out.cases_.assign(n, std::nullopt);
  const std::uint8_t* p = data + 2;
  for (std::size_t e = 0; e < n; ++e)
    for (std::size_t a = 0; a < op->inputs.size(); ++a) {
      const std::size_t bytes = element_count(*op, a, k) * word;  // one element's array is contiguous
      out.raw[a].insert(out.raw[a].end(), p, p + bytes);
      p += bytes;
    }
  return true;
}

std::vector<double> Decoded::words(std::size_t e, std::size_t a) const {
  const std::size_t word = f64 ? 8 : 4, count = element_count(*op, a, k);
  const unsigned char* p = raw[a].data() + e * count * word;
  std::vector<double> out(count);
  for (std::size_t j = 0; j < count; ++j, p += word) {
    if (f64) {
      std::memcpy(&out[j], p, 8);
    } else {
      float x;
      std::memcpy(&x, p, 4);
      out[j] = x;  // exact, NaN payloads aside (the judge reads a NaN as NaN)
    }
  }
  return out;
}

const engine::Case& Decoded::exact_case(std::size_t e) const {
  std::optional<engine::Case>& c = cases_.at(e);
  if (!c) {
    c.emplace();
    c->k = k;
    c->label = "fuzz";
    c->inputs.assign(op->inputs.size(), {});
    for (std::size_t a = 0; a < op->inputs.size(); ++a)
      for (const double x : words(e, a)) c->inputs[a].push_back(ref::Real(x));
  }
  return *c;
}

std::vector<std::uint8_t> header(const std::vector<std::string>& family_ops, const std::string& op, bool f64,
                                 std::size_t n, std::size_t k) {
  const auto it = std::find(family_ops.begin(), family_ops.end(), op);
  if (it == family_ops.end()) throw std::invalid_argument("op " + op + " is not in the family");
  if (n < 1 || n > kMaxElements || k > kMaxInfluences) throw std::invalid_argument("n or k out of range");
  return {static_cast<std::uint8_t>(it - family_ops.begin()),
          static_cast<std::uint8_t>((f64 ? 1 : 0) | ((n - 1) << 1) | (k << 4))};
}

std::vector<std::uint8_t> encode(const std::vector<std::string>& family_ops, const std::string& op, ref::Format format,
                                 const std::vector<engine::Case>& cases) {
  const bool f64 = format == ref::Format::binary64;
  const std::size_t k = cases.empty() ? 0 : cases.front().k;
  std::vector<std::uint8_t> bytes = header(family_ops, op, f64, cases.size(), k);
  for (const engine::Case& c : cases)
    for (const auto& arr : c.inputs)
      for (const ref::Real& x : arr) {
        unsigned char w[8];
        if (f64) {
          const double d = mpfr_get_d(x.mpfr_srcptr(), MPFR_RNDN);
          std::memcpy(w, &d, 8);
        } else {
          const float f = mpfr_get_flt(x.mpfr_srcptr(), MPFR_RNDN);
          std::memcpy(w, &f, 4);
        }
        bytes.insert(bytes.end(), w, w + (f64 ? 8 : 4));
      }
  return bytes;
}

}  // namespace rotorcert::fuzz
