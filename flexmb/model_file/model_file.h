#pragma once
/// \file model_file.h
/// Loading a model from its YAML model file (reference: docs/model-file.md).

#include <memory>
#include <string>

#include "flexmb/model/model.h"

namespace flexmb {

/// Reads the YAML model file at `path` and returns the finalized model.
/// Throws InputError "FILE:LINE: ENTITY: message" on any fault in the file
/// (syntax, unknown key, bad value, dangling reference), and when the file
/// cannot be read. `overrides` (e.g. --t-end, --dt) replace the file's
/// solver settings before the model is finalized and are checked by the
/// same rules (model/settings.h).
std::unique_ptr<Model> LoadModelFile(const std::string& path, const SolverOverrides& overrides = {});

/// Same as LoadModelFile for YAML text held in memory; `name_for_messages`
/// stands for the file name in error messages.
std::unique_ptr<Model> LoadModelString(const std::string& yaml, const std::string& name_for_messages,
                                       const SolverOverrides& overrides = {});

}  // namespace flexmb
