// The parameters of the keywords flexmb reads: any other parameter on such
// a keyword is an error that names it (a misspelled or unsupported
// parameter could change the model). Parameters that flexmb accepts but
// does not use are those that cannot change a linear model's stiffness or
// mass (set bookkeeping, damping factors, controls of nonlinear or
// thermal analyses, isotropic orientations); the builders reject the known
// ones they do not support with their own message (docs/formats.md).

#include <map>
#include <string>
#include <vector>

#include "flexmb/fe_io/abaqus/abaqus_deck.h"
#include "flexmb/fe_io/text_scanner.h"

namespace flexmb::io::abaqus {

void CheckParams(const Card& c) {
  // keyword (upper case, no blanks) -> its parameters (likewise)
  static const std::map<std::string, std::vector<std::string>> kParams = {
      {"NODE", {"NSET", "SYSTEM", "INPUT"}},
      {"ELEMENT", {"TYPE", "ELSET", "INPUT"}},
      {"NSET", {"NSET", "ELSET", "GENERATE", "INPUT", "INTERNAL", "UNSORTED", "INSTANCE"}},
      {"ELSET", {"ELSET", "GENERATE", "INPUT", "INTERNAL", "UNSORTED", "INSTANCE"}},
      {"SURFACE", {"NAME", "TYPE", "INPUT", "INTERNAL"}},
      {"MATERIAL", {"NAME"}},
      {"ELASTIC", {"TYPE", "MODULI", "DEPENDENCIES"}},
      {"DENSITY", {"DEPENDENCIES"}},
      {"SOLIDSECTION", {"ELSET", "MATERIAL", "ORIENTATION", "CONTROLS"}},
      {"SHELLSECTION",
       {"ELSET", "MATERIAL", "OFFSET", "ORIENTATION", "COMPOSITE", "NODALTHICKNESS", "SECTIONINTEGRATION", "POISSON",
        "CONTROLS", "TEMPERATURE"}},
      {"MEMBRANESECTION", {"ELSET", "MATERIAL", "OFFSET", "ORIENTATION", "NODALTHICKNESS", "CONTROLS"}},
      {"BEAMSECTION", {"ELSET", "MATERIAL", "SECTION", "POISSON", "TEMPERATURE", "ORIENTATION", "OFFSET1", "OFFSET2"}},
      {"BEAMGENERALSECTION", {"ELSET", "SECTION", "DENSITY", "MATERIAL", "POISSON"}},
      {"TRANSVERSESHEARSTIFFNESS", {}},
      {"MASS", {"ELSET", "ALPHA"}},
      {"SPRING", {"ELSET", "ORIENTATION", "NONLINEAR"}},
      {"ROTARYINERTIA", {"ELSET", "ALPHA", "ORIENTATION"}},
      {"BOUNDARY", {"OP", "TYPE", "USER", "AMPLITUDE", "INPUT", "FIXED"}},
      {"RIGIDBODY", {"REFNODE", "ROTNODE", "NSET", "ELSET", "TIENSET", "PINNSET", "ISOTHERMAL"}},
      {"COUPLING", {"REFNODE", "SURFACE", "CONSTRAINTNAME"}},
      {"KINEMATIC", {}},
      {"DISTRIBUTING", {"WEIGHTINGMETHOD"}},
      {"SYSTEM", {}},
      {"EQUATION", {"INPUT"}},
      {"TIE",
       {"NAME", "POSITIONTOLERANCE", "ADJUST", "TYPE", "NOROTATION", "CYCLICSYMMETRY", "MULTISTAGE", "FLUIDCOUPLING",
        "THERMAL", "CONSTRAINTRATIO", "NOTHICKNESS"}},
  };
  auto it = kParams.find(c.key);
  if (it == kParams.end()) return;
  for (const Param& p : c.params) {
    bool known = false;
    for (const std::string& k : it->second) known = known || p.key == k;
    if (known) continue;
    std::string list;
    for (const std::string& k : it->second) list += (list.empty() ? "" : ", ") + k;
    Fail(c.origin, c.name, "unknown parameter " + p.key + (p.has_value ? "=" + Printable(p.value) : "") +
                               (list.empty() ? " (this keyword takes none)" : " (flexmb knows " + list + ")"));
  }
}

}  // namespace flexmb::io::abaqus
