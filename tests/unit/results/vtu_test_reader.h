#pragma once
/// \file vtu_test_reader.h
/// A small reader of the .vtu frames of results/vtk_animation.h for tests,
/// written independently of the writer: it finds a DataArray by name in the
/// XML text and decodes it, format="ascii" as numbers, format="binary" as
/// base64 of a byte-count header (header_type UInt32 or UInt64 of the
/// <VTKFile> element, UInt32 without one) followed by little-endian values
/// of the array's type (Float64, Float32, Int32, Int64, UInt8).

#include <cstdint>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace flexmb::vtu_test {

/// The whole file as text.
inline std::string VtuTestFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream buf;
  buf << in.rdbuf();
  return buf.str();
}

/// The value of attribute `name` in the tag starting at `tag` ("" if none).
inline std::string VtuTestAttribute(const std::string& xml, size_t tag, const std::string& name) {
  const size_t end = xml.find('>', tag);
  const size_t at = xml.find(" " + name + "=\"", tag);
  if (at == std::string::npos || at > end) return "";
  const size_t v = at + name.size() + 3;
  return xml.substr(v, xml.find('"', v) - v);
}

/// Decodes base64 text; whitespace is skipped, '=' ends the data. Throws
/// std::runtime_error for another character.
inline std::vector<unsigned char> VtuTestBase64(const std::string& text) {
  std::vector<unsigned char> out;
  unsigned acc = 0;
  int bits = 0;
  for (char c : text) {
    int v;
    if (c >= 'A' && c <= 'Z') v = c - 'A';
    else if (c >= 'a' && c <= 'z') v = c - 'a' + 26;
    else if (c >= '0' && c <= '9') v = c - '0' + 52;
    else if (c == '+') v = 62;
    else if (c == '/') v = 63;
    else if (c == '=') break;
    else if (c == ' ' || c == '\n' || c == '\r' || c == '\t') continue;
    else throw std::runtime_error(std::string("not base64: ") + c);
    acc = (acc << 6) | static_cast<unsigned>(v);
    bits += 6;
    if (bits >= 8) {
      bits -= 8;
      out.push_back(static_cast<unsigned char>((acc >> bits) & 0xff));
    }
  }
  return out;
}

/// Little-endian unsigned integer of `bytes` bytes at p.
inline std::uint64_t VtuTestLittle(const unsigned char* p, int bytes) {
  std::uint64_t v = 0;
  for (int k = bytes - 1; k >= 0; --k) v = (v << 8) | p[k];
  return v;
}

/// The values of the DataArray named `name` (or of the Points' array for
/// "Points") as doubles; `format` receives its format attribute. Throws
/// std::runtime_error if the array is missing or the byte count of a binary
/// array does not match its data.
inline std::vector<double> VtuTestArray(const std::string& path, const std::string& name,
                                        std::string* format = nullptr) {
  const std::string xml = VtuTestFile(path);
  size_t tag = name == "Points" ? xml.find("<Points>") : xml.find("Name=\"" + name + "\"");
  if (tag == std::string::npos) throw std::runtime_error("no DataArray " + name + " in " + path);
  tag = name == "Points" ? xml.find("<DataArray", tag) : xml.rfind("<DataArray", tag);
  const size_t begin = xml.find('>', tag) + 1, end = xml.find("</DataArray>", begin);
  const std::string text = xml.substr(begin, end - begin);
  const std::string fmt = VtuTestAttribute(xml, tag, "format"), type = VtuTestAttribute(xml, tag, "type");
  if (format) *format = fmt;
  std::vector<double> out;
  if (fmt == "ascii") {
    std::istringstream values(text);
    double v = 0;
    while (values >> v) out.push_back(v);
    return out;
  }
  if (fmt != "binary") throw std::runtime_error("unknown format '" + fmt + "' of " + name);
  const size_t root = xml.find("<VTKFile");
  if (VtuTestAttribute(xml, root, "byte_order") != "LittleEndian") throw std::runtime_error("not little endian");
  const int header = VtuTestAttribute(xml, root, "header_type") == "UInt64" ? 8 : 4;
  const std::vector<unsigned char> raw = VtuTestBase64(text);
  if (raw.size() < static_cast<size_t>(header)) throw std::runtime_error("no header in " + name);
  const std::uint64_t bytes = VtuTestLittle(raw.data(), header);
  if (bytes != raw.size() - static_cast<size_t>(header)) throw std::runtime_error("byte count of " + name);
  const unsigned char* p = raw.data() + header;
  const int size = type == "Float64" || type == "Int64" ? 8 : type == "Float32" || type == "Int32" ? 4 : 1;
  if (bytes % static_cast<std::uint64_t>(size) != 0) throw std::runtime_error("partial value in " + name);
  for (std::uint64_t k = 0; k < bytes; k += static_cast<std::uint64_t>(size)) {
    const std::uint64_t u = VtuTestLittle(p + k, size);
    if (type == "Float64") {
      double d;
      std::memcpy(&d, &u, 8);
      out.push_back(d);
    } else if (type == "Float32") {
      const auto u32 = static_cast<std::uint32_t>(u);
      float f;
      std::memcpy(&f, &u32, 4);
      out.push_back(f);
    } else if (type == "Int32") {
      out.push_back(static_cast<double>(static_cast<std::int32_t>(static_cast<std::uint32_t>(u))));
    } else if (type == "Int64") {
      out.push_back(static_cast<double>(static_cast<std::int64_t>(u)));
    } else if (type == "UInt8") {
      out.push_back(static_cast<double>(u));
    } else {
      throw std::runtime_error("unknown type '" + type + "' of " + name);
    }
  }
  return out;
}

}  // namespace flexmb::vtu_test
