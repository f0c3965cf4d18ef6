#pragma once
/// \file json_reader.h
/// A minimal strict JSON reader for the command-line tests: the stdout of a
/// --json command must be exactly one JSON object (RFC 8259 grammar,
/// duplicate keys rejected, \u escapes beyond ASCII not decoded).

#include <gtest/gtest.h>

#include <cctype>
#include <map>
#include <string>
#include <vector>

namespace flexmb::testing {

/// One JSON value (objects keep their keys sorted).
struct Json {
  enum Kind { kNull, kBool, kNumber, kString, kArray, kObject } kind = kNull;
  double number = 0.0;
  bool boolean = false;
  std::string string;
  std::vector<Json> array;
  std::map<std::string, Json> object;

  const Json& operator[](const std::string& key) const {
    static const Json missing;
    const auto it = object.find(key);
    return it == object.end() ? missing : it->second;
  }
  bool Has(const std::string& key) const { return object.count(key) != 0; }
  std::vector<double> Numbers() const {
    std::vector<double> v;
    for (const Json& x : array) v.push_back(x.number);
    return v;
  }
};

/// A strict JSON reader (RFC 8259 grammar; \u escapes beyond ASCII are not decoded).
class JsonParser {
 public:
  explicit JsonParser(const std::string& text) : s_(text) {}

  // the whole text as one value; false (with a reason) if it is not valid JSON
  bool Parse(Json& out, std::string& error) {
    try {
      out = Value();
      Space();
      if (p_ != s_.size()) Fail("text after the value");
      return true;
    } catch (const std::string& e) {
      error = e;
      return false;
    }
  }

 private:
  [[noreturn]] void Fail(const std::string& what) { throw what + " at offset " + std::to_string(p_); }
  void Space() {
    while (p_ < s_.size() && (s_[p_] == ' ' || s_[p_] == '\n' || s_[p_] == '\t' || s_[p_] == '\r')) ++p_;
  }
  bool Eat(char c) {
    Space();
    if (p_ < s_.size() && s_[p_] == c) {
      ++p_;
      return true;
    }
    return false;
  }
  void Expect(char c) {
    if (!Eat(c)) Fail(std::string("expected '") + c + "'");
  }
  bool Word(const char* w) {
    const std::string word(w);
    if (s_.compare(p_, word.size(), word) != 0) return false;
    p_ += word.size();
    return true;
  }
  std::string String() {
    Expect('"');
    std::string out;
    while (true) {
      if (p_ >= s_.size()) Fail("unterminated string");
      const char c = s_[p_++];
      if (c == '"') return out;
      if (static_cast<unsigned char>(c) < 0x20) Fail("control character in a string");
      if (c != '\\') {
        out += c;
        continue;
      }
      if (p_ >= s_.size()) Fail("unterminated escape");
      const char e = s_[p_++];
      const std::string simple = "\"\\/bfnrt", meaning = "\"\\/\b\f\n\r\t";
      if (simple.find(e) != std::string::npos) {
        out += meaning[simple.find(e)];
      } else if (e == 'u' && p_ + 4 <= s_.size()) {
        out += static_cast<char>(std::stoi(s_.substr(p_, 4), nullptr, 16));
        p_ += 4;
      } else {
        Fail("bad escape");
      }
    }
  }
  double Number() {
    const size_t start = p_;
    if (p_ < s_.size() && s_[p_] == '-') ++p_;
    auto digits = [&] {
      const size_t d = p_;
      while (p_ < s_.size() && std::isdigit(static_cast<unsigned char>(s_[p_]))) ++p_;
      if (p_ == d) Fail("expected digits");
    };
    if (p_ < s_.size() && s_[p_] == '0') ++p_;
    else digits();
    if (p_ < s_.size() && s_[p_] == '.') {
      ++p_;
      digits();
    }
    if (p_ < s_.size() && (s_[p_] == 'e' || s_[p_] == 'E')) {
      ++p_;
      if (p_ < s_.size() && (s_[p_] == '+' || s_[p_] == '-')) ++p_;
      digits();
    }
    return std::stod(s_.substr(start, p_ - start));
  }
  Json Value() {
    Space();
    if (p_ >= s_.size()) Fail("expected a value");
    Json v;
    const char c = s_[p_];
    if (c == '{') {
      v.kind = Json::kObject;
      ++p_;
      if (Eat('}')) return v;
      do {
        Space();
        const std::string key = String();
        if (v.object.count(key)) Fail("duplicate key " + key);
        Expect(':');
        v.object[key] = Value();
      } while (Eat(','));
      Expect('}');
    } else if (c == '[') {
      v.kind = Json::kArray;
      ++p_;
      if (Eat(']')) return v;
      do v.array.push_back(Value());
      while (Eat(','));
      Expect(']');
    } else if (c == '"') {
      v.kind = Json::kString;
      v.string = String();
    } else if (Word("null")) {
      v.kind = Json::kNull;
    } else if (Word("true") || Word("false")) {
      v.kind = Json::kBool;
      v.boolean = s_[p_ - 1] == 'e' && s_[p_ - 2] == 'u';
    } else {
      v.kind = Json::kNumber;
      v.number = Number();
    }
    return v;
  }

  const std::string& s_;
  size_t p_ = 0;
};

/// Parses the stdout of a --json command, which must be exactly one JSON object.
inline ::testing::AssertionResult ParseJsonObject(const std::string& text, Json& out) {
  std::string error;
  if (!JsonParser(text).Parse(out, error)) return ::testing::AssertionFailure() << error << " in:\n" << text;
  if (out.kind != Json::kObject) return ::testing::AssertionFailure() << "not a JSON object:\n" << text;
  return ::testing::AssertionSuccess();
}

}  // namespace flexmb::testing
