// Every built-in implementation is also built as a dlopen plugin from the same source; the
// plugin must load through the C ABI and agree bit for bit with its static twin.
#include <cstring>
#include <map>
#include <set>
#include <filesystem>

#include <gtest/gtest.h>

#include <rotorcert/engine/abi_op.hpp>
#include <rotorcert/engine/cases.hpp>
#include <rotorcert/engine/runner.hpp>
#include <rotorcert/registry.hpp>

namespace {

using namespace rotorcert;

template <class S>
std::vector<S> native(const std::vector<engine::Case>& cases, std::size_t a) {
  std::vector<S> v;
  for (const auto& c : cases)
    for (const ref::Real& x : c.inputs[a]) v.push_back(S(x.toDouble()));
  return v;
}

/// Runs op on both tables with identical inputs; compares outputs and status byte for byte.
template <class S>
void compare(const rc_impl& a, const rc_impl& b, const engine::AbiOp& op, const std::vector<engine::Case>& cases,
             std::size_t k) {
  std::vector<std::vector<S>> in;
  std::vector<const void*> in_ptrs;
  for (std::size_t i = 0; i < op.inputs.size(); ++i) in.push_back(native<S>(cases, i));
  for (auto& v : in) in_ptrs.push_back(v.data());
  std::vector<std::vector<S>> out_a, out_b;
  std::vector<void*> pa, pb;
  for (const auto& arr : op.outputs) {
    out_a.emplace_back(cases.size() * arr.stride);
    out_b.emplace_back(cases.size() * arr.stride);
  }
  for (auto& v : out_a) pa.push_back(v.data());
  for (auto& v : out_b) pb.push_back(v.data());
  std::vector<std::uint8_t> sa(cases.size()), sb(cases.size());
  ASSERT_EQ(engine::call(a, op.name, cases.size(), k, in_ptrs, pa, sa.data()), 0) << op.name;
  ASSERT_EQ(engine::call(b, op.name, cases.size(), k, in_ptrs, pb, sb.data()), 0) << op.name;
  EXPECT_EQ(sa, sb) << a.name << " " << op.name;
  for (std::size_t i = 0; i < out_a.size(); ++i)
    EXPECT_EQ(std::memcmp(out_a[i].data(), out_b[i].data(), out_a[i].size() * sizeof(S)), 0)
        << a.name << " " << op.name << " output " << op.outputs[i].name << " differs between static and plugin";
}

TEST(Plugins, EveryBuiltinHasAPluginTwinThatAgreesBitForBit) {
  const auto builtins = impl::builtin_tables();
  ASSERT_FALSE(builtins.empty());
  std::set<std::string> ids;
  for (const auto& entry : std::filesystem::directory_iterator(ROTORCERT_PLUGIN_DIR))
    if (entry.path().extension() == ".so") ids.insert(entry.path().string());
  std::size_t matched = 0;
  for (const std::string& path : ids) {
    const auto plugin = impl::Plugin::load(path);
    for (const rc_impl* p : plugin->tables()) {
      const rc_impl* s = impl::find_builtin(p->name, p->scalar);
      ASSERT_NE(s, nullptr) << path << " offers " << p->name << " which is not built in";
      EXPECT_NE(s, p) << "the plugin's table must be its own copy, not the static one";
      ++matched;
      for (const engine::AbiOp& op : engine::abi_ops()) {
        ASSERT_EQ(engine::supports(*s, op.name), engine::supports(*p, op.name)) << p->name << " " << op.name;
        if (!engine::supports(*s, op.name)) continue;
        engine::CaseOptions options;
        options.cases_per_family = 8;
        options.worked_examples = false;
        // The cases of every clause that uses this op, NaN and edge inputs included.
        std::map<std::size_t, std::vector<engine::Case>> by_k;
        for (const char* clause : {"EDGE-5", "EDGE-6", "EDGE-7", "EDGE-8"}) {
          const std::vector<std::string> only{op.name};
          for (const auto& check : engine::checks_for_clause_impl(spec::load_spec(spec::resolve_spec_dir()), clause,
                                                                  engine::format_of(*s), options, only))
            for (const auto& c : check.cases) by_k[c.k].push_back(c);
        }
        for (const auto& [k, cases] : by_k) {
          if (s->scalar == RC_SCALAR_FLOAT32) compare<float>(*s, *p, op, cases, k);
          else compare<double>(*s, *p, op, cases, k);
        }
      }
    }
  }
  EXPECT_EQ(matched, builtins.size()) << "every built-in table has exactly one plugin twin";
}

TEST(Plugins, BadPluginsAreRejectedWithAClearMessage) {
  EXPECT_THROW(impl::Plugin::load("/nonexistent/plugin.so"), impl::PluginError);
  try {
    impl::Plugin::load("/nonexistent/plugin.so");
  } catch (const impl::PluginError& e) {
    EXPECT_NE(std::string(e.what()).find("cannot load plugin"), std::string::npos) << e.what();
  }
  // A shared library that is no rotorcert plugin: libm has no rotorcert_impl_entry.
  try {
    impl::Plugin::load("/lib/x86_64-linux-gnu/libm.so.6");
    ADD_FAILURE() << "libm loaded as a plugin";
  } catch (const impl::PluginError& e) {
    EXPECT_NE(std::string(e.what()).find("does not export rotorcert_impl_entry"), std::string::npos) << e.what();
  }
}

}  // namespace
