#include "apps/flexmb/commands/command_support.h"

#include <cmath>
#include <cstdio>
#include <filesystem>

#include "flexmb/fe_io/fe_model_file.h"
#include "flexmb/fe_io/matrix_text.h"

namespace flexmb::io::command {

double Seconds(Clock::time_point a, Clock::time_point b) { return std::chrono::duration<double>(b - a).count(); }

std::string Short(double x) {
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%.6g", x);
  return buf;
}

std::string ShortVector(const Eigen::Vector3d& v) {
  return "(" + Short(v.x()) + ", " + Short(v.y()) + ", " + Short(v.z()) + ")";
}

std::string ModelName(const std::string& path) {
  const std::filesystem::path p(path);
  return p.has_filename() ? p.filename().string() : p.parent_path().filename().string();
}

void WriteFrequencyTable(std::ostream& out, const Eigen::VectorXd& frequencies_hz) {
  out << "mode  frequency [Hz]\n";
  char line[64];
  for (Eigen::Index k = 0; k < frequencies_hz.size(); ++k) {
    std::snprintf(line, sizeof(line), "%4d  %.9g\n", static_cast<int>(k + 1), frequencies_hz[k]);
    out << line;
  }
}

void WriteMassText(std::ostream& out, double mass, const Eigen::Vector3d& center, const Eigen::Matrix3d& inertia,
                   const char* axes) {
  out << "mass: " << Short(mass) << " kg\n";
  out << "centre of mass: " << ShortVector(center) << " m\n";
  out << "inertia about the centre of mass (" << axes << " axes): [" << ShortVector(inertia.row(0).transpose())
      << ", " << ShortVector(inertia.row(1).transpose()) << ", " << ShortVector(inertia.row(2).transpose())
      << "] kg m^2\n";
}

std::vector<double> NumberList(const std::string& text, const std::string& option) {
  std::vector<double> v;
  size_t start = 0;
  while (true) {
    const size_t end = text.find(',', start);
    const std::string_view token = std::string_view(text).substr(start, end == std::string::npos ? end : end - start);
    double x = 0.0;
    if (!io::ParseDoubleToken(token, x) || !std::isfinite(x))
      throw InputError(option + " expects comma-separated numbers, got '" + text + "': '" + std::string(token) +
                       "' is not a number");
    v.push_back(x);
    if (end == std::string::npos) break;
    start = end + 1;
  }
  return v;
}

std::vector<int> NodeListOption(const fe::Mesh& mesh, const std::string& list, const std::string& path) {
  if (list.empty()) return {};
  return InFile(path, [&] { return ResolveNodeList(mesh, list); });
}

}  // namespace flexmb::io::command
