// Writes the seed corpora fuzz/corpus/<harness>/ (run by hand when the harnesses or the engine's
// cases change; the files are kept in the repository, findings are added beside them):
//   fuzz_make_corpus OUT_DIR
// Operation harnesses: one input per (op, clause, case label) of the engine's seeded cases
// (engine::checks_for_clause, seed 1, one case per family, worked examples included), binary64
// and binary32 alternately; one batch of 8 ordinary cases per op (SIMD lanes and tails); and
// hand-made words per op that no rounding can produce: quiet NaNs with payloads, signalling
// NaNs, -0, the smallest subnormal, +-Inf, the largest finite value.
// Parser harnesses: a few small exported vector files and results files of built-in tables.
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <string>

#include <rotorcert/registry.hpp>
#include <rotorcert/vectors/run.hpp>
#include <rotorcert/vectors/vector_file.hpp>

#include "decode.hpp"
#include "families.hpp"
#include "oracle.hpp"
#include "results_set.hpp"

namespace fs = std::filesystem;
using namespace rotorcert;

namespace {

void write(const fs::path& file, const std::string& bytes) {
  fs::create_directories(file.parent_path());
  std::ofstream out(file, std::ios::binary);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}
void write(const fs::path& file, const std::vector<std::uint8_t>& bytes) {
  write(file, std::string(bytes.begin(), bytes.end()));
}

std::string slug(const std::string& s) {
  std::string r;
  for (char c : s) r += (std::isalnum(static_cast<unsigned char>(c)) || c == '-') ? c : '_';
  while (r.find("__") != std::string::npos) r.erase(r.find("__"), 1);
  return r.substr(0, 60);
}

/// Raw words cycling through `pattern` (binary64 words or binary32 words) for every input value.
std::vector<std::uint8_t> raw_seed(const std::vector<std::string>& ops, const std::string& op, bool f64, std::size_t k,
                                   const std::vector<std::uint64_t>& pattern) {
  const engine::AbiOp& d = *engine::find_abi_op(op);
  std::vector<std::uint8_t> bytes = fuzz::header(ops, op, f64, 1, d.nway ? k : 0);
  std::size_t words = 0;
  for (std::size_t a = 0; a < d.inputs.size(); ++a) words += fuzz::element_count(d, a, d.nway ? k : 0);
  for (std::size_t i = 0; i < words; ++i) {
    const std::uint64_t w = pattern[i % pattern.size()];
    unsigned char b[8];
    if (f64) std::memcpy(b, &w, 8);
    else {
      const std::uint32_t v = static_cast<std::uint32_t>(w);
      std::memcpy(b, &v, 4);
    }
    bytes.insert(bytes.end(), b, b + (f64 ? 8 : 4));
  }
  return bytes;
}

}  // namespace

/// `--eligibility`: which table is checked on which op (the table in fuzz/README.md).
int print_eligibility() {
  for (const auto& [family, ops] : fuzz::families())
    for (const std::string& op : ops) {
      std::string yes, no;
      for (const rc_impl* t : impl::builtin_tables()) {
        if (!engine::supports(*t, op)) continue;
        const std::string name = std::string(t->name) + (t->scalar == RC_SCALAR_FLOAT32 ? "/f" : "/d");
        std::string why;
        if (fuzz::eligible(*t, op, &why)) yes += (yes.empty() ? "" : ", ") + name;
        else no += (no.empty() ? "" : ", ") + name + " (" + why + ")";
      }
      std::printf("| %s | %s | %s | %s | %s |\n", family.c_str(), op.c_str(), fuzz::fuzz_tolerance(op).c_str(),
                  yes.empty() ? "-" : yes.c_str(), no.empty() ? "-" : no.c_str());
    }
  return 0;
}

int main(int argc, char** argv) {
  if (argc == 2 && std::string(argv[1]) == "--eligibility") {
    fuzz::init();
    return print_eligibility();
  }
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s OUT_DIR (the repository's fuzz/corpus) | --eligibility\n", argv[0]);
    return 2;
  }
  const fs::path out = argv[1];
  fuzz::init();
  const spec::Spec& spec = fuzz::embedded_spec();
  int total = 0;

  // Hand-made words: binary64 first, then binary32 (the low 32 bits of each entry are used).
  const std::vector<std::uint64_t> specials64 = {
      0x8000000000000000ull,  // -0
      0x0000000000000001ull,  // smallest subnormal
      0x7ff0000000000000ull,  // +Inf
      0x7ff8000000c0ffeeull,  // quiet NaN with a payload
      0x7fefffffffffffffull,  // largest finite
      0x3ff0000000000000ull,  // 1
      0xbff0000000000000ull,  // -1
      0x3fe0000000000000ull,  // 0.5
  };
  const std::vector<std::uint64_t> specials32 = {0x80000000u, 0x00000001u, 0x7f800000u, 0x7fc0beefu,
                                                 0x7f7fffffu, 0x3f800000u, 0xbf800000u, 0x3f000000u};
  const std::vector<std::uint64_t> snan64 = {0x7ff0000000000001ull, 0xfff4000000000badull};
  const std::vector<std::uint64_t> snan32 = {0x7f800001u, 0xffa00badu};
  const std::vector<std::uint64_t> subnormal32 = {0x00000003u, 0x807fffffu, 0x00000000u};
  const std::vector<std::uint64_t> huge64 = {0x7fe0000000000000ull, 0xffefffffffffffffull, 0x7fd0000000000000ull};

  for (const auto& [family, ops] : fuzz::families()) {
    const fs::path dir = out / family;
    fs::remove_all(dir);
    int files = 0;
    for (const std::string& op : ops) {
      int alternate = 0;
      std::set<std::string> seen;
      for (const std::string& clause : fuzz::clauses_judging(op)) {
        for (const ref::Format f : {ref::Format::binary64, ref::Format::binary32}) {
          engine::CaseOptions o;
          o.seed = 1;
          o.cases_per_family = 1;
          for (const engine::Check& check : engine::checks_for_clause_impl(spec, clause, f, o, {op}))
            for (const engine::Case& c : check.cases) {
              const bool f64 = f == ref::Format::binary64;
              if ((alternate % 2 == 0) != f64) continue;
              if (!seen.insert(clause).second) continue;  // one input per clause and op
              ++alternate;
              write(dir / slug(op + "_" + (f64 ? "f64_" : "f32_") + clause + "_" + c.label), fuzz::encode(ops, op, f, {c}));
              ++files;
            }
        }
      }
      // A batch of 8 ordinary cases (binary32: the SIMD table's lanes and tail).
      engine::CaseOptions o;
      o.seed = 2;
      o.cases_per_family = 8;
      o.worked_examples = false;
      const std::string main_clause = fuzz::clauses_judging(op).front();
      for (const engine::Check& check : engine::checks_for_clause_impl(spec, main_clause, ref::Format::binary32, o, {op})) {
        std::vector<engine::Case> batch;
        for (const engine::Case& c : check.cases)
          if (batch.size() < 8 && (batch.empty() || c.k == batch.front().k)) batch.push_back(c);
        write(dir / slug(op + "_f32_batch_of_" + std::to_string(batch.size())),
              fuzz::encode(ops, op, ref::Format::binary32, batch));
        ++files;
        break;
      }
      const std::size_t k = engine::find_abi_op(op)->nway ? 3 : 0;
      write(dir / slug(op + "_f64_specials"), raw_seed(ops, op, true, k, specials64));
      write(dir / slug(op + "_f32_specials"), raw_seed(ops, op, false, k, specials32));
      write(dir / slug(op + (k % 2 ? "_f32_signalling_nan" : "_f64_signalling_nan")),
            k % 2 ? raw_seed(ops, op, false, k, snan32) : raw_seed(ops, op, true, k, snan64));
      write(dir / slug(op + "_f32_subnormal_and_-0"), raw_seed(ops, op, false, k, subnormal32));
      write(dir / slug(op + "_f64_huge"), raw_seed(ops, op, true, k, huge64));
      files += 5;
    }
    std::printf("%s: %d inputs\n", family.c_str(), files);
    total += files;
  }

  // Vector files: a few small ones of different value kinds.
  {
    const fs::path dir = out / "vectors_file";
    fs::remove_all(dir);
    vectors::BuildOptions o;
    o.seed = 1;
    o.cases_per_family = 1;
    o.clauses = {"NORM-1", "MAT-3", "EXP-2", "SLERP-4", "QLB-1", "DQ-5", "SKIN-2", "EDGE-7", "EDGE-9"};
    int files = 0;
    std::set<std::string> clauses;
    for (const vectors::VectorFile& f : vectors::build_vector_files(spec, o)) {
      if (!clauses.insert(f.clause).second) continue;  // one file per clause: small seeds
      write(dir / vectors::file_name(f), vectors::render(spec, f));
      ++files;
    }
    std::printf("vectors_file: %d inputs\n", files);
    total += files;
  }
  // Results files: what built-in tables return for the harness's fixed vectors.
  {
    const fs::path dir = out / "results_file";
    fs::remove_all(dir);
    int files = 0;
    for (const rc_impl* t : impl::builtin_tables()) {
      const std::string name = t->name;
      if (name != "dq" && name != "rotor_m2" && name != "rotor_gen" && name != "glm_quat" && name != "eigen_quat" && name != "rotor_simd") continue;
      const ref::Format f = t->scalar == RC_SCALAR_FLOAT32 ? ref::Format::binary32 : ref::Format::binary64;
      const auto j = vectors::run_table(*t, fuzz::results_vector_set(f), "results.json");
      write(dir / (name + "_" + vectors::scalar_name(f) + ".json"), j.dump(1));
      ++files;
    }
    std::printf("results_file: %d inputs\n", files);
    total += files;
  }
  std::printf("total: %d inputs in %s\n", total, out.c_str());
  return 0;
}
