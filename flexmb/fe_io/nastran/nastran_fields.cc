#include "flexmb/fe_io/nastran/nastran_fields.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <system_error>
#include <utility>
#include <vector>

namespace flexmb::io::nastran {

namespace {

namespace fs = std::filesystem;

constexpr int kMaxIncludeDepth = 32;

bool IsSpace(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }
bool IsDigit(char c) { return c >= '0' && c <= '9'; }
char ToUpper(char c) { return (c >= 'a' && c <= 'z') ? static_cast<char>(c - 'a' + 'A') : c; }

std::string_view Trim(std::string_view s) {
  size_t b = 0, e = s.size();
  while (b < e && IsSpace(s[b])) ++b;
  while (e > b && IsSpace(s[e - 1])) --e;
  return s.substr(b, e - b);
}

std::string Upper(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = ToUpper(c);
  return out;
}

bool StartsWithNoCase(std::string_view s, std::string_view prefix) {
  if (s.size() < prefix.size()) return false;
  for (size_t i = 0; i < prefix.size(); ++i)
    if (ToUpper(s[i]) != prefix[i]) return false;
  return true;
}

// tabs jump to the next multiple of 8 columns, as on a punched card
std::string ExpandTabs(std::string_view line) {
  std::string out;
  out.reserve(line.size() + 16);
  for (char c : line) {
    if (c == '\t') {
      do out += ' ';
      while (out.size() % 8 != 0);
    } else {
      out += c;
    }
  }
  return out;
}

// "BEGIN BULK" (any case, any blanks between), without a comment
bool IsBeginBulk(std::string_view line) {
  const size_t dollar = line.find('$');
  if (dollar != std::string_view::npos) line = line.substr(0, dollar);
  line = Trim(line);
  if (!StartsWithNoCase(line, "BEGIN")) return false;
  std::string_view rest = line.substr(5);
  if (rest.empty() || !IsSpace(rest[0])) return false;
  return Upper(Trim(rest)) == "BULK";
}

std::vector<std::string_view> SplitLines(std::string_view text) {
  std::vector<std::string_view> lines;
  size_t start = 0;
  while (start <= text.size()) {
    size_t end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    std::string_view line = text.substr(start, end - start);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    lines.push_back(line);
    if (end == text.size()) break;
    start = end + 1;
  }
  return lines;
}

std::string ReadText(const std::string& path, const ErrorContext& where) {
  std::error_code ec;
  if (!fs::is_regular_file(path, ec))
    throw InputError("cannot open '" + path + "': no such regular file", where);
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError("cannot open '" + path + "'", where);
  std::ostringstream ss;
  ss << in.rdbuf();
  std::string text = ss.str();
  // a UTF-8 byte order mark is not part of the first card
  if (text.rfind("\xEF\xBB\xBF", 0) == 0) text.erase(0, 3);
  return text;
}

enum class NumStatus { kOk, kMalformed, kRange };

NumStatus ParseRealImpl(std::string_view s, double* value) {
  s = Trim(s);
  const size_t n = s.size();
  size_t i = 0;
  std::string buf;
  buf.reserve(n + 2);
  if (i < n && (s[i] == '+' || s[i] == '-')) {
    if (s[i] == '-') buf += '-';
    ++i;
  }
  size_t digits = 0;
  while (i < n && IsDigit(s[i])) {
    buf += s[i++];
    ++digits;
  }
  if (i < n && s[i] == '.') {
    buf += s[i++];
    while (i < n && IsDigit(s[i])) {
      buf += s[i++];
      ++digits;
    }
  }
  if (digits == 0) return NumStatus::kMalformed;
  if (i < n) {
    // exponent: E or D with optional sign, or a bare sign ("1.-3")
    const char c = ToUpper(s[i]);
    if (c == 'E' || c == 'D') {
      ++i;
    } else if (c != '+' && c != '-') {
      return NumStatus::kMalformed;
    }
    buf += 'e';
    if (i < n && (s[i] == '+' || s[i] == '-')) buf += s[i++];
    size_t exp_digits = 0;
    while (i < n && IsDigit(s[i])) {
      buf += s[i++];
      ++exp_digits;
    }
    if (exp_digits == 0 || i != n) return NumStatus::kMalformed;
  }
  double v = 0.0;
  const auto res = std::from_chars(buf.data(), buf.data() + buf.size(), v);
  if (res.ec == std::errc::result_out_of_range) return NumStatus::kRange;
  if (res.ec != std::errc() || res.ptr != buf.data() + buf.size()) return NumStatus::kMalformed;
  if (!std::isfinite(v)) return NumStatus::kRange;
  *value = v;
  return NumStatus::kOk;
}

// reads the lines of the main file and its INCLUDEs into cards
class DeckReader {
 public:
  Deck deck;

  void ReadMain(const std::string& path) {
    const std::string text = ReadText(path, ErrorContext{path, 0, ""});
    const std::vector<std::string_view> lines = SplitLines(text);
    size_t first = 0;
    for (size_t k = 0; k < lines.size(); ++k) {
      if (IsBeginBulk(lines[k])) {
        first = k + 1;
        break;
      }
    }
    std::error_code ec;
    const fs::path canonical = fs::weakly_canonical(path, ec);
    stack_.push_back(ec ? path : canonical.string());
    deck.files.push_back(path);
    ReadLines(lines, first, 0, 0);
    Flush();
  }

 private:
  std::vector<std::string> stack_;  // canonical paths of the files being read
  Card current_;
  bool has_current_ = false;
  bool done_ = false;
  bool in_equation_ = false;  // the current card is a DEQATN: its lines are free text
  bool replicated_ = false;   // the last cards came from a replication entry
  std::vector<std::string> last_rules_;  // its data fields

  // Nastran's replication entry: field 1 "=" (one image) or "=n" / "=(n)"
  // (n images) repeats the preceding card, each image from the one before
  // with the rules of the data fields: "=" the field above, "==" it and all
  // trailing fields above, "*x" / "*(x)" the field above plus x (an integer
  // stays an integer), blank a blank field, anything else itself; an entry
  // without data fields repeats the rules of the replication entry just
  // before it. Only for single-line cards (8 data fields at most).
  void Replicate(const std::string& first, std::vector<std::string> rules, int file, int line_no) {
    Flush();
    int count = 1;
    if (first.size() > 1) {
      std::string n = first.substr(1);
      if (n.size() > 2 && n.front() == '(' && n.back() == ')') n = n.substr(1, n.size() - 2);
      if (!ParseInteger(n, &count) || count < 1)
        Fail(file, line_no, "malformed replication count '" + first + "' (expected =, =n or =(n), n >= 1)");
    }
    const bool blank = std::all_of(rules.begin(), rules.end(), [](const std::string& r) { return r.empty(); });
    if (blank) {
      // "=n" alone: n more images with the increments of the entry before
      if (!replicated_)
        Fail(file, line_no, "replication entry without data fields: it repeats the increments of a preceding "
                            "replication entry, and there is none directly before it");
      rules = last_rules_;
    }
    last_rules_ = rules;
    if (deck.cards.empty() || deck.cards.back().file != file)
      Fail(file, line_no, "replication entry ('=' in field 1) without a preceding card in this file");
    if (deck.cards.back().fields.size() > 8)
      Fail(file, line_no, "replication of " + deck.cards.back().name +
                              ", a card with continuations, is not supported; write the cards out");
    for (int image = 0; image < count; ++image) {
      const Card& prev = deck.cards.back();
      Card card;
      card.name = prev.name;
      card.file = file;
      card.line = line_no;
      bool all_rest = false;
      for (size_t k = 0; k < 8; ++k) {
        const std::string& rule = k < rules.size() ? rules[k] : std::string();
        const std::string above = k < prev.fields.size() ? prev.fields[k] : std::string();
        if (rule == "==") all_rest = true;
        std::string value;
        if (all_rest || rule == "=")
          value = above;
        else if (!rule.empty() && rule.front() == '*')
          value = Increment(above, rule, file, line_no, k + 2);
        else
          value = rule;
        card.fields.push_back(std::move(value));
        card.lines.push_back(line_no);
      }
      while (!card.fields.empty() && card.fields.back().empty()) {
        card.fields.pop_back();
        card.lines.pop_back();
      }
      deck.cards.push_back(std::move(card));
    }
    replicated_ = true;
  }

  // the field above plus the increment of `rule` ("*x" or "*(x)")
  std::string Increment(const std::string& field_above, const std::string& rule, int file, int line_no,
                        size_t field) {
    const std::string above = field_above.empty() ? "0" : field_above;  // a blank field counts as 0
    std::string x = rule.substr(1);
    if (x.size() > 2 && x.front() == '(' && x.back() == ')') x = x.substr(1, x.size() - 2);
    const std::string where = "field " + std::to_string(field) + " of the replication entry";
    int ia = 0, ix = 0;
    if (!LooksReal(above) && !LooksReal(x) && ParseInteger(above, &ia) && ParseInteger(x, &ix))
      return std::to_string(static_cast<long long>(ia) + ix);
    double a = 0.0, dx = 0.0;
    if (!ParseReal(above, &a) || !ParseReal(x, &dx))
      Fail(file, line_no, where + ": cannot add '" + x + "' to '" + above + "' (both must be numbers)");
    char text[40];
    std::snprintf(text, sizeof text, "%.17g", a + dx);
    std::string out = text;
    if (out.find_first_of(".eE") == std::string::npos) out += ".";  // stays a real
    return out;
  }

  [[noreturn]] void Fail(int file, int line, const std::string& message) const {
    throw InputError(message, ErrorContext{deck.files[file], line, ""});
  }

  void Flush() {
    in_equation_ = false;
    if (!has_current_) return;
    while (!current_.fields.empty() && current_.fields.back().empty()) {
      current_.fields.pop_back();
      current_.lines.pop_back();
    }
    deck.cards.push_back(std::move(current_));
    current_ = Card();
    has_current_ = false;
  }

  void Append(std::vector<std::string>& fields, size_t width, int line) {
    fields.resize(width);
    for (std::string& f : fields) {
      current_.fields.push_back(std::move(f));
      current_.lines.push_back(line);
    }
  }

  void ReadLines(const std::vector<std::string_view>& lines, size_t first, int file, int depth) {
    for (size_t k = first; k < lines.size() && !done_; ++k) {
      const int line_no = static_cast<int>(k) + 1;
      std::string_view raw = lines[k];
      if (StartsWithNoCase(raw, "INCLUDE") &&
          (raw.size() == 7 || IsSpace(raw[7]) || raw[7] == '\'' || raw[7] == '"')) {
        Flush();
        k = Include(lines, k, file, depth);
        continue;
      }
      const size_t dollar = raw.find('$');
      if (dollar != std::string_view::npos) raw = raw.substr(0, dollar);
      if (Trim(raw).empty()) continue;
      if (StartsWithNoCase(raw, "BEGIN") && (raw.size() == 5 || IsSpace(raw[5]))) {
        if (IsBeginBulk(raw)) continue;
        Fail(file, line_no, "'" + std::string(Trim(raw)) +
                                "': BEGIN sections other than BEGIN BULK (part superelements, "
                                "auxiliary models) are not supported");
      }
      ReadDataLine(raw, file, line_no);
    }
  }

  // DEQATN EQID EQUATION: the equation (columns 17 to 72 and the following
  // lines' columns 9 to 72, up to the next card) is free text that may hold
  // commas and blanks anywhere; the card keeps EQID only. True if `raw` was
  // such a line.
  bool ReadEquationLine(std::string_view raw, int file, int line_no) {
    const std::string line = ExpandTabs(raw);
    const std::string_view head = Trim(std::string_view(line).substr(0, std::min<size_t>(8, line.size())));
    const std::string_view text = Trim(raw);
    if (in_equation_ && (head.empty() || head.front() == '+' || head.front() == '*' || text.front() == ','))
      return true;
    in_equation_ = false;
    if (!StartsWithNoCase(text, "DEQATN") ||
        !(text.size() == 6 || IsSpace(text[6]) || text[6] == ',' || text[6] == '*'))
      return false;
    Flush();
    // EQID: field 2 (columns 9 to 16, 9 to 24 in large field) or the
    // first free field
    std::string eqid;
    if (text.find(',') < 8 || (!head.empty() && Upper(head).rfind("DEQATN", 0) != 0)) {
      std::string_view rest = text.substr(6);
      while (!rest.empty() && (IsSpace(rest.front()) || rest.front() == ',' || rest.front() == '*')) rest.remove_prefix(1);
      size_t end = 0;
      while (end < rest.size() && !IsSpace(rest[end]) && rest[end] != ',') ++end;
      eqid = Upper(rest.substr(0, end));
    } else {
      const size_t width = head.back() == '*' ? 16 : 8;
      eqid = line.size() > 8 ? Upper(Trim(std::string_view(line).substr(8, width))) : std::string();
    }
    current_.name = "DEQATN";
    current_.file = file;
    current_.line = line_no;
    current_.fields = {eqid};
    current_.lines = {line_no};
    has_current_ = true;
    in_equation_ = true;
    return true;
  }

  void ReadDataLine(std::string_view raw, int file, int line_no) {
    if (ReadEquationLine(raw, file, line_no)) return;
    std::vector<std::string> fields;
    std::string first;
    bool large = false;
    if (raw.find(',') != std::string_view::npos) {
      // free field: comma separated, blanks around commas ignored
      std::vector<std::string_view> parts;
      size_t start = 0;
      while (true) {
        const size_t comma = raw.find(',', start);
        parts.push_back(raw.substr(start, comma == std::string_view::npos ? std::string_view::npos
                                                                         : comma - start));
        if (comma == std::string_view::npos) break;
        start = comma + 1;
      }
      // a trailing comma (or several) adds only blank fields
      while (parts.size() > 1 && Trim(parts.back()).empty()) parts.pop_back();
      first = Upper(Trim(parts[0]));
      large = !first.empty() && (first.front() == '*' || first.back() == '*');
      const size_t max_data = large ? 4 : 8;
      if (parts.size() > max_data + 2)
        Fail(file, line_no,
             "free-field line has " + std::to_string(parts.size()) + " fields; at most " +
                 std::to_string(max_data + 2) + " (name, " + std::to_string(max_data) +
                 " data fields, continuation) are allowed per line");
      for (size_t p = 1; p < parts.size() && p <= max_data; ++p) fields.push_back(Upper(Trim(parts[p])));
    } else {
      const std::string line = ExpandTabs(raw);
      first = Upper(Trim(std::string_view(line).substr(0, std::min<size_t>(8, line.size()))));
      large = !first.empty() && (first.front() == '*' || first.back() == '*');
      const size_t width = large ? 16 : 8;
      const size_t count = large ? 4 : 8;
      for (size_t f = 0; f < count; ++f) {
        const size_t col = 8 + f * width;
        fields.push_back(col < line.size() ? Upper(Trim(std::string_view(line).substr(col, width)))
                                           : std::string());
      }
    }
    if (!first.empty() && first.front() == '=') {
      Replicate(first, fields, file, line_no);
      return;
    }
    const bool continuation = first.empty() || first.front() == '+' || first.front() == '*';
    if (continuation) {
      if (replicated_)
        Fail(file, line_no,
             "continuation line after a replication entry ('=' in field 1): replicating cards with "
             "continuations is not supported; write the cards out");
      if (!has_current_)
        Fail(file, line_no, "continuation line without a preceding card");
      if (!large) {
        const size_t padded = (current_.fields.size() + 7) / 8 * 8;
        current_.fields.resize(padded);
        current_.lines.resize(padded, line_no);
      }
      Append(fields, large ? 4 : 8, line_no);
      return;
    }
    Flush();
    replicated_ = false;
    std::string name = first;
    if (name.back() == '*') name.pop_back();
    bool valid = !name.empty() && name.front() >= 'A' && name.front() <= 'Z';
    for (char c : name) valid = valid && ((c >= 'A' && c <= 'Z') || IsDigit(c));
    if (!valid)
      Fail(file, line_no,
           "malformed card name '" + first +
               "' (fixed-format fields must be aligned to 8 columns, 16 for large field; "
               "free-format fields are separated by commas)");
    if (name == "ENDDATA") {
      done_ = true;
      return;
    }
    current_.name = std::move(name);
    current_.file = file;
    current_.line = line_no;
    has_current_ = true;
    Append(fields, large ? 4 : 8, line_no);
  }

  // the file an INCLUDE names: as given if absolute, else the first regular
  // file among the including file's folder, the main deck's folder and the
  // current directory (Nastran's search); the error names every folder tried
  fs::path Locate(const std::string& name, int file, int line_no) {
    const fs::path given(name);
    if (!given.is_relative()) return given;
    std::error_code ec;
    const fs::path cwd = fs::current_path(ec);
    // (folder, roles) in search order, each folder once
    std::vector<std::pair<fs::path, std::string>> folders;
    const std::pair<fs::path, const char*> roles[] = {{fs::path(deck.files[file]).parent_path(), "including file"},
                                                      {fs::path(deck.files[0]).parent_path(), "main deck"},
                                                      {fs::path(), "current directory"}};
    for (const auto& role : roles) {
      fs::path normal = role.first.lexically_normal();
      if (normal == ".") normal.clear();
      bool seen = false;
      for (auto& f : folders)
        if (f.first == normal) {
          f.second += std::string(", ") + role.second;
          seen = true;
        }
      if (!seen) folders.emplace_back(normal, role.second);
    }
    for (const auto& f : folders)
      if (fs::is_regular_file(f.first / given, ec)) return f.first / given;
    std::string tried;
    for (const auto& f : folders)
      tried += (tried.empty() ? "" : "; ") + std::string("'") + (f.first.empty() ? cwd : f.first).string() + "' (" +
               f.second + ")";
    Fail(file, line_no, "INCLUDE: cannot open '" + name + "': no such regular file in any folder tried: " + tried);
  }

  // handles the INCLUDE at lines[k]; returns the index of its last line
  size_t Include(const std::vector<std::string_view>& lines, size_t k, int file, int depth) {
    const int line_no = static_cast<int>(k) + 1;
    std::string_view rest = Trim(lines[k].substr(7));
    std::string name;
    if (!rest.empty() && (rest[0] == '\'' || rest[0] == '"')) {
      const char quote = rest[0];
      std::string_view part = rest.substr(1);
      while (true) {
        const size_t close = part.find(quote);
        if (close != std::string_view::npos) {
          name += part.substr(0, close);
          break;
        }
        // the name continues on the next line
        name += Trim(part);
        if (++k >= lines.size())
          Fail(file, line_no, "INCLUDE: unterminated file name (missing closing quote)");
        part = Trim(lines[k]);
      }
    } else {
      size_t end = 0;
      while (end < rest.size() && !IsSpace(rest[end]) && rest[end] != '$') ++end;
      name = std::string(rest.substr(0, end));
    }
    if (Trim(name).empty()) Fail(file, line_no, "INCLUDE without a file name");
    if (depth + 1 > kMaxIncludeDepth)
      Fail(file, line_no, "INCLUDE nested deeper than " + std::to_string(kMaxIncludeDepth) + " levels");
    const fs::path target = Locate(name, file, line_no);
    const std::string display = target.lexically_normal().string();
    std::error_code ec;
    const fs::path canonical = fs::weakly_canonical(target, ec);
    const std::string key = ec ? display : canonical.string();
    for (const std::string& open : stack_)
      if (open == key) Fail(file, line_no, "INCLUDE cycle: '" + display + "' is already being read");
    const std::string text = ReadText(display, ErrorContext{deck.files[file], line_no, "INCLUDE"});
    const std::vector<std::string_view> included = SplitLines(text);
    const int index = static_cast<int>(deck.files.size());
    deck.files.push_back(display);
    stack_.push_back(key);
    ReadLines(included, 0, index, depth + 1);
    Flush();
    stack_.pop_back();
    return k;
  }
};

}  // namespace

Deck ReadDeck(const std::string& path) {
  DeckReader reader;
  reader.ReadMain(path);
  return std::move(reader.deck);
}

bool ParseInteger(std::string_view text, int* value) {
  text = Trim(text);
  if (text.empty()) return false;
  bool negative = false;
  if (text[0] == '+' || text[0] == '-') {
    negative = text[0] == '-';
    text.remove_prefix(1);
  }
  if (text.empty()) return false;
  for (char c : text)
    if (!IsDigit(c)) return false;
  long long v = 0;
  const auto res = std::from_chars(text.data(), text.data() + text.size(), v);
  if (res.ec != std::errc() || res.ptr != text.data() + text.size()) return false;
  if (negative) v = -v;
  if (v < INT32_MIN || v > INT32_MAX) return false;
  *value = static_cast<int>(v);
  return true;
}

bool ParseReal(std::string_view text, double* value) {
  return ParseRealImpl(text, value) == NumStatus::kOk;
}

bool LooksReal(std::string_view text) {
  text = Trim(text);
  for (size_t i = 0; i < text.size(); ++i) {
    const char c = ToUpper(text[i]);
    if (c == '.' || c == 'E' || c == 'D') return true;
    if (i > 0 && (c == '+' || c == '-')) return true;
  }
  return false;
}

std::string Entry::Entity() const {
  if (card_.fields.empty() || card_.fields[0].empty()) return card_.name;
  return card_.name + " " + card_.fields[0];
}

const std::string& Entry::Text(int i) const {
  static const std::string kEmpty;
  if (i < 1 || i > Size()) return kEmpty;
  return card_.fields[i - 1];
}

int Entry::Line(int i) const {
  if (i < 1 || i > Size()) return card_.line;
  return card_.lines[i - 1];
}

ErrorContext Entry::Context(int i) const { return ErrorContext{File(), Line(i), Entity()}; }

void Entry::Fail(int i, const std::string& message) const { throw InputError(message, Context(i)); }

int Entry::Int(int i, const char* what) const {
  if (Blank(i)) Fail(i, std::string(what) + " is required (field is blank)");
  int v = 0;
  if (!ParseInteger(Text(i), &v))
    Fail(i, std::string(what) + ": malformed integer '" + Text(i) + "'");
  return v;
}

int Entry::Int(int i, const char* what, int fallback) const {
  return Blank(i) ? fallback : Int(i, what);
}

int Entry::Id(int i, const char* what) const {
  const int v = Int(i, what);
  if (v <= 0) Fail(i, std::string(what) + " must be a positive integer, got " + std::to_string(v));
  return v;
}

double Entry::Real(int i, const char* what) const {
  if (Blank(i)) Fail(i, std::string(what) + " is required (field is blank)");
  double v = 0.0;
  switch (ParseRealImpl(Text(i), &v)) {
    case NumStatus::kOk: return v;
    case NumStatus::kRange:
      Fail(i, std::string(what) + ": number '" + Text(i) + "' is not finite in double precision");
    case NumStatus::kMalformed: break;
  }
  Fail(i, std::string(what) + ": malformed number '" + Text(i) + "'");
}

double Entry::Real(int i, const char* what, double fallback) const {
  return Blank(i) ? fallback : Real(i, what);
}

}  // namespace flexmb::io::nastran
