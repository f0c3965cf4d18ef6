#pragma once
/// \file nastran_builder.h
/// The model layer of the Nastran bulk data reader (internal to flexmb/io):
/// turns the cards of nastran_fields.h into an fe::Mesh. Its members are
/// defined by topic: nastran_reader.cc (card phases, checks and lookups),
/// nastran_geometry.cc (defaults, coordinate systems, materials, grids),
/// nastran_properties.cc (PSHELL, PSOLID, PBAR, PBARL, PBEAM, PBEAML),
/// nastran_elements.cc (shells, solids, beams, CONM2, CONM1),
/// nastran_rods.cc (PROD, PTUBE, CROD, CONROD, CTUBE),
/// nastran_springs.cc (PELAS, CELAS1, CELAS2), nastran_masses.cc (PMASS,
/// CMASS1, CMASS2), nastran_bush.cc (PBUSH, CBUSH),
/// nastran_cd.cc (components in a displacement system, GRID CD) and
/// nastran_constraints.cc (RBE2, SPC, ASET / BSET, SET1) and
/// nastran_rigid_elements.cc (RBAR, RBAR1, RBE3).

#include <array>
#include <initializer_list>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "flexmb/fe/mesh.h"
#include "flexmb/fe_io/nastran/nastran_fields.h"

namespace flexmb::io::nastran {

/// A coordinate system card, CORD2R/C/S resolved to the basic frame.
struct CoordSys {
  const Card* card = nullptr;
  char kind = 'R';            ///< R, C, S; 0 for unsupported definitions (CORD1x, CORD3x)
  int rid = 0;                ///< system the defining points are given in
  fe::Vec3 a = fe::Vec3::Zero(), b = fe::Vec3::Zero(), c = fe::Vec3::Zero();  ///< defining points in RID
  int state = 0;              ///< 0 unresolved, 1 on the resolution path, 2 resolved
  fe::Vec3 origin = fe::Vec3::Zero();     ///< [basic]
  fe::Mat3 R = fe::Mat3::Identity();      ///< columns: local axes in basic
};

/// Basic position of the point with coordinates `coords` in the system
/// `cs` (rectangular, cylindrical (r, theta deg, z) or spherical (r, theta
/// deg, phi deg)).
fe::Vec3 ToBasic(const CoordSys& cs, const fe::Vec3& coords);

/// The system's unit axes at a basic position x, as columns: R for
/// rectangular, (e_r, e_theta, e_z) for cylindrical, (e_r, e_theta, e_phi)
/// for spherical.
fe::Mat3 BasisAt(const CoordSys& cs, const fe::Vec3& x);

/// The matrix with columns c0, c1, c2.
fe::Mat3 Columns(const fe::Vec3& c0, const fe::Vec3& c1, const fe::Vec3& c2);

/// `v` with 6 significant digits, for messages.
std::string Str(double v);

/// What a property id names: the card and its section.
struct PropertyRef {
  std::string card;  ///< "PSHELL", "PBAR", ...
  int index = -1;    ///< into the family's section list
};

/// The rows that make the components `mask3` (bits 0..2: axes of `basis`,
/// columns in basic) of the translations (block 0) or rotations (block 3)
/// of node `node` follow node `independent` rigidly (or stay zero if
/// independent < 0): D^T u = D^T W u_ind, D the masked axes, W the rigid
/// map. Each row makes one basic component of the node (the best
/// conditioned choice) dependent on its other components and on the
/// independent node; id, card and origin are left to the caller.
std::vector<fe::LinearConstraint> CdRows(const fe::Mesh& mesh, int node, int block, const fe::Mat3& basis, int mask3,
                                         int independent);

/// A PBUSH's stiffness: K1..K6 along the CBUSH element axes.
struct BushProperty {
  std::array<double, 6> k{};      ///< [N/m] (K1..K3), [N m/rad] (K4..K6)
  std::array<bool, 6> given{};    ///< field not blank
};

/// A material as a shell section uses it (PSHELL MID1, MID2, MID3): the
/// plane-stress stiffness in its material axes, the transverse-shear
/// stiffness (xz, yz) and the density.
struct ShellMaterial {
  fe::Mat3 q = fe::Mat3::Zero();                    ///< (s11 s22 s12) = q (e11 e22 g12) [Pa]
  Eigen::Matrix2d shear = Eigen::Matrix2d::Zero();  ///< (t13 t23) = shear (g13 g23) [Pa]
  double rho = 0.0;                                 ///< [kg/m^3]
};

/// Builds the mesh of one bulk data file; see ReadNastran.
class Builder {
 public:
  /// Reads the deck of `path` (nastran::ReadDeck); `path` becomes mesh.source.
  explicit Builder(const std::string& path) : deck_(ReadDeck(path)) { mesh_.source = path; }

  /// Interprets the cards in phases (defaults, coordinate systems,
  /// materials, grids, properties, elements, links, sets) so that
  /// references may point forward; throws InputError naming file, line and
  /// card on bad or unsupported input.
  fe::Mesh Run();

 private:
  Deck deck_;
  fe::Mesh mesh_;
  std::map<int, CoordSys> coords_;
  std::map<int, int> nodes_;                    // grid id -> node index
  struct SpointRange {
    int first, last;
    fe::Origin origin;
  };
  std::vector<SpointRange> spoints_;            // scalar point ids (SPOINT), for messages
  std::vector<int> node_cd_;                    // displacement system per node
  std::map<int, int> materials_;                // MAT1 id -> index
  std::map<int, std::string> other_materials_;  // unsupported material id -> card
  std::map<int, fe::LaminatePly> ply_materials_;  // MAT8 id -> its ply (t, theta unset)
  std::map<int, ShellMaterial> mat2_;           // MAT2 id -> its shell stiffness
  std::map<int, fe::Origin> material_origin_;
  std::map<int, PropertyRef> properties_;
  std::map<int, fe::Origin> property_origin_;
  std::vector<double> pelas_k_;                 // PELAS stiffness by property index
  std::vector<double> pmass_m_;                 // PMASS mass by property index
  std::vector<BushProperty> pbush_;             // PBUSH by property index
  std::map<int, fe::Origin> element_ids_;       // elements, RBE2/RBAR/RBE3, masses and springs share the id space
  std::map<std::string, std::set<int>> set_members_;
  std::set<std::string> warned_;
  std::map<int, std::pair<int, fe::Origin>> cd_fixed_;  // node -> fixed CD components, first card
  const Card* grdset_ = nullptr;
  const Card* baror_ = nullptr;
  const Card* beamor_ = nullptr;

  static fe::Origin OriginOf(const Entry& e) { return fe::Origin{e.File(), e.Line()}; }
  static std::string Where(const fe::Origin& o) { return o.file + ":" + std::to_string(o.line); }

  // nastran_reader.cc
  void Warn(const Entry& e, const std::string& message, const std::string& key = "");
  void Dispatch(const Entry& e);
  void CheckNewId(std::map<int, fe::Origin>& ids, const Entry& e, int id, const char* what);
  static double Positive(const Entry& e, int i, const char* what, double v);
  static double NonNegative(const Entry& e, int i, const char* what, double v);
  static int Components(const Entry& e, int i, const char* what);
  const CoordSys& Coord(const Entry& e, int i, int id);
  int NodeIndex(const Entry& e, int i, const char* what);
  void AddSpoint(const Entry& e);
  int MaterialIndex(const Entry& e, int i, int id);
  int PropertyIndex(const Entry& e, int i, int pid, std::initializer_list<const char*> cards);
  void CheckCd(const Entry& e, int i, int node, int mask);
  std::vector<std::pair<int, int>> GridList(const Entry& e, int first, bool stop_at_real, bool strict,
                                            bool* explicit_missing = nullptr);

  // nastran_cd.cc: components in a displacement system (GRID CD)
  fe::Mat3 CdBasis(int node);
  void AddFixed(const Entry& e, int node, int mask);
  void FinishCdFixed();
  bool AddCdRigid(const Entry& e, int id, int independent, int dependent, int mask);

  // nastran_geometry.cc
  void AddDefaults(const Entry& e);
  void AddCoord(const Entry& e);
  void Resolve(CoordSys& target);
  void AddMaterial(const Entry& e);
  void AddGrid(const Entry& e);

  // nastran_properties.cc
  void AddProperty(const Entry& e);
  int AddPshell(const Entry& e, int pid);

  // nastran_laminates.cc
  void AddMat8(const Entry& e, int id);
  void AddMat2(const Entry& e, int id);
  fe::LaminatePly PlyMaterial(const Entry& e, int i, int mid);
  ShellMaterial ShellMaterialOf(const Entry& e, int i, int mid);
  int AddPcomp(const Entry& e, int pid);
  void ReadShellMaterialAngle(const Entry& e, int i, fe::Element& el);
  void ReadPbar(const Entry& e, fe::BeamSection& s);
  void ReadBeamLibrary(const Entry& e, fe::BeamSection& s);
  void ReadPbeam(const Entry& e, fe::BeamSection& s);

  // nastran_rods.cc
  void ReadProd(const Entry& e, fe::BeamSection& s);
  void ReadPtube(const Entry& e, fe::BeamSection& s);
  void AddRod(const Entry& e);

  // nastran_elements.cc
  fe::Element NewElement(const Entry& e, fe::ElementType type);
  void ReadNodes(const Entry& e, fe::Element& el, int first, int count);
  void AddShell(const Entry& e);
  void AddShear(const Entry& e);
  int AddPshear(const Entry& e, int pid);
  void AddSolid(const Entry& e);
  void AddBeam(const Entry& e);
  fe::Vec3 Offset(const Entry& e, char how, const fe::Vec3& w, int node, const fe::Vec3& xa, const fe::Vec3& xb,
                  const fe::Vec3& v, int field);
  void AddConm2(const Entry& e);
  void AddConm1(const Entry& e);

  // nastran_springs.cc
  void AddPelas(const Entry& e);
  void AddCelas(const Entry& e);

  // nastran_masses.cc
  void AddPmass(const Entry& e);
  void AddCmass(const Entry& e);

  // nastran_bush.cc
  void AddPbush(const Entry& e, int pid);
  void AddCbush(const Entry& e);

  // nastran_constraints.cc
  void AddRbe2(const Entry& e);

  // nastran_rigid_elements.cc
  void AddRbar(const Entry& e);
  void AddRbe3(const Entry& e);
  void AddToSet(const std::string& name, int node);
  void AddSpc(const Entry& e);
  /// MPC: one linear constraint row (all SIDs merged); components in the grids' CD systems.
  void AddMpc(const Entry& e);
  void AddBoundarySet(const Entry& e);
  void AddSet1(const Entry& e);
};

}  // namespace flexmb::io::nastran
