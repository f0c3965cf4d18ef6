#include "apps/flexmb/commands/run.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>

namespace flexmb {
namespace {

constexpr const char* kPython = "/usr/bin/python3";

TEST(RunSummary, JsonParsesBackWithEscapesAndNonFiniteAsNull) {
  if (access(kPython, X_OK) != 0) GTEST_SKIP() << "no " << kPython << " to parse the JSON";
  RunSummary s;
  s.status = RunStatus::kNumericalError;
  s.message = "m.yaml:3: joint 'a\"b': bad\\value\nnext line\ttab";
  s.model = "dir/m.yaml";
  s.t_end = 0.125;
  s.steps = 125;
  s.dof = 7;
  s.max_constraint_violation = std::numeric_limits<double>::quiet_NaN();
  s.steps_per_second = 1.0 / 3.0;
  s.warnings = {"w1", "w\"2"};
  const auto path = std::filesystem::temp_directory_path() /
                    ("flexmb_summary_test_" + std::to_string(getpid()) + ".json");
  std::ofstream(path) << SummaryJson(s);

  // python reads it and prints the fields back in a fixed format
  const std::string cmd =
      std::string(kPython) +
      " -c 'import json,sys; d=json.load(open(sys.argv[1]));"
      " print(repr(d[\"status\"]), repr(d[\"message\"]), d[\"t_end\"], d[\"steps\"], d[\"dof\"],"
      " d[\"max_constraint_violation\"], repr(d[\"steps_per_second\"]), d[\"warnings\"])' '" +
      path.string() + "'";
  std::FILE* p = popen(cmd.c_str(), "r");
  ASSERT_NE(p, nullptr);
  std::string out;
  char buf[1024];
  while (std::fgets(buf, sizeof(buf), p)) out += buf;
  EXPECT_EQ(pclose(p), 0);
  std::filesystem::remove(path);
  EXPECT_EQ(out,
            "'failed' 'm.yaml:3: joint \\'a\"b\\': bad\\\\value\\nnext line\\ttab' 0.125 125 7 None "
            "0.3333333333333333 ['w1', 'w\"2']\n");
}

TEST(RunSummary, StatusNamesAndExitCodes) {
  EXPECT_STREQ(StatusName(RunStatus::kOk), "ok");
  EXPECT_STREQ(StatusName(RunStatus::kInputError), "failed");
  EXPECT_STREQ(StatusName(RunStatus::kNumericalError), "failed");
  EXPECT_STREQ(StatusName(RunStatus::kInterrupted), "interrupted");
  EXPECT_EQ(ExitCode(RunStatus::kOk), 0);
  EXPECT_EQ(ExitCode(RunStatus::kNumericalError), 1);
  EXPECT_EQ(ExitCode(RunStatus::kInputError), 2);
  EXPECT_EQ(ExitCode(RunStatus::kInterrupted), 130);
}

}  // namespace
}  // namespace flexmb
