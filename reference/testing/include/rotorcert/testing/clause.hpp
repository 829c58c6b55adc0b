// Tagging tests with the spec clauses they check.
//
// RC_CLAUSE("NORM-1") inside a test records the clause as a gtest property (it appears in
// --gtest_output=xml) and in failure messages. The traceability test scans the sources for
// RC_CLAUSE("...") and fails when a clause of spec/clauses.json is named by no test and is
// not listed in spec/pending.json.
#pragma once

#include <string>

#include <gtest/gtest.h>

#define RC_CLAUSE(id)                                                   \
  ::testing::Test::RecordProperty(std::string("clause ") + (id), (id)); \
  SCOPED_TRACE(std::string("spec clause ") + (id))
