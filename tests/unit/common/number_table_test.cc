// ReadNumberTable (common/number_table.h): separators, comments, one title
// line, and errors that name the file and line. The reference is the text
// written in each test.

#include "flexmb/common/number_table.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "flexmb/common/error.h"

namespace {

std::string NumberTableFile(const std::string& name, const std::string& text) {
  const std::filesystem::path p = std::filesystem::temp_directory_path() / ("flexmb_number_table_" + name);
  std::ofstream(p) << text;
  return p.string();
}

// the message of the InputError that reading `text` gives ("" if none)
std::string NumberTableError(const std::string& name, const std::string& text) {
  const std::string path = NumberTableFile(name, text);
  try {
    flexmb::ReadNumberTable(path, 2, "S-N file", "cycles, range");
  } catch (const flexmb::InputError& e) {
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
    return e.what();
  }
  return "";
}

}  // namespace

TEST(NumberTable, SeparatorsCommentsAndTitle) {
  const std::string path =
      NumberTableFile("ok.csv", "# comment line\ncycles; range\n\n1e4, 3e8  # first point\n2e6;9e7\r\n  5e6 \t 6.6e7\n");
  const flexmb::NumberTable t = flexmb::ReadNumberTable(path, 2, "S-N file", "cycles, range");
  ASSERT_EQ(t.rows.size(), 3u);
  EXPECT_EQ(t.rows[0][0], 1e4);
  EXPECT_EQ(t.rows[0][1], 3e8);
  EXPECT_EQ(t.rows[1][0], 2e6);
  EXPECT_EQ(t.rows[2][1], 6.6e7);
  EXPECT_EQ(t.lines, (std::vector<int>{4, 5, 6}));
}

TEST(NumberTable, ErrorsNameTheLine) {
  // a second line of text is not a title any more
  EXPECT_NE(NumberTableError("text.csv", "N, S\n1e4, 3e8\nfoo, bar\n").find(".csv:3: "), std::string::npos);
  // a title after the first row
  EXPECT_NE(NumberTableError("late.csv", "1e4, 3e8\nN, S\n").find("expected two numbers 'cycles, range'"),
            std::string::npos);
  // too many and too few columns, a number with trailing letters
  EXPECT_NE(NumberTableError("three.csv", "1e4, 3e8\n2e6, 9e7, 1\n").find(".csv:2: "), std::string::npos);
  EXPECT_NE(NumberTableError("one.csv", "1e4, 3e8\n2e6\n").find(".csv:2: "), std::string::npos);
  EXPECT_NE(NumberTableError("suffix.csv", "1e4, 3e8\n2e6, 9e7MPa\n").find(".csv:2: "), std::string::npos);
  // NaN and infinity are numbers to strtod, but not values
  EXPECT_NE(NumberTableError("nan.csv", "1e4, nan\n").find("NaN or infinite value"), std::string::npos);
  EXPECT_NE(NumberTableError("inf.csv", "1e4, 3e8\n1e999, 1\n").find("NaN or infinite value"), std::string::npos);
  EXPECT_NE(NumberTableError("missing_dir/none.csv", "").find("cannot open the S-N file"), std::string::npos);
}
