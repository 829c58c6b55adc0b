#include <rotorcert/certify/certificate.hpp>

#include <filesystem>

#include <rotorcert/spec/data_layout.hpp>
#include <rotorcert/spec/spec.hpp>

namespace rotorcert::certify {
namespace {

const char* const kLevelNames[] = {"Core", "Interp", "Blend", "Rigid", "Skinning", "Robust"};

}  // namespace

TableInfo table_info(const rc_impl& table, std::string source, std::string plugin_path) {
  TableInfo t;
  t.name = table.name ? table.name : "";
  t.scalar = table.scalar == RC_SCALAR_FLOAT32 ? "float" : "double";
  t.version = table.version ? table.version : "";
  t.description = table.description ? table.description : "";
  t.source = std::move(source);
  t.plugin_path = std::move(plugin_path);
  for (int i = 0; i < 6; ++i)
    if (table.levels & (1u << i)) t.claimed_levels.emplace_back(kLevelNames[i]);
  t.claimed_levels.emplace_back("Hygiene");  // every C-ABI table's contract (HYG-*, engine::claimed_clauses)
  t.claimed_clauses = engine::claimed_clauses(table);
  for (const engine::AbiOp& op : engine::abi_ops())
    if (engine::supports(table, op.name)) t.supported_ops.push_back(op.name);
  const engine::Declarations d = engine::declarations_of(table);
  t.declared_preconditions.assign(d.preconditions.begin(), d.preconditions.end());
  t.declared_conventions.assign(d.conventions.begin(), d.conventions.end());
  return t;
}

std::map<std::string, std::string> read_expected_failures(const std::filesystem::path& file, const std::string& table,
                                                          const std::string& scalar) {
  std::map<std::string, std::string> result;
  if (!std::filesystem::exists(file)) return result;
  const json j = spec::read_json(file);
  for (const json& f : j.at("failures"))
    if (f.at("table") == table && f.at("scalar") == scalar) result[f.at("clause")] = f.at("why");
  return result;
}

std::filesystem::path builtin_expected_failures_file(const std::string& impl_name) {
  return spec::data_layout().impls_dir / impl_name / "expected_failures.json";
}

std::map<std::string, std::string> expected_failures(const std::string& impl_name, const std::string& scalar) {
  // The file sits in the directory of the implementation that provides the table; a directory
  // may provide several tables (glm_quat also provides glm_mix), so every file is read.
  std::map<std::string, std::string> result;
  const std::filesystem::path impls = spec::data_layout().impls_dir;
  std::error_code ec;
  for (const auto& dir : std::filesystem::directory_iterator(impls, ec))
    for (auto& [clause, why] : read_expected_failures(dir.path() / "expected_failures.json", impl_name, scalar))
      result[clause] = why;
  return result;
}

}  // namespace rotorcert::certify
