#include "apps/flexmb/commands/study_command.h"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

namespace flexmb::cli {

namespace {

// this executable's absolute path (/proc/self/exe, else argv[0] made absolute)
std::filesystem::path StudyCommandSelf(const char* self) {
  std::error_code ec;
  std::filesystem::path p = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (ec) p = std::filesystem::absolute(self, ec);
  return p;
}

}  // namespace

int StudyCommand(const std::vector<std::string>& args, const char* self) {
  const std::filesystem::path exe = StudyCommandSelf(self);
  // <build>/bin/flexmb next to <build>/python/flexmb/
  const std::filesystem::path py_dir = exe.parent_path().parent_path() / "python";
  std::error_code ec;
  if (std::filesystem::exists(py_dir / "flexmb" / "study_cli.py", ec)) {
    const char* old = std::getenv("PYTHONPATH");
    std::string path = py_dir.string();
    if (old && *old) path += std::string(":") + old;
    setenv("PYTHONPATH", path.c_str(), 1);
  }
  if (!std::getenv("FLEXMB_CLI")) setenv("FLEXMB_CLI", exe.c_str(), 1);
  std::string python = "python3";
  if (const char* env = std::getenv("FLEXMB_PYTHON"); env && *env) {
    python = env;
  } else if (access("/usr/bin/python3", X_OK) == 0) {
    python = "/usr/bin/python3";
  }
  std::vector<std::string> words = {python, "-m", "flexmb.study_cli"};
  words.insert(words.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& w : words) argv.push_back(w.data());
  argv.push_back(nullptr);
  std::fflush(stdout);
  execvp(python.c_str(), argv.data());
  std::fprintf(stderr, "error: flexmb study needs Python 3 with the flexmb module (%s: %s); see docs/studies.md\n",
               python.c_str(), std::strerror(errno));
  return 1;
}

}  // namespace flexmb::cli
