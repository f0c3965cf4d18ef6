#pragma once
/// \file nastran_fields.h
/// The lexical layer of the Nastran bulk data reader: files and INCLUDEs to
/// lines, lines to cards (small, large and free field, continuations, tabs,
/// comments), cards to typed fields (Nastran's integer and real forms).
/// The meaning of the cards is in nastran_builder.h.

#include <string>
#include <string_view>
#include <vector>

#include "flexmb/common/error.h"

namespace flexmb::io::nastran {

/// One bulk data entry with its continuations merged. Field k (1-based) is
/// Nastran field k+1 of the first line for k = 1..8, then field 2.. of the
/// continuation lines: 8 data fields per small- or free-field line, 4 per
/// large-field line (so a large-field line pair makes 8). The continuation
/// fields (field 10 of a line, field 1 of the next) are dropped.
struct Card {
  std::string name;                 ///< upper case, without the large-field '*'
  std::vector<std::string> fields;  ///< data fields, trimmed, upper case; trailing blanks dropped
  std::vector<int> lines;           ///< line of each field (same size as fields)
  int file = 0;                     ///< index into Deck::files
  int line = 0;                     ///< line of the card's first line (1-based)
};

/// The bulk data of a file and its INCLUDEs, in reading order.
struct Deck {
  std::vector<std::string> files;   ///< file names as used in messages
  std::vector<Card> cards;
};

/// Reads the bulk data of `path`: everything after BEGIN BULK if the file
/// has that line (executive and case control before it are skipped,
/// INCLUDEs there are not followed), else the whole file; up to ENDDATA.
/// INCLUDE 'name' (quoted names may continue over lines) is resolved
/// relative to the including file; cycles and a depth over 32 are errors.
/// Throws InputError with file and line for unreadable files, malformed
/// lines and orphan continuations. A DEQATN's equation (free text with
/// commas and blanks, continued on the lines up to the next card) is not
/// split into fields: its card holds EQID only.
Deck ReadDeck(const std::string& path);

/// Parses an integer field ("12", "-3", "+7"); false if `text` is not one
/// or out of the int range.
bool ParseInteger(std::string_view text, int* value);

/// Parses a Nastran real field: "1.5", "1.", ".5", "1.5E3", "1.5D3",
/// "1.5+3", "-.5-2", "7" (an integer is accepted where a real is expected).
/// False if `text` is not a number or not finite in double precision.
bool ParseReal(std::string_view text, double* value);

/// True if `text` has the form of a real (a decimal point or an exponent),
/// as opposed to an integer; used where the type decides the meaning.
bool LooksReal(std::string_view text);

/// Typed, checked access to the fields of one card. Field indices are as in
/// Card (1 = first data field). Every error names the file, the line of the
/// field and the entity ("CQUAD4 17").
class Entry {
 public:
  /// Views `card` of `deck` (both must outlive the Entry).
  Entry(const Card& card, const Deck& deck) : card_(card), deck_(deck) {}

  /// The card viewed.
  const Card& card() const { return card_; }
  /// The card name ("CQUAD4").
  const std::string& name() const { return card_.name; }
  /// "CARD id" for messages (id = text of field 1, if any).
  std::string Entity() const;
  /// Number of fields (trailing blanks dropped).
  int Size() const { return static_cast<int>(card_.fields.size()); }
  /// Text of field i, "" if blank or beyond the end.
  const std::string& Text(int i) const;
  /// True if field i is blank (or beyond the end).
  bool Blank(int i) const { return Text(i).empty(); }

  /// Required integer / integer with a default for a blank field. `what`
  /// names the field in messages ("PID").
  int Int(int i, const char* what) const;
  int Int(int i, const char* what, int fallback) const;
  /// Required integer > 0 (an id).
  int Id(int i, const char* what) const;
  /// Required real / real with a default for a blank field.
  double Real(int i, const char* what) const;
  double Real(int i, const char* what, double fallback) const;

  /// Context for an error at field i (its line; the card's line if i is
  /// beyond the end or 0).
  ErrorContext Context(int i = 0) const;
  /// Throws InputError at field i.
  [[noreturn]] void Fail(int i, const std::string& message) const;
  /// Throws InputError at the card's first line.
  [[noreturn]] void Fail(const std::string& message) const { Fail(0, message); }
  /// The file name of the card.
  const std::string& File() const { return deck_.files[card_.file]; }
  /// Line of field i (the card's line if i is out of range).
  int Line(int i = 0) const;

 private:
  const Card& card_;
  const Deck& deck_;
};

}  // namespace flexmb::io::nastran
