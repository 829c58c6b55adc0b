// `rotorcert list`: every implementation the tool can certify — the built-in ones and any plugin
// named on the command line — with its scalar type, the levels and number of clauses it claims,
// the operations it provides and, for SIMD implementations, the dispatch targets it can run.
#include <cstdio>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

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

}  // namespace

Command add_list(CLI::App& parent) {
  CLI::App* app = parent.add_subcommand("list", "List the implementations: scalar type, levels claimed, SIMD targets");
  auto plugins = std::make_shared<std::vector<std::string>>();
  app->add_option("--plugin", *plugins, "Also load and list this plugin (.so through the C ABI); repeatable");
  return {app, [plugins]() {
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
