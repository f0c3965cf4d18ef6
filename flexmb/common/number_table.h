#pragma once
/// \file number_table.h
/// Reader of small tables of numbers in text files (CSV-like): one row of
/// a fixed number of columns per line, separated by commas, semicolons or
/// blanks, '#' starting a comment, blank lines skipped, and one line of
/// column titles allowed before the first row. Used by the S-N curve and
/// road profile readers.

#include <string>
#include <vector>

namespace flexmb {

/// A table read by ReadNumberTable.
struct NumberTable {
  std::vector<std::vector<double>> rows;  ///< rows in file order, each of the asked column count
  std::vector<int> lines;                 ///< the 1-based file line of each row
};

/// Reads `path` as a table of `columns` numbers per line (see the file
/// comment). Every value must be a complete number (strtod syntax) and
/// finite. Throws InputError naming the file and line: "<what>: expected
/// <columns> numbers '<layout>'" (the count in words: "two") for a line that is not such a row (other
/// than a first title line), "<what>: NaN or infinite value"; and naming
/// the file if it cannot be opened.
NumberTable ReadNumberTable(const std::string& path, int columns, const std::string& what,
                            const std::string& layout);

}  // namespace flexmb
