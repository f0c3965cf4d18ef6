#include "flexmb/fe_io/nastran/nastran_reader.h"

#include <cmath>
#include <cstdio>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "flexmb/common/error.h"
#include "flexmb/common/log.h"
#include "flexmb/fe/constraint_chains.h"
#include "flexmb/fe/element_traits.h"
#include "flexmb/fe_io/nastran/nastran_builder.h"
#include "flexmb/fe_io/skipped_cards.h"
#include "flexmb/fe_io/nastran/nastran_fields.h"

namespace flexmb::io {
namespace nastran {
namespace {

// cards are interpreted in phases, so that references may point forward in
// the file (bulk data is unordered)
enum class Phase { kDefaults, kCoords, kMaterials, kGrids, kProperties, kElements, kLinks, kSets };

const std::map<std::string, Phase>& Phases() {
  static const std::map<std::string, Phase> kPhases = [] {
    const std::pair<Phase, std::vector<const char*>> groups[] = {
        {Phase::kDefaults, {"GRDSET", "BAROR", "BEAMOR"}},
        {Phase::kCoords, {"CORD2R", "CORD2C", "CORD2S", "CORD1R", "CORD1C", "CORD1S", "CORD3G", "CORD3R"}},
        {Phase::kMaterials, {"MAT1", "MAT2", "MAT3", "MAT8", "MAT9", "MAT10", "MAT11"}},
        {Phase::kGrids, {"GRID", "SPOINT"}},
        {Phase::kProperties, {"PSHELL", "PCOMP", "PCOMPG", "PBAR", "PBARL", "PBEAM", "PBEAML", "PSOLID", "PELAS", "PROD", "PTUBE",
                                 "PBUSH", "PMASS", "PSHEAR"}},
        {Phase::kLinks, {"RBE2", "RBAR", "RBAR1", "RBE3", "CONM2", "CONM1", "CELAS1", "CELAS2", "CBUSH",
                           "CMASS1", "CMASS2"}},
        {Phase::kSets, {"SPC1", "SPC", "MPC", "ASET", "ASET1", "BSET", "BSET1", "SET1"}}};
    std::map<std::string, Phase> m;
    for (const auto& [phase, names] : groups)
      for (const char* n : names) m.emplace(n, phase);
    // the element cards of fe/element_traits.h
    for (const fe::ElementTraits& t : fe::AllElementTraits())
      for (const char* n : t.nastran_cards) m.emplace(n, Phase::kElements);
    return m;
  }();
  return kPhases;
}

// skipped without a word: they do not describe the part's K and M
const std::set<std::string> kSilent = {"PARAM", "EIGRL", "EIGR", "SPCADD", "MPCADD"};

// cards that would change stiffness or mass: reading on without them would
// give a wrong model (the element cards of fe/element_traits.h come first)
const std::set<std::string> kUnsupported = {
    "CBUSH1D", "CBUSH2D",
    "CELAS3", "CELAS4", "CGAP",    "CQUAD",
    "CBEND",   "CBEAM3",  "CWELD",   "CFAST",  "CSEAM",
    "CTRIAX", "CTRIAX6", "CQUADX", "CMASS3",  "CMASS4",
    "GENEL",  "CRAC2D", "CRAC3D",  "RBE1",    "RROD",
    "RTRPLT", "RTRPLT1", "RSPLINE", "RJOINT", "RSSCON",
    "PBUSH1D", "PBUSH2D", "PGAP",    "PCOMPLS",
    "PBCOMP", "PBEND",   "PBEAM3",  "PWELD",   "PFAST",  "PSEAM",
    "PLPLANE", "PLSOLID", "PSHLN1", "PSHLN2", "PSLDN1",  "PBRSECT", "PBMSECT", "PCONEAX"};

// design optimisation cards (SOL 200): they change properties only in an
// optimisation run; an analysis uses the property cards as they stand
const std::set<std::string> kDesignCards = {
    "DESVAR", "DVPREL1", "DVPREL2", "DVMREL1", "DVMREL2", "DVCREL1", "DVCREL2", "DVGRID", "DLINK",  "DDVAL",
    "DRESP1", "DRESP2",  "DRESP3",  "DCONSTR", "DCONADD", "DOPTPRM", "DTABLE",  "DTABLE2", "DEQATN", "DSCREEN",
    "DVSHAP", "DVBSHAP", "DVLREL1", "DVPSURF", "DRESPM",  "TOPVAR",  "DMNCON",  "DVTREL1"};

std::string ComponentString(int mask) {
  std::string s;
  for (int c = 0; c < 6; ++c)
    if (mask & (1 << c)) s += static_cast<char>('1' + c);
  return s;
}

}  // namespace

std::string Str(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

fe::Mesh Builder::Run() {
  std::vector<std::vector<const Card*>> phases(static_cast<int>(Phase::kSets) + 1);
  SkippedCards skipped;
  const Card* design = nullptr;
  for (const Card& card : deck_.cards) {
    if (!design && kDesignCards.count(card.name)) design = &card;
    const auto it = Phases().find(card.name);
    const fe::Origin at{deck_.files[card.file], card.line};
    if (it != Phases().end()) {
      phases[static_cast<int>(it->second)].push_back(&card);
    } else if (kUnsupported.count(card.name)) {
      skipped.Unsupported(card.name, at, Entry(card, deck_).Entity());
    } else if (!kSilent.count(card.name)) {
      skipped.Ignored(card.name, at);
    }
  }
  skipped.Report("card", deck_.files.empty() ? std::string() : deck_.files.front());
  if (design)
    Warn(Entry(*design, deck_),
         "design optimisation cards (" + design->name +
             " and others: SOL 200) are skipped: they change properties only in an optimisation run, where the "
             "design variables' initial values may replace property values; the model read is the one of an "
             "analysis (property cards as written)",
         "design cards");
  for (int p = 0; p < static_cast<int>(phases.size()); ++p) {
    if (p == static_cast<int>(Phase::kCoords)) {
      for (const Card* c : phases[p]) AddCoord(Entry(*c, deck_));
      for (auto& [id, cs] : coords_) Resolve(cs);
      continue;
    }
    if (p == static_cast<int>(Phase::kProperties)) {
      for (const Card* c : phases[p]) AddProperty(Entry(*c, deck_));
      continue;
    }
    for (const Card* c : phases[p]) Dispatch(Entry(*c, deck_));
    if (p == static_cast<int>(Phase::kGrids)) mesh_.IndexNodes();
  }
  FinishCdFixed();
  fe::ResolveConstraintChains(mesh_);
  mesh_.IndexNodes();
  return std::move(mesh_);
}

// one warning per key (card type, or card type and topic)
void Builder::Warn(const Entry& e, const std::string& message, const std::string& key) {
  if (!warned_.insert(key.empty() ? e.name() : key).second) return;
  LogWarning(FormatWithContext(message + " (reported once)", e.Context()));
}

void Builder::Dispatch(const Entry& e) {
  const std::string& n = e.name();
  if (n == "GRDSET" || n == "BAROR" || n == "BEAMOR") return AddDefaults(e);
  if (n.rfind("MAT", 0) == 0) return AddMaterial(e);
  if (n == "GRID") return AddGrid(e);
  if (n == "SPOINT") return AddSpoint(e);
  if (n == "CROD" || n == "CONROD" || n == "CTUBE") return AddRod(e);
  if (n == "CSHEAR") return AddShear(e);
  for (const fe::ElementTraits& t : fe::AllElementTraits())
    for (const char* card : t.nastran_cards)
      if (n == card) {
        if (t.family == fe::ElementFamily::kShell) return AddShell(e);
        if (t.family == fe::ElementFamily::kBeam) return AddBeam(e);
        return AddSolid(e);
      }
  if (n == "RBE2") return AddRbe2(e);
  if (n == "RBAR" || n == "RBAR1") return AddRbar(e);
  if (n == "RBE3") return AddRbe3(e);
  if (n == "CONM2") return AddConm2(e);
  if (n == "CONM1") return AddConm1(e);
  if (n == "CELAS1" || n == "CELAS2") return AddCelas(e);
  if (n == "CMASS1" || n == "CMASS2") return AddCmass(e);
  if (n == "CBUSH") return AddCbush(e);
  if (n == "SPC1" || n == "SPC") return AddSpc(e);
  if (n == "MPC") return AddMpc(e);
  if (n == "ASET" || n == "ASET1" || n == "BSET" || n == "BSET1") return AddBoundarySet(e);
  if (n == "SET1") return AddSet1(e);
}

void Builder::CheckNewId(std::map<int, fe::Origin>& ids, const Entry& e, int id, const char* what) {
  const auto [it, inserted] = ids.emplace(id, OriginOf(e));
  if (!inserted)
    e.Fail(1, std::string("duplicate ") + what + " id " + std::to_string(id) + " (first defined at " +
                  Where(it->second) + ")");
}

// values read are finite; values computed from them may overflow
double Builder::Positive(const Entry& e, int i, const char* what, double v) {
  if (!(v > 0.0) || !std::isfinite(v)) e.Fail(i, std::string(what) + " must be positive and finite, got " + Str(v));
  return v;
}

double Builder::NonNegative(const Entry& e, int i, const char* what, double v) {
  if (!(v >= 0.0) || !std::isfinite(v)) e.Fail(i, std::string(what) + " must not be negative, got " + Str(v));
  return v;
}

// component list "123456" as a bit mask
int Builder::Components(const Entry& e, int i, const char* what) {
  const std::string& t = e.Text(i);
  if (t.empty()) e.Fail(i, std::string(what) + " is required (field is blank)");
  int mask = 0;
  for (char c : t) {
    if (c < '1' || c > '6')
      e.Fail(i, std::string(what) + ": malformed component list '" + t + "' (digits 1 to 6 expected)");
    mask |= 1 << (c - '1');
  }
  return mask;
}

const CoordSys& Builder::Coord(const Entry& e, int i, int id) {
  const auto it = coords_.find(id);
  if (it == coords_.end()) e.Fail(i, "coordinate system " + std::to_string(id) + " does not exist");
  if (it->second.kind == 0)
    e.Fail(i, "coordinate system " + std::to_string(id) + " is a " + it->second.card->name +
                  ", which is not supported (use CORD2R, CORD2C or CORD2S)");
  return it->second;
}

int Builder::NodeIndex(const Entry& e, int i, const char* what) {
  const int id = e.Id(i, what);
  const auto it = nodes_.find(id);
  if (it == nodes_.end()) {
    for (const SpointRange& r : spoints_)
      if (id >= r.first && id <= r.last)
        e.Fail(i, std::to_string(id) + " is a scalar point (SPOINT at " + Where(r.origin) +
                      "), which flexmb does not support: only grid points carry DOF");
    e.Fail(i, "node " + std::to_string(id) + " does not exist");
  }
  return it->second;
}

// SPOINT: ids one by one, or "ID1 THRU ID2"; recorded for the messages of
// the cards that refer to them (scalar points carry no DOF in flexmb)
void Builder::AddSpoint(const Entry& e) {
  int previous = -1;  // the field of the id added last from this card
  for (int i = 1; i <= e.Size(); ++i) {
    if (e.Blank(i)) continue;
    if (e.Text(i) == "THRU") {
      if (previous != i - 1) e.Fail(i, "THRU needs an id right before it");
      const int first = spoints_.back().first, last = e.Id(i + 1, "ID");
      if (last < first) e.Fail(i + 1, "THRU range ends below its start");
      spoints_.back().last = last;  // the range's first id was added as a single one
      ++i;
      continue;
    }
    previous = i;
    const int id = e.Id(i, "ID");
    spoints_.push_back({id, id, OriginOf(e)});
  }
}

int Builder::MaterialIndex(const Entry& e, int i, int id) {
  const auto it = materials_.find(id);
  if (it != materials_.end()) return it->second;
  const auto other = other_materials_.find(id);
  if (other != other_materials_.end())
    e.Fail(i, "material " + std::to_string(id) + " is a " + other->second +
                  ", which is not supported here (MAT1 everywhere; MAT2 and MAT8 in shell properties)");
  e.Fail(i, "material " + std::to_string(id) + " does not exist");
}

int Builder::PropertyIndex(const Entry& e, int i, int pid, std::initializer_list<const char*> cards) {
  const auto it = properties_.find(pid);
  std::string expected;
  for (const char* c : cards) expected += (expected.empty() ? "" : " or ") + std::string(c);
  if (it == properties_.end())
    e.Fail(i, "property " + std::to_string(pid) + " does not exist (" + e.name() + " needs a " +
                  expected + ")");
  for (const char* c : cards)
    if (it->second.card == c) return it->second.index;
  e.Fail(i, "property " + std::to_string(pid) + " is a " + it->second.card + "; " + e.name() +
                " needs a " + expected);
}

// DOF components of a node with a displacement system other than basic:
// only the sets independent of the system's orientation can be kept
void Builder::CheckCd(const Entry& e, int i, int node, int mask) {
  const int cd = node_cd_[node];
  if (cd == 0 || mask == 0b111 || mask == 0b111000 || mask == 0b111111) return;
  e.Fail(i, "components " + ComponentString(mask) + " of node " + std::to_string(mesh_.nodes[node].id) +
                " refer to its displacement system CD = " + std::to_string(cd) +
                "; flexmb keeps DOF in the basic frame and supports only 123, 456 or 123456 there "
                "(unsupported)");
}

// a grid list from field `first`: ids and "a THRU b" ranges; stops at a
// real if `stop_at_real` (RBE2's ALPHA). Explicit ids must exist (or set
// *explicit_missing if given). Ids missing in a THRU range are an error if
// `strict`, else skipped with a warning (Nastran's SPC1 rule).
std::vector<std::pair<int, int>> Builder::GridList(const Entry& e, int first, bool stop_at_real, bool strict,
                                                   bool* explicit_missing) {
  std::vector<std::pair<int, int>> out;  // node index, field
  long long skipped = 0;
  for (int f = first; f <= e.Size(); ++f) {
    const std::string& t = e.Text(f);
    if (t.empty()) continue;
    if (stop_at_real && nastran::LooksReal(t)) break;
    if (t == "THRU") e.Fail(f, "THRU must follow a grid id");
    if (e.Text(f + 1) == "THRU") {
      const int a = e.Id(f, "grid id before THRU");
      const int b = e.Id(f + 2, "grid id after THRU");
      const std::string range = "THRU range " + std::to_string(a) + " to " + std::to_string(b);
      if (b < a) e.Fail(f + 2, range + " is empty");
      long long expected = a, found = 0;
      for (auto it = nodes_.lower_bound(a); it != nodes_.end() && it->first <= b; ++it) {
        if (strict && it->first != expected)
          e.Fail(f + 1, range + ": node " + std::to_string(expected) + " does not exist");
        expected = static_cast<long long>(it->first) + 1;
        out.emplace_back(it->second, f);
        ++found;
      }
      if (strict && expected != static_cast<long long>(b) + 1)
        e.Fail(f + 1, range + ": node " + std::to_string(expected) + " does not exist");
      skipped += static_cast<long long>(b) - a + 1 - found;
      f += 2;
      continue;
    }
    const int id = e.Id(f, "grid id");
    const auto it = nodes_.find(id);
    if (it == nodes_.end()) {
      if (explicit_missing) {
        *explicit_missing = true;
        continue;
      }
      e.Fail(f, "node " + std::to_string(id) + " does not exist");
    }
    out.emplace_back(it->second, f);
  }
  if (skipped > 0)
    LogWarning(FormatWithContext(
        std::to_string(skipped) + " grid ids of THRU ranges do not exist and are skipped", e.Context()));
  return out;
}

}  // namespace nastran

fe::Mesh ReadNastran(const std::string& path) { return nastran::Builder(path).Run(); }

}  // namespace flexmb::io
