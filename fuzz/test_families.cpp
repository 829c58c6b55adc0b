// Every op of the op list (abi_op_list.h) is fed by exactly one operation harness (families.hpp),
// and every op a family names is in the list: an op added to the ABI is fuzzed from the start.
#include <map>
#include <string>

#include <gtest/gtest.h>

#include <rotorcert/op_id.hpp>

#include "families.hpp"

TEST(Families, EveryOpOfTheOpListIsInExactlyOneFamily) {
  std::map<std::string, int> families_of;
  for (const auto& [family, ops] : rotorcert::fuzz::families())
    for (const std::string& op : ops) {
      EXPECT_TRUE(rotorcert::op_id(op).has_value()) << family << " names " << op << ", which the op list lacks";
      ++families_of[op];
    }
  for (const rotorcert::OpInfo& row : rotorcert::kOps)
    EXPECT_EQ(families_of[std::string(row.name)], 1) << row.name << " must be in exactly one family";
}
