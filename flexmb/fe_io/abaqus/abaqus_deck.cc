#include "flexmb/fe_io/abaqus/abaqus_deck.h"

#include <cctype>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>

#include "flexmb/common/error.h"
#include "flexmb/fe_io/text_scanner.h"

namespace flexmb::io::abaqus {
namespace {

using fe::Origin;

constexpr int kMaxIncludeDepth = 16;


// splits at commas outside double quotes; fields trimmed, quotes removed.
// Returns an error message for malformed quoting (empty if none).
std::string SplitFields(std::string_view line, std::vector<std::string>& out, bool& trailing_comma) {
  out.clear();
  std::string cur;
  bool quoted = false, was_quoted = false;
  for (char c : line) {
    if (c == '"') {
      if (!quoted && !was_quoted && Trim(cur).empty()) cur.clear();
      if (!quoted && was_quoted) return "two quoted parts in one field";
      quoted = !quoted;
      was_quoted = true;
      continue;
    }
    if (c == ',' && !quoted) {
      out.push_back(was_quoted ? cur : std::string(Trim(cur)));
      cur.clear();
      was_quoted = false;
      continue;
    }
    if (!quoted && was_quoted && !std::isspace(static_cast<unsigned char>(c))) return "text after a closing quote";
    cur += c;
  }
  if (quoted) return "unterminated quote";
  const std::string last = was_quoted ? cur : std::string(Trim(cur));
  trailing_comma = last.empty() && !was_quoted && !out.empty();
  if (!trailing_comma) out.push_back(last);
  return "";
}

std::vector<std::string> SplitKeyword(std::string_view line, const Origin& o, bool& trailing_comma) {
  std::vector<std::string> out;
  const std::string error = SplitFields(line, out, trailing_comma);
  if (!error.empty()) Fail(o, "", error);
  return out;
}

DataLine SplitData(std::string_view line, const Origin& o) {
  DataLine d;
  d.origin = o;
  d.error = SplitFields(line, d.fields, d.continued);
  return d;
}

// blank lines and "**" comments carry nothing
bool IsComment(std::string_view line) { return line.empty() || line.substr(0, 2) == "**"; }

// keyword names and parameters whose data follow the keyword line
const std::set<std::string>& KeywordsWithInput() {
  static const std::set<std::string> k = {"NODE", "ELEMENT", "NSET", "ELSET", "BOUNDARY", "SURFACE"};
  return k;
}

bool IsRegularFile(const std::string& path) {
  std::error_code ec;
  return std::filesystem::is_regular_file(path, ec);
}

std::string Resolve(const std::string& including_file, const std::string& name) {
  std::filesystem::path p(name);
  if (p.is_absolute()) return p.string();
  return (std::filesystem::path(including_file).parent_path() / p).string();
}

class DeckLexer {
 public:
  std::vector<Card> cards;

  void ReadFile(const std::string& path, int depth, const Origin* from) {
    if (depth > kMaxIncludeDepth)
      Fail(*from, "*INCLUDE", "includes nested deeper than " + std::to_string(kMaxIncludeDepth) +
                                  " levels (an include cycle?)");
    if (!IsRegularFile(path)) {
      std::error_code ec;
      const bool exists = std::filesystem::exists(path, ec);
      const std::string what = exists ? "is not a regular file" : "does not exist";
      if (from != nullptr) Fail(*from, "*INCLUDE", "file '" + Printable(path) + "' " + what);
      throw InputError("cannot read: the file " + what, {path, 0, ""});
    }
    TextScanner sc(path);
    std::string_view raw;
    bool keyword_continues = false;
    while (sc.NextLine(raw)) {
      const Origin o{path, sc.line()};
      const std::string_view line = Trim(raw);
      if (keyword_continues) {
        keyword_continues = AddParams(cards.back(), line, o);
        if (!keyword_continues) Complete(depth);
        continue;
      }
      if (IsComment(line)) continue;
      if (line[0] == '*') {
        Card c;
        c.origin = o;
        bool trailing = false;
        const std::vector<std::string> f = SplitKeyword(line.substr(1), o, trailing);
        c.key = Upper(NoBlanks(f[0]));
        if (c.key.empty()) Fail(o, "", "empty keyword");
        c.name = "*" + Upper(f[0]);
        for (size_t i = 1; i < f.size(); ++i) AddParam(c, f[i], o);
        cards.push_back(std::move(c));
        keyword_continues = trailing;
        if (!keyword_continues) Complete(depth);
        continue;
      }
      if (cards.empty()) Fail(o, "", "data line before the first keyword");
      cards.back().data.push_back(SplitData(line, o));
    }
    if (keyword_continues) Complete(depth);
  }

 private:
  static void AddParam(Card& c, const std::string& field, const Origin& o) {
    if (field.empty()) return;
    Param p;
    const size_t eq = field.find('=');
    p.key = Upper(NoBlanks(field.substr(0, eq)));
    if (eq != std::string::npos) {
      p.has_value = true;
      p.value = std::string(Trim(field.substr(eq + 1)));
    }
    if (p.key.empty()) Fail(o, c.name, "parameter without a name");
    c.params.push_back(std::move(p));
  }

  // continuation of a keyword line; true if it continues further
  static bool AddParams(Card& c, std::string_view line, const Origin& o) {
    bool trailing = false;
    for (const std::string& f : SplitKeyword(line, o, trailing)) AddParam(c, f, o);
    return trailing;
  }

  // the keyword line is complete: follow *INCLUDE and INPUT=
  void Complete(int depth) {
    Card& c = cards.back();
    const Param* input = c.Find("INPUT");
    if (c.key == "INCLUDE") {
      if (input == nullptr || input->value.empty()) Fail(c.origin, c.name, "needs INPUT=<file>");
      const Origin from = c.origin;
      const std::string path = Resolve(from.file, input->value);
      cards.pop_back();
      ReadFile(path, depth + 1, &from);
      return;
    }
    if (input == nullptr || !KeywordsWithInput().count(c.key)) return;
    if (input->value.empty()) Fail(c.origin, c.name, "INPUT= needs a file name");
    const std::string path = Resolve(c.origin.file, input->value);
    if (!IsRegularFile(path)) Fail(c.origin, c.name, "INPUT file '" + Printable(path) + "' cannot be read");
    TextScanner sc(path);
    std::string_view raw;
    while (sc.NextLine(raw)) {
      const Origin o{path, sc.line()};
      const std::string_view line = Trim(raw);
      if (IsComment(line)) continue;
      if (line[0] == '*') Fail(o, c.name, "a file given by INPUT= may hold data lines only");
      c.data.push_back(SplitData(line, o));
    }
  }
};

}  // namespace

std::vector<Card> ReadCards(const std::string& path) {
  DeckLexer lexer;
  lexer.ReadFile(path, 0, nullptr);
  return std::move(lexer.cards);
}

bool WrittenByAbaqusCae(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::string line;
  for (int k = 0; k < 200 && std::getline(in, line); ++k)
    if (NoBlanks(Upper(line)).rfind("**GENERATEDBY:ABAQUS/CAE", 0) == 0) return true;
  return false;
}

[[noreturn]] void Fail(const Origin& o, const std::string& entity, const std::string& message) {
  throw InputError(message, {o.file, o.line, entity});
}

std::string Upper(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return out;
}

std::string_view Trim(std::string_view s) {
  size_t b = 0, e = s.size();
  while (b < e && std::isspace(static_cast<unsigned char>(s[b]))) ++b;
  while (e > b && std::isspace(static_cast<unsigned char>(s[e - 1]))) --e;
  return s.substr(b, e - b);
}

std::string NoBlanks(std::string_view s) {
  std::string out;
  for (char c : s)
    if (!std::isspace(static_cast<unsigned char>(c))) out += c;
  return out;
}

std::string At(const Origin& o) { return o.file + ":" + std::to_string(o.line); }

bool ParseInt(std::string_view s, int64_t& v) {
  if (s.size() > 1 && s[0] == '+') s.remove_prefix(1);
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  return ec == std::errc() && end == s.data() + s.size();
}

int Integer(const DataLine& d, size_t i, const std::string& entity, const char* what, int64_t lo, int64_t hi) {
  if (i >= d.fields.size() || d.fields[i].empty()) Fail(d.origin, entity, std::string("missing ") + what);
  int64_t v = 0;
  if (!ParseInt(d.fields[i], v))
    Fail(d.origin, entity, std::string("expected a whole number for ") + what + ", got '" + Printable(d.fields[i]) + "'");
  if (v < lo || v > hi)
    Fail(d.origin, entity, std::string(what) + " " + std::to_string(v) + " is out of range [" + std::to_string(lo) +
                               ", " + std::to_string(hi) + "]");
  return static_cast<int>(v);
}

double Real(std::string_view s, const Origin& o, const std::string& entity, const char* what) {
  std::string t(Trim(s));
  for (char& c : t)
    if (c == 'd' || c == 'D') c = 'e';  // Fortran exponent
  std::string_view v = t;
  if (v.size() > 1 && v[0] == '+' && v[1] != '+' && v[1] != '-') v.remove_prefix(1);
  double x = 0.0;
  const auto [end, ec] = std::from_chars(v.data(), v.data() + v.size(), x);
  if (ec == std::errc::result_out_of_range)
    Fail(o, entity, std::string(what) + " is out of the range of a double: '" + Printable(s) + "'");
  if (v.empty() || ec != std::errc() || end != v.data() + v.size())
    Fail(o, entity, std::string("expected a number for ") + what + ", got '" + Printable(s) + "'");
  if (!std::isfinite(x)) Fail(o, entity, std::string(what) + " must be finite, got '" + Printable(s) + "'");
  return x;
}

// field i as a number; blank or absent fields give `fallback`
double RealOr(const DataLine& d, size_t i, const std::string& entity, const char* what, double fallback) {
  if (i >= d.fields.size() || d.fields[i].empty()) return fallback;
  return Real(d.fields[i], d.origin, entity, what);
}

double RealReq(const DataLine& d, size_t i, const std::string& entity, const char* what) {
  if (i >= d.fields.size() || d.fields[i].empty()) Fail(d.origin, entity, std::string("missing ") + what);
  return Real(d.fields[i], d.origin, entity, what);
}

double Positive(const DataLine& d, size_t i, const std::string& entity, const char* what) {
  const double v = RealReq(d, i, entity, what);
  if (!(v > 0.0)) Fail(d.origin, entity, std::string(what) + " must be positive, got " + d.fields[i]);
  return v;
}

void MaxFields(const DataLine& d, size_t n, const std::string& entity) {
  if (d.fields.size() > n)
    Fail(d.origin, entity, "too many values on the line (" + std::to_string(d.fields.size()) + ", at most " +
                               std::to_string(n) + ")");
}

}  // namespace flexmb::io::abaqus
