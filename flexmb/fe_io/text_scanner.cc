#include "flexmb/fe_io/text_scanner.h"

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "flexmb/common/error.h"

namespace flexmb::io {
namespace {

bool IsSpace(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\v' || c == '\f'; }

// the whole of `t` (`token` without an accepted sign) as a T; fails naming
// `what`: "WHAT<out_of_range>TOKEN" or "expected <kind> for WHAT, got 'TOKEN'"
template <class T>
T ParseWhole(const TextScanner& s, std::string_view token, std::string_view t, const char* what,
             const char* out_of_range, const char* kind) {
  T value{};
  const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), value);
  if (ec == std::errc::result_out_of_range) s.Fail(std::string(what) + out_of_range + Printable(token));
  if (ec != std::errc() || end != t.data() + t.size())
    s.Fail(std::string("expected ") + kind + " for " + what + ", got '" + Printable(token) + "'");
  return value;
}

}  // namespace

TextScanner::TextScanner(const std::string& path) : file_(path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw InputError("cannot read: it is a directory", {path, 0, ""});
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError("cannot open: " + std::string(std::strerror(errno)), {path, 0, ""});
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw InputError("cannot read the file", {path, 0, ""});
  text_ = std::move(text).str();
}

TextScanner::TextScanner(std::string name, std::string text) : file_(std::move(name)), text_(std::move(text)) {}

bool TextScanner::NextLine(std::string_view& line) {
  if (pos_ >= text_.size()) return false;
  const size_t eol = text_.find('\n', pos_);
  const size_t end = eol == std::string::npos ? text_.size() : eol;
  line = std::string_view(text_).substr(pos_, end - pos_);
  while (!line.empty() && line.back() == '\r') line.remove_suffix(1);
  line_ = pos_line_;
  if (eol == std::string::npos) {
    pos_ = text_.size();
  } else {
    pos_ = eol + 1;
    ++pos_line_;
  }
  return true;
}

bool TextScanner::NextNonBlankLine(std::string_view& line) {
  while (NextLine(line)) {
    for (char c : line)
      if (!IsSpace(c)) return true;
  }
  return false;
}

bool TextScanner::NextToken(std::string_view& token) {
  const size_t n = text_.size();
  while (pos_ < n && IsSpace(text_[pos_])) {
    if (text_[pos_] == '\n') ++pos_line_;
    ++pos_;
  }
  if (pos_ >= n) return false;
  const size_t start = pos_;
  while (pos_ < n && !IsSpace(text_[pos_])) ++pos_;
  token = std::string_view(text_).substr(start, pos_ - start);
  line_ = pos_line_;
  return true;
}

std::string_view TextScanner::Token(const char* what) {
  std::string_view token;
  if (!NextToken(token)) {
    line_ = pos_line_;
    Fail(std::string("unexpected end of file, expected ") + what);
  }
  return token;
}

void TextScanner::Fail(const std::string& message) const { FailAt(line_, message); }

void TextScanner::FailAt(int line, const std::string& message) const {
  throw InputError(message, {file_, line, entity_});
}

int64_t TextScanner::Integer(std::string_view token, const char* what, int64_t lo, int64_t hi) const {
  std::string_view t = token;
  if (t.size() > 1 && t[0] == '+') t.remove_prefix(1);
  const int64_t value = ParseWhole<int64_t>(*this, token, t, what, " is out of range: ", "a whole number");
  if (value < lo || value > hi)
    Fail(std::string(what) + " must be in [" + std::to_string(lo) + ", " + std::to_string(hi) + "], got " +
         std::to_string(value));
  return value;
}

double TextScanner::Real(std::string_view token, const char* what) const {
  std::string_view t = token;
  if (t.size() > 1 && t[0] == '+' && t[1] != '-' && t[1] != '+') t.remove_prefix(1);
  const double value = ParseWhole<double>(*this, token, t, what, " is out of the range of a double: ", "a number");
  if (!std::isfinite(value)) Fail(std::string(what) + " must be finite, got '" + Printable(token) + "'");
  return value;
}

int64_t TextScanner::NextInteger(const char* what, int64_t lo, int64_t hi) {
  return Integer(Token(what), what, lo, hi);
}

double TextScanner::NextReal(const char* what) { return Real(Token(what), what); }

void SplitTokens(std::string_view line, std::vector<std::string_view>& tokens) {
  tokens.clear();
  size_t i = 0;
  const size_t n = line.size();
  while (i < n) {
    while (i < n && IsSpace(line[i])) ++i;
    if (i >= n) break;
    const size_t start = i;
    while (i < n && !IsSpace(line[i])) ++i;
    tokens.push_back(line.substr(start, i - start));
  }
}

std::string Printable(std::string_view token) {
  std::string out;
  const size_t limit = 40;
  for (size_t i = 0; i < token.size() && i < limit; ++i) {
    const unsigned char c = static_cast<unsigned char>(token[i]);
    if (c >= 0x20 && c < 0x7f) {
      out += static_cast<char>(c);
    } else {
      static const char* hex = "0123456789abcdef";
      out += "\\x";
      out += hex[c >> 4];
      out += hex[c & 15];
    }
  }
  if (token.size() > limit) out += "...";
  return out;
}

}  // namespace flexmb::io
