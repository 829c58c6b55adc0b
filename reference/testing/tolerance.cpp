#include <rotorcert/testing/tolerance.hpp>

#include <fstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

namespace rotorcert::testing {
namespace {

const nlohmann::json& tolerance_classes() {
  static const nlohmann::json classes = [] {
    const std::string path = std::string(ROTORCERT_SPEC_DIR) + "/clauses.json";
    std::ifstream in(path);
    if (!in) throw std::runtime_error("cannot open " + path);
    return nlohmann::json::parse(in).at("tolerance_classes");
  }();
  return classes;
}

}  // namespace

const ref::Real& ref_class_bar() {
  static const ref::Real bar(tolerance_classes().at("ref").at("strict").get<std::string>());
  return bar;
}

ref::Bars eps_class_bars(const std::string& name) {
  const auto& c = tolerance_classes().at(name);
  if (c.at("kind") != "eps") throw std::invalid_argument(name + " is not an eps tolerance class");
  return {c.at("strict").get<double>(), c.at("loose").get<double>()};
}

}  // namespace rotorcert::testing
