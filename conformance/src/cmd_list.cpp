// `rotorcert list`: every implementation the tool can certify — the built-in ones and any plugin
// named on the command line — with its scalar type, the levels and number of clauses it claims,
// the operations it provides and, for SIMD implementations, the dispatch targets it can run.
// `rotorcert list --ops [--json]`: the ABI's operations instead (the op list, abi_op_list.h, with
// the engine's array layouts), for plugin authors and for the vectors packages' tables.
#include <cctype>
#include <cstdio>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include <rotorcert/engine/abi_op.hpp>
#include <rotorcert/registry.hpp>

#include "commands.hpp"

namespace rotorcert::cli {
namespace {

std::string levels_of(std::uint32_t bits) {
  static const std::pair<std::uint32_t, const char*> names[] = {
      {RC_LEVEL_CORE, "Core"},   {RC_LEVEL_INTERP, "Interp"},     {RC_LEVEL_BLEND, "Blend"},
      {RC_LEVEL_RIGID, "Rigid"}, {RC_LEVEL_SKINNING, "Skinning"}, {RC_LEVEL_ROBUST, "Robust"}};
  std::string s;
  for (const auto& [bit, name] : names)
    if (bits & bit) s += (s.empty() ? "" : ",") + std::string(name);
  return s.empty() ? "-" : s;
}

void print(const rc_impl& t, const std::string& source) {
  std::size_t clauses = 0;
  while (t.clauses && t.clauses[clauses]) ++clauses;
  std::size_t ops = 0;
  for (const auto& op : engine::abi_ops()) ops += engine::supports(t, op.name) ? 1 : 0;
  std::string targets = "-";
  if (t.simd_targets) {
    targets.clear();
    for (int i = 0; t.simd_targets[i]; ++i) targets += (i ? " " : "") + std::string(t.simd_targets[i]);
    targets += " (in use: " + std::string(t.current_target()) + ")";
  }
  std::printf("%-14s %-6s %-40s %3zu clauses %2zu/%zu ops  %-10s %s\n", t.name,
              t.scalar == RC_SCALAR_FLOAT32 ? "float" : "double", levels_of(t.levels).c_str(), clauses, ops,
              engine::abi_ops().size(), source.c_str(), targets.c_str());
  std::printf("               %s (%s)\n", t.description, t.version);
}

/// "CORE" -> "Core", the spec's spelling of a level.
std::string level_name(std::string_view capitals) {
  std::string s(capitals);
  for (std::size_t i = 1; i < s.size(); ++i) s[i] = static_cast<char>(std::tolower(static_cast<unsigned char>(s[i])));
  return s;
}

const char* kind_name(OpKind k) {
  switch (k) {
    case OpKind::ELEM: return "elementwise";
    case OpKind::BLEND: return "blend";
    case OpKind::SKIN: return "skin";
  }
  return "?";
}

nlohmann::json arrays_json(const std::vector<engine::Array>& arrays) {
  nlohmann::json a = nlohmann::json::array();
  for (const engine::Array& x : arrays) a.push_back({{"name", x.name}, {"stride", x.stride}, {"per_influence", x.per_influence}});
  return a;
}

/// The op list: per op its slot, ABI version, level, clauses, kind and arrays (LAYOUT-1 strides).
void print_ops(bool json) {
  nlohmann::json ops = nlohmann::json::array();
  for (const engine::AbiOp& op : engine::abi_ops()) {
    const OpInfo& row = op_info(op.id);
    if (json) {
      ops.push_back({{"name", op.name}, {"abi_version", row.since}, {"level", level_name(row.level)},
                     {"clauses", std::string(row.clauses)}, {"kind", kind_name(row.kind)},
                     {"inputs", arrays_json(op.inputs)}, {"outputs", arrays_json(op.outputs)}});
      continue;
    }
    auto arrays = [](const std::vector<engine::Array>& v) {
      std::string s;
      for (const engine::Array& x : v)
        s += (s.empty() ? "" : ", ") + x.name + "[" + (x.per_influence ? "k*" : "") + std::to_string(x.stride) + "]";
      return s;
    };
    std::printf("%-29s v%u %-9s %-12s %-11s (%s) -> (%s)\n", op.name.c_str(), row.since, level_name(row.level).c_str(),
                std::string(row.clauses).c_str(), kind_name(row.kind), arrays(op.inputs).c_str(),
                arrays(op.outputs).c_str());
  }
  if (json) std::printf("%s\n", nlohmann::json{{"abi_version", RC_ABI_VERSION}, {"ops", ops}}.dump(1).c_str());
}

}  // namespace

Command add_list(CLI::App& parent) {
  CLI::App* app = parent.add_subcommand("list", "List the implementations: scalar type, levels claimed, SIMD targets");
  auto plugins = std::make_shared<std::vector<std::string>>();
  app->add_option("--plugin", *plugins, "Also load and list this plugin (.so through the C ABI); repeatable");
  auto ops = std::make_shared<bool>(false);
  auto json = std::make_shared<bool>(false);
  app->add_flag("--ops", *ops, "List the ABI's operations instead: version, level, clauses, kind, arrays (LAYOUT-1)");
  app->add_flag("--json", *json, "With --ops: as JSON")->needs(app->get_option("--ops"));
  return {app, [plugins, ops, json]() {
            if (*ops) {
              print_ops(*json);
              return kExitOk;
            }
            std::printf("%-14s %-6s %-40s %s\n", "name", "scalar", "levels claimed", "clauses, ops, source, SIMD targets");
            for (const rc_impl* t : impl::builtin_tables()) print(*t, "built-in");
            std::vector<std::unique_ptr<impl::Plugin>> loaded;
            for (const std::string& path : *plugins) {
              try {
                loaded.push_back(impl::Plugin::load(path));
              } catch (const impl::PluginError& e) {
                std::cerr << "rotorcert list: " << e.what() << '\n';
                return kExitUsage;
              }
              for (const rc_impl* t : loaded.back()->tables()) print(*t, "plugin");
            }
            return kExitOk;
          }};
}

}  // namespace rotorcert::cli
