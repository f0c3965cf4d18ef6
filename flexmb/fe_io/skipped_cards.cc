#include "flexmb/fe_io/skipped_cards.h"

#include <algorithm>
#include <utility>
#include <vector>

#include "flexmb/common/error.h"
#include "flexmb/common/log.h"

namespace flexmb::io {

void SkippedCards::Ignored(const std::string& name, const fe::Origin& at) {
  Seen& s = ignored_[name];
  if (s.count++ == 0) s.first = at, s.order = next_++;
}

void SkippedCards::Unsupported(const std::string& name, const fe::Origin& at, const std::string& entity) {
  Seen& s = unsupported_[name];
  if (s.count++ == 0) s.first = at, s.entity = entity, s.order = next_++;
}

// "NAME (xN, first at FILE:LINE), ..." in the order of first appearance
std::string SkippedCards::List(const std::map<std::string, Seen>& cards) {
  std::vector<std::pair<std::string, const Seen*>> in_order;
  for (const auto& [name, seen] : cards) in_order.emplace_back(name, &seen);
  std::sort(in_order.begin(), in_order.end(),
            [](const auto& a, const auto& b) { return a.second->order < b.second->order; });
  std::string text;
  for (const auto& [name, seen] : in_order) {
    text += (text.empty() ? "" : ", ") + name + " (x" + std::to_string(seen->count) + ", " +
            (seen->count > 1 ? "first at " : "at ") + seen->first.file + ":" + std::to_string(seen->first.line) + ")";
  }
  return text;
}

void SkippedCards::Report(const char* kind, const std::string& file) const {
  if (!unsupported_.empty()) {
    const Seen* first = nullptr;
    for (const auto& [name, seen] : unsupported_)
      if (!first || seen.order < first->order) first = &seen;
    const std::string what = "not supported and would change the stiffness or mass of the model";
    const std::string text =
        unsupported_.size() == 1
            ? unsupported_.begin()->first + " is " + what + ": " + List(unsupported_) + " (see docs/formats.md)"
            : std::to_string(unsupported_.size()) + " " + kind + " types are " + what + ": " + List(unsupported_) +
                  " (see docs/formats.md)";
    throw InputError(text, {first->first.file, first->first.line, first->entity});
  }
  if (!ignored_.empty())
    LogWarning(file + ": skipped " + kind + "s (they do not change the stiffness or mass): " + List(ignored_));
}

}  // namespace flexmb::io
