#pragma once
/// \file study_command.h
/// `flexmb study STUDY.yaml --out DIR ...`: parameter studies (docs/studies.md)
/// are implemented once, in Python (python/flexmb/study_cli.py, on Dask);
/// the command line hands its arguments to that module, so the command and
/// flexmb.study() share one implementation.

#include <string>
#include <vector>

namespace flexmb::cli {

/// Replaces this process by `PYTHON -m flexmb.study_cli ARGS...`. PYTHON is
/// $FLEXMB_PYTHON, else /usr/bin/python3 if present, else python3 on PATH.
/// The build's python/ folder next to bin/ (where the module lands) is put
/// in front of PYTHONPATH, and FLEXMB_CLI is set to this executable (unless
/// set) so that the runs use it. `self` is argv[0]. Returns only on
/// failure: 1, with the reason on stderr.
int StudyCommand(const std::vector<std::string>& args, const char* self);

}  // namespace flexmb::cli
