#pragma once
/// \file abaqus_deck.h
/// The lexical layer of the Abaqus / CalculiX input deck reader (internal to
/// flexmb/io): files, *INCLUDE and INPUT= to cards (a keyword line with its
/// parameters and the data lines after it), typed, checked access to the
/// fields of a data line, and the element families shared with the writer.
/// The meaning of the cards is in abaqus_builder.h.

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "flexmb/fe/element_traits.h"
#include "flexmb/fe/mesh.h"

namespace flexmb::io::abaqus {

/// One data line, split at commas outside double quotes.
struct DataLine {
  std::vector<std::string> fields;  ///< trimmed, quotes removed
  bool continued = false;           ///< the line ended with a comma
  std::string error;                ///< malformed quoting, reported if the card is used
  fe::Origin origin;                ///< file and line
};

/// One keyword-line parameter, "KEY" or "KEY=value".
struct Param {
  std::string key;        ///< upper case, blanks removed
  std::string value;      ///< trimmed, quotes removed
  bool has_value = false; ///< an '=' was given
};

/// A keyword line with its parameters and data lines.
struct Card {
  std::string key;   ///< upper case, blanks removed: "SHELLSECTION"
  std::string name;  ///< for messages: "*SHELL SECTION"
  std::vector<Param> params;
  std::vector<DataLine> data;
  fe::Origin origin;
  int parent = -1;   ///< sub-options (*ELASTIC, *KINEMATIC, ...): index of their card

  /// The parameter with upper-case, blank-free name `k`, or nullptr.
  const Param* Find(const char* k) const {
    for (const Param& p : params)
      if (p.key == k) return &p;
    return nullptr;
  }
};

/// Reads the cards of the deck `path` in order, following *INCLUDE (nested
/// at most 16 deep, relative to the including file) and INPUT= of *NODE,
/// *ELEMENT, *NSET, *ELSET, *BOUNDARY and *SURFACE. Comment lines ("**")
/// and blank lines are dropped. Throws InputError with file and line for
/// unreadable files, malformed keyword lines and data before any keyword;
/// malformed quoting on a data line is kept in DataLine::error.
std::vector<Card> ReadCards(const std::string& path);

/// True if one of the first 200 lines of `path` begins with "** Generated
/// by: Abaqus/CAE" (case and blanks aside; Abaqus/CAE writes "** Generated
/// by: Abaqus/CAE 2021"): the deck's C3D8 are then Abaqus's, not
/// CalculiX's (docs/formats.md).
bool WrittenByAbaqusCae(const std::string& path);

/// Throws InputError "FILE:LINE: ENTITY: message" at `o`.
[[noreturn]] void Fail(const fe::Origin& o, const std::string& entity, const std::string& message);

/// "FILE:LINE" of `o`, for messages that point at another place.
std::string At(const fe::Origin& o);

/// `s` in upper case (ASCII).
std::string Upper(std::string_view s);

/// `s` without its leading and trailing white space.
std::string_view Trim(std::string_view s);

/// `s` without any white space ("REF NODE" -> "REFNODE").
std::string NoBlanks(std::string_view s);

/// Parses the whole of `s` as a decimal integer (a leading '+' allowed);
/// false otherwise.
bool ParseInt(std::string_view s, int64_t& v);

/// Field i of `d` as a whole number in [lo, hi]; throws naming `entity` and
/// `what` if it is missing, not a whole number or out of range.
int Integer(const DataLine& d, size_t i, const std::string& entity, const char* what, int64_t lo, int64_t hi);

/// `s` as a finite number (Fortran 'D' exponents and a leading '+'
/// accepted); throws at `o` naming `entity` and `what` otherwise.
double Real(std::string_view s, const fe::Origin& o, const std::string& entity, const char* what);

/// Field i of `d` as a number; blank or absent fields give `fallback`.
double RealOr(const DataLine& d, size_t i, const std::string& entity, const char* what, double fallback);

/// Field i of `d` as a number; throws if it is blank or absent.
double RealReq(const DataLine& d, size_t i, const std::string& entity, const char* what);

/// Field i of `d` as a positive number; throws otherwise.
double Positive(const DataLine& d, size_t i, const std::string& entity, const char* what);

/// Throws if `d` has more than `n` fields.
void MaxFields(const DataLine& d, size_t n, const std::string& entity);

/// Throws if `c`, a keyword or sub-option that flexmb reads, has a
/// parameter that flexmb does not know for it (a misspelling, or one that
/// could change the model), naming the parameter and listing the known
/// ones. Other keywords are not checked. Defined in abaqus_params.cc.
void CheckParams(const Card& c);

/// True for the shell element types (family shell in fe/element_traits.h).
inline bool IsShell(fe::ElementType t) { return fe::Traits(t).family == fe::ElementFamily::kShell; }

/// True for the beam element types (family beam in fe/element_traits.h).
inline bool IsBeam(fe::ElementType t) { return fe::Traits(t).family == fe::ElementFamily::kBeam; }

/// True for the solid element types (family solid in fe/element_traits.h).
inline bool IsSolid(fe::ElementType t) { return fe::Traits(t).family == fe::ElementFamily::kSolid; }

}  // namespace flexmb::io::abaqus
