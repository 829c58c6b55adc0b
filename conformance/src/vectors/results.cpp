#include <rotorcert/vectors/results.hpp>

#include <rotorcert/impl_abi.h>
#include <rotorcert/vectors/error.hpp>

namespace rotorcert::vectors {

using nlohmann::json;

std::filesystem::path ResultsFile::vectors_path() const {
  const std::filesystem::path v(vectors);
  return v.is_absolute() ? v : file.parent_path() / v;
}

ResultsFile parse_results(const json& j, const std::filesystem::path& file) {
  auto fail = [&](const std::string& path, const std::string& message) -> void { throw VectorsError(file, path, message); };
  auto string_at = [&](const json& obj, const std::string& key, const std::string& path, bool required) {
    if (!obj.contains(key)) {
      if (required) fail(path, "missing field \"" + key + "\"");
      return std::string();
    }
    if (!obj[key].is_string()) fail(path + "/" + key, "expected a string");
    return obj[key].get<std::string>();
  };
  auto strings_at = [&](const json& obj, const std::string& key, const std::string& path) {
    std::vector<std::string> r;
    if (!obj[key].is_array()) fail(path + "/" + key, "expected an array of strings");
    for (std::size_t i = 0; i < obj[key].size(); ++i) {
      if (!obj[key][i].is_string()) fail(path + "/" + key + "/" + std::to_string(i), "expected a string");
      r.push_back(obj[key][i].get<std::string>());
    }
    return r;
  };

  ResultsFile r;
  r.file = file;
  if (!j.is_object()) fail("", "expected a JSON object");
  if (string_at(j, "format", "", true) != "rotorcert-results") fail("/format", "not a rotorcert-results file");
  if (!j.contains("format_version")) fail("", "missing field \"format_version\"");
  if (j["format_version"] != kResultsFormatVersion)
    fail("/format_version", "format version " + std::to_string(kResultsFormatVersion) + " expected");
  if (!j.contains("implementation") || !j["implementation"].is_object()) fail("/implementation", "expected an object");
  const json& impl = j["implementation"];
  r.name = string_at(impl, "name", "/implementation", true);
  if (r.name.empty()) fail("/implementation/name", "empty name");
  r.scalar = string_at(impl, "scalar", "/implementation", true);
  if (r.scalar != "float" && r.scalar != "double") fail("/implementation/scalar", "expected \"float\" or \"double\"");
  r.version = string_at(impl, "version", "/implementation", false);
  r.description = string_at(impl, "description", "/implementation", false);
  if (impl.contains("claimed_clauses")) r.claimed_clauses = strings_at(impl, "claimed_clauses", "/implementation");
  if (impl.contains("claimed_levels")) r.claimed_levels = strings_at(impl, "claimed_levels", "/implementation");
  // DECL-1: documented preconditions and chosen conventions, "op:id".
  for (const char* key : {"preconditions", "conventions"}) {
    if (!impl.contains(key)) continue;
    std::vector<std::string>& into = std::string(key) == "preconditions" ? r.preconditions : r.conventions;
    into = strings_at(impl, key, "/implementation");
    for (std::size_t i = 0; i < into.size(); ++i)
      if (into[i].find(':') == std::string::npos)
        throw VectorsError(file, std::string("/implementation/") + key + "/" + std::to_string(i),
                           "a declaration is \"op:id\" (DECL-1), got \"" + into[i] + "\"");
  }
  if (impl.contains("hygiene")) {
    r.hygiene = strings_at(impl, "hygiene", "/implementation");
    for (std::size_t i = 0; i < r.hygiene.size(); ++i)
      if (r.hygiene[i] != "HYG-1")
        fail("/implementation/hygiene/" + std::to_string(i), "a results file can only show HYG-1, not \"" + r.hygiene[i] + "\"");
  }
  r.vectors = string_at(j, "vectors", "", true);
  if (j.contains("unsupported_ops")) r.unsupported_ops = strings_at(j, "unsupported_ops", "");
  if (!j.contains("results")) fail("", "missing field \"results\"");
  if (!j["results"].is_array()) fail("/results", "expected an array");
  const json& results = j["results"];
  for (std::size_t i = 0; i < results.size(); ++i) {
    const std::string p = "/results/" + std::to_string(i);
    const json& e = results[i];
    if (!e.is_object()) fail(p, "expected an object");
    ResultEntry entry;
    entry.json_path = p;
    entry.id = string_at(e, "id", p, true);
    if (!e.contains("status")) fail(p, "missing field \"status\"");
    const json& s = e["status"];
    if (s.is_string() && s == "OK") entry.status = RC_OK;
    else if (s.is_string() && s == "DOMAIN_ERROR") entry.status = RC_DOMAIN_ERROR;
    else if (s.is_number_integer() && s.get<std::int64_t>() >= 0 && s.get<std::int64_t>() <= 255)
      entry.status = static_cast<std::uint8_t>(s.get<std::int64_t>());
    else fail(p + "/status", "expected \"OK\", \"DOMAIN_ERROR\" or a status byte 0..255");
    if (e.contains("call_rc")) {
      if (!e["call_rc"].is_number_integer()) fail(p + "/call_rc", "expected an integer");
      entry.call_rc = e["call_rc"].get<int>();
    }
    if (!e.contains("out")) fail(p, "missing field \"out\"");
    if (!e["out"].is_object()) fail(p + "/out", "expected an object of output arrays");
    if (e.contains("modified_inputs")) {
      if (!e["modified_inputs"].is_string()) fail(p + "/modified_inputs", "expected a string");
      entry.modified_inputs = e["modified_inputs"].get<std::string>();
    }
    entry.out = e["out"];
    r.results.push_back(std::move(entry));
  }
  return r;
}

}  // namespace rotorcert::vectors
