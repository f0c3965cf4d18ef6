#pragma once
/// \file text_scanner.h
/// A small scanner over a text file for the mesh readers (gmsh, legacy VTK):
/// reads the file whole, hands out lines or whitespace-separated tokens with
/// their 1-based line numbers, and converts tokens to checked numbers. Every
/// failure is an InputError "FILE:LINE: ENTITY: message".

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace flexmb::io {

/// Sequential reader of one text file, by line or by token.
class TextScanner {
 public:
  /// Reads the file `path` whole; throws InputError naming it if it cannot
  /// be opened or read, or is a directory.
  explicit TextScanner(const std::string& path);
  /// Scans `text` as if it were the file `name` (for tests).
  TextScanner(std::string name, std::string text);

  /// The file name used in messages.
  const std::string& file() const { return file_; }
  /// Line of the last line or token handed out (1-based; 0 before any).
  int line() const { return line_; }
  /// The entity named in messages, e.g. "element 17"; empty for none.
  void SetEntity(std::string entity) { entity_ = std::move(entity); }

  /// The rest of the current line (or the next line if at a line start),
  /// without its end-of-line characters; false at the end of the file.
  bool NextLine(std::string_view& line);
  /// The next line that is not blank; false at the end of the file.
  bool NextNonBlankLine(std::string_view& line);
  /// The next whitespace-separated token, crossing line ends; false at the
  /// end of the file.
  bool NextToken(std::string_view& token);
  /// The next token; throws "unexpected end of file, expected `what`".
  std::string_view Token(const char* what);
  /// The raw bytes of the file.
  const std::string& text() const { return text_; }

  /// A reading position, to look ahead and come back.
  struct Position {
    size_t pos = 0;    ///< byte offset of the next character
    int pos_line = 1;  ///< line of that character
    int line = 0;      ///< line of the last item handed out
  };
  /// The current position.
  Position Tell() const { return {pos_, pos_line_, line_}; }
  /// Returns to a position from Tell().
  void Seek(const Position& p) {
    pos_ = p.pos;
    pos_line_ = p.pos_line;
    line_ = p.line;
  }

  /// Throws InputError at the current line with the current entity.
  [[noreturn]] void Fail(const std::string& message) const;
  /// Throws InputError at `line` with the current entity.
  [[noreturn]] void FailAt(int line, const std::string& message) const;

  /// Whole number in [lo, hi] from `token`; `what` names it in messages.
  int64_t Integer(std::string_view token, const char* what, int64_t lo, int64_t hi) const;
  /// Finite floating-point number from `token` (a leading '+' allowed).
  double Real(std::string_view token, const char* what) const;
  /// The next token as a whole number / finite number.
  int64_t NextInteger(const char* what, int64_t lo, int64_t hi);
  double NextReal(const char* what);

 private:
  std::string file_;
  std::string text_;
  std::string entity_;
  size_t pos_ = 0;
  int line_ = 0;       // line of the last item handed out
  int pos_line_ = 1;   // line that pos_ is on
};

/// Splits `line` at blanks and tabs into `tokens` (cleared first).
void SplitTokens(std::string_view line, std::vector<std::string_view>& tokens);

/// Short printable form of a token for messages (at most 40 characters,
/// control characters escaped).
std::string Printable(std::string_view token);

}  // namespace flexmb::io
