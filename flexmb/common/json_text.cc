#include "flexmb/common/json_text.h"

#include <cmath>
#include <cstdio>

namespace flexmb::io {

std::string JsonString(const std::string& s) {
  std::string out = "\"";
  for (const char c : s) {
    switch (c) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\n': out += "\\n"; break;
      case '\t': out += "\\t"; break;
      case '\r': out += "\\r"; break;
      default:
        if (static_cast<unsigned char>(c) < 0x20) {
          char buf[8];
          std::snprintf(buf, sizeof(buf), "\\u%04x", c);
          out += buf;
        } else {
          out += c;
        }
    }
  }
  return out + "\"";
}

std::string JsonNumber(double x) {
  if (!std::isfinite(x)) return "null";
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%.17g", x);
  return buf;
}

std::string JsonVector(const Eigen::Vector3d& v) {
  return "[" + JsonNumber(v.x()) + ", " + JsonNumber(v.y()) + ", " + JsonNumber(v.z()) + "]";
}

std::string JsonMatrix(const Eigen::Matrix3d& m) {
  std::string out = "[";
  for (int r = 0; r < 3; ++r) out += (r ? ", " : "") + JsonVector(m.row(r).transpose());
  return out + "]";
}

std::string JsonArray(const Eigen::VectorXd& v) {
  std::string out = "[";
  for (Eigen::Index i = 0; i < v.size(); ++i) out += (i ? ", " : "") + JsonNumber(v[i]);
  return out + "]";
}

}  // namespace flexmb::io
