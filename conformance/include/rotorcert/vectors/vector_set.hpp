// A directory of vector files: writing one (`rotorcert vectors export`) with its index.json, and
// reading one back, every file checked against the reference (vector_file.hpp).
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include <rotorcert/vectors/vector_file.hpp>

namespace rotorcert::vectors {

/// File name -> contents of an export: every vector file and index.json. Deterministic: the
/// same spec and options give byte-identical contents.
std::map<std::string, std::string> render_export(const spec::Spec& spec, const BuildOptions& options);

/// Writes render_export() into dir (created if needed), each file atomically, index.json last.
/// Returns the files written.
std::vector<std::filesystem::path> write_export(const std::filesystem::path& dir,
                                                const std::map<std::string, std::string>& files);

/// A loaded export.
struct VectorSet {
  std::filesystem::path index;  // the index.json read
  std::uint64_t seed = 1;
  int cases_per_family = 0;
  std::vector<VectorFile> files;  // index order
};

/// Reads the export at `where` (a directory holding index.json, or the index file itself) and
/// every file it lists; only files of `format` when given. Throws VectorsError.
VectorSet load_vectors(const spec::Spec& spec, const std::filesystem::path& where,
                       const ref::Format* format = nullptr);

/// Reads a JSON file; VectorsError on I/O or syntax errors.
nlohmann::json read_json_file(const std::filesystem::path& file);

/// Parses the text of `file` as JSON; VectorsError naming the file on syntax errors and on
/// numbers beyond binary64 (the only exceptions it throws).
nlohmann::json parse_json_text(std::string_view text, const std::filesystem::path& file);

}  // namespace rotorcert::vectors
