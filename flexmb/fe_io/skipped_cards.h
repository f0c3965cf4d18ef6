#pragma once
/// \file skipped_cards.h
/// The cards (Nastran) or keywords (Abaqus) a reader does not read,
/// collected while reading and reported once at the end: those that do not
/// change the stiffness or mass of the model (loads, output requests,
/// analysis control) in one warning, those that would and are not
/// supported in one error that lists them all, so a user sees every
/// obstacle of a deck at once instead of one per attempt.

#include <map>
#include <string>

#include "flexmb/fe/mesh.h"

namespace flexmb::io {

/// See the file comment.
class SkippedCards {
 public:
  /// Records a card skipped because it does not change K or M.
  void Ignored(const std::string& name, const fe::Origin& at);
  /// Records a card that would change K or M and is not supported; `entity`
  /// names it in the error ("CROD 12").
  void Unsupported(const std::string& name, const fe::Origin& at, const std::string& entity);
  /// True if an unsupported card was recorded.
  bool HasUnsupported() const { return !unsupported_.empty(); }
  /// Throws InputError naming the first unsupported card's file, line and
  /// entity and listing every unsupported card (count, first place) if
  /// there is one; otherwise logs one warning listing the ignored cards, if
  /// any. `kind` is "card" or "keyword", `file` the deck read.
  void Report(const char* kind, const std::string& file) const;

 private:
  struct Seen {
    int count = 0;
    fe::Origin first;
    std::string entity;
    int order = 0;  // order of first appearance
  };
  static std::string List(const std::map<std::string, Seen>& cards);
  std::map<std::string, Seen> ignored_, unsupported_;
  int next_ = 0;
};

}  // namespace flexmb::io
