#pragma once
/// \file text.h
/// Small text helpers shared by the file readers.

#include <filesystem>
#include <string>
#include <string_view>

namespace flexmb {

/// Copy of `s` with the ASCII letters A-Z in lower case (other bytes, UTF-8
/// included, unchanged; independent of the locale).
inline std::string AsciiLower(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c);
  return out;
}

/// `s` in single quotes, for naming a value in a message ("'frame'").
inline std::string Quoted(std::string_view s) { return "'" + std::string(s) + "'"; }

/// Extension of the file name in `path` with its dot, in lower case
/// (".bdf"; empty if there is none).
inline std::string LowerExtension(const std::string& path) {
  return AsciiLower(std::filesystem::path(path).extension().string());
}

}  // namespace flexmb
