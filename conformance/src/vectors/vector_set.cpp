#include <rotorcert/vectors/vector_set.hpp>

#include <fstream>
#include <set>
#include <sstream>

#include <rotorcert/certify/atomic_file.hpp>
#include <rotorcert/vectors/error.hpp>

#ifndef ROTORCERT_VERSION
#error "ROTORCERT_VERSION must be defined by the build"
#endif

namespace rotorcert::vectors {

using nlohmann::json;
using nlohmann::ordered_json;

std::map<std::string, std::string> render_export(const spec::Spec& spec, const BuildOptions& options) {
  std::map<std::string, std::string> out;
  const std::vector<VectorFile> files = build_vector_files(spec, options);
  ordered_json list = ordered_json::array();
  std::size_t total = 0;
  for (const VectorFile& f : files) {
    out[file_name(f)] = render(spec, f);
    list.push_back({{"file", file_name(f)}, {"clause", f.clause}, {"level", f.level}, {"op", f.op},
                    {"number_format", format_name(f.format)}, {"tolerance", f.tolerance}, {"numberOfTests", f.tests.size()}});
    total += f.tests.size();
  }
  ordered_json formats = ordered_json::array();
  for (ref::Format f : options.formats) formats.push_back(format_name(f));
  ordered_json index;
  index["format"] = "rotorcert-vectors-index";
  index["format_version"] = kFormatVersion;
  index["schema"] = "vectors.schema.json";
  index["rotorcert_version"] = ROTORCERT_VERSION;
  index["spec_version"] = spec.version;
  index["seed"] = options.seed;
  index["cases_per_family"] = options.cases_per_family;
  index["number_formats"] = formats;
  index["numberOfFiles"] = files.size();
  index["numberOfTests"] = total;
  index["files"] = list;
  out["index.json"] = index.dump(2) + "\n";
  return out;
}

std::vector<std::filesystem::path> write_export(const std::filesystem::path& dir,
                                                const std::map<std::string, std::string>& files) {
  std::filesystem::create_directories(dir);
  std::vector<std::filesystem::path> written;
  // index.json last: a reader that finds it finds every file it lists.
  for (const auto& [name, contents] : files)
    if (name != "index.json") {
      certify::write_atomically(dir / name, contents);
      written.push_back(dir / name);
    }
  if (const auto it = files.find("index.json"); it != files.end()) {
    certify::write_atomically(dir / it->first, it->second);
    written.push_back(dir / it->first);
  }
  return written;
}

json read_json_file(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw VectorsError(file, "", "cannot be read");
  std::stringstream text;
  text << in.rdbuf();
  return parse_json_text(text.str(), file);
}

json parse_json_text(std::string_view text, const std::filesystem::path& file) {
  try {
    return json::parse(text);
  } catch (const json::exception& e) {  // parse_error, and out_of_range for numbers beyond binary64
    throw VectorsError(file, "", std::string("not valid JSON: ") + e.what());
  }
}

VectorSet load_vectors(const spec::Spec& spec, const std::filesystem::path& where, const ref::Format* format) {
  VectorSet set;
  set.index = std::filesystem::is_directory(where) ? where / "index.json" : where;
  const json index = read_json_file(set.index);
  auto fail = [&](const std::string& path, const std::string& message) { throw VectorsError(set.index, path, message); };
  if (!index.is_object() || index.value("format", "") != "rotorcert-vectors-index")
    fail("/format", "not a rotorcert-vectors-index file (the index.json written by `rotorcert vectors export`)");
  if (!index.contains("format_version") || index["format_version"] != kFormatVersion)
    fail("/format_version", "format version " + std::to_string(kFormatVersion) + " expected");
  if (!index.contains("seed") || !index["seed"].is_number_unsigned()) fail("/seed", "expected a non-negative integer");
  if (!index.contains("cases_per_family") || !index["cases_per_family"].is_number_integer())
    fail("/cases_per_family", "expected an integer");
  set.seed = index["seed"].get<std::uint64_t>();
  set.cases_per_family = index["cases_per_family"].get<int>();
  if (!index.contains("files") || !index["files"].is_array()) fail("/files", "expected an array");
  std::set<std::string> ids;
  const json& files = index["files"];
  for (std::size_t i = 0; i < files.size(); ++i) {
    const std::string p = "/files/" + std::to_string(i);
    const json& e = files[i];
    if (!e.is_object() || !e.contains("file") || !e["file"].is_string()) fail(p + "/file", "expected a file name");
    if (!e.contains("number_format") || !e["number_format"].is_string()) fail(p + "/number_format", "expected a string");
    const std::string number_format = e["number_format"].get<std::string>();
    if (format != nullptr && number_format != format_name(*format)) continue;
    const std::filesystem::path file = set.index.parent_path() / e["file"].get<std::string>();
    VectorFile f = parse_vector_file(spec, read_json_file(file), file);
    if (format_name(f.format) != number_format || e.value("clause", "") != f.clause || e.value("op", "") != f.op)
      fail(p, "the entry does not describe " + file.string() + " (" + f.clause + " / " + f.op + " / " + format_name(f.format) + ")");
    if (f.seed != set.seed) throw VectorsError(file, "/seed", "differs from the seed of " + set.index.string());
    for (std::size_t t = 0; t < f.tests.size(); ++t)
      if (!ids.insert(f.tests[t].id).second)
        throw VectorsError(file, "/tests/" + std::to_string(t) + "/id", "duplicate id " + f.tests[t].id);
    set.files.push_back(std::move(f));
  }
  return set;
}

}  // namespace rotorcert::vectors
