// The FE element traits table (fe/element_traits.h): rows in id order with
// their kernels, node orders that are permutations, Abaqus faces on the
// element's nodes, distinct file codes and names, and the mesh functions
// (NodeCount, DofsPerNode, TypeName) read from it.

#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <string>
#include <vector>

#include "flexmb/common/error.h"
#include "flexmb/fe/element_traits.h"
#include "flexmb/fe/elements/beam3.h"
#include "flexmb/fe/elements/shear4.h"
#include "flexmb/fe/elements/solid_hex8.h"
#include "flexmb/fe/mesh.h"

namespace flexmb::fe {
namespace element_traits_test {

void ExpectPermutation(std::span<const int> order, int n, const std::string& what) {
  if (order.empty()) return;
  ASSERT_EQ(static_cast<int>(order.size()), n) << what;
  std::vector<int> sorted(order.begin(), order.end());
  std::sort(sorted.begin(), sorted.end());
  for (int k = 0; k < n; ++k) EXPECT_EQ(sorted[k], k) << what;
}

TEST(ElementTraits, RowsAreComplete) {
  std::set<std::string> names;
  std::set<int> body_codes, gmsh_codes, vtk_codes;
  std::set<std::string> abaqus;
  int k = 0;
  for (const ElementTraits& t : AllElementTraits()) {
    const std::string what = t.name;
    EXPECT_EQ(static_cast<int>(t.type), k++) << what;
    EXPECT_EQ(&Traits(t.type), &t);
    EXPECT_TRUE(names.insert(t.name).second) << what;
    EXPECT_TRUE(t.nodes > 0 && t.corners > 0 && t.corners <= t.nodes) << what;
    EXPECT_EQ(t.DofsPerNode(), t.family == ElementFamily::kSolid ? 3 : 6) << what;
    EXPECT_EQ(NodeCount(t.type), t.nodes);
    EXPECT_EQ(DofsPerNode(t.type), t.DofsPerNode());
    EXPECT_STREQ(TypeName(t.type), t.description);
    EXPECT_TRUE(t.matrices && t.stress && t.geometric_stiffness) << what;
    // a row without a Nastran card is another integration of an earlier
    // row's shape (hex20r of hex20): Abaqus names it, VTK writes it as that
    // row (and reads it back as that row), gmsh has no code for it. A row
    // with its own cards may also share an earlier row's shape (rod2 on
    // beam2's line), with the same VTK and gmsh rules. The 3-node beam is
    // its own shape without a Nastran card (CBEAM3 needs PBEAM3, not read)
    const ElementTraits* shape_row = nullptr;
    for (const ElementTraits& u : AllElementTraits()) {
      if (&u == &t) break;
      if (u.vtk_code == t.vtk_code && u.nodes == t.nodes && u.family == t.family) shape_row = &u;
    }
    const bool variant = shape_row != nullptr;
    if (t.nastran_cards.empty() && t.type != kBeam3) EXPECT_TRUE(variant) << what;
    if (variant) {
      EXPECT_EQ(t.gmsh_code, 0) << what;
    } else if (t.family == ElementFamily::kSolid) {
      EXPECT_GE(t.nastran_card_grids, t.nodes) << what;
    }
    // every row has an Abaqus name but the shear panel (Abaqus has none;
    // its writer refuses one) and Abaqus's C3D8 (the reader picks it for
    // C3D8 by the deck's Abaqus/CAE line, the writer writes that line)
    if (t.type != kShear4 && t.type != kHex8Selective) ASSERT_FALSE(t.abaqus.empty()) << what;
    for (const AbaqusName& a : t.abaqus) EXPECT_TRUE(abaqus.insert(a.name).second) << a.name;
    for (const AbaqusFace& f : t.abaqus_faces)
      for (int i = 0; i < f.count; ++i) EXPECT_TRUE(f.nodes[i] >= 1 && f.nodes[i] <= t.nodes) << what << f.label;
    ExpectPermutation(t.nastran_order, t.nodes, what + " nastran");
    ExpectPermutation(t.gmsh_order, t.nodes, what + " gmsh");
    ExpectPermutation(t.vtk_order, t.nodes, what + " vtk");
    EXPECT_TRUE(body_codes.insert(t.body_file_code).second) << what;
    EXPECT_GE(t.body_file_code, 0) << what;
    if (!variant) {
      EXPECT_TRUE(gmsh_codes.insert(t.gmsh_code).second) << what;
      EXPECT_TRUE(vtk_codes.insert(t.vtk_code).second) << what;
    }
  }
  // the first rows are the named enumerators, in their order
  EXPECT_EQ(Traits(ElementType::kHex8).nodes, 8);
  EXPECT_STREQ(Traits(ElementType::kTet10).abaqus.front().name, "C3D10");
  EXPECT_THROW(Traits(static_cast<ElementType>(static_cast<int>(AllElementTraits().size()))), InputError);
  EXPECT_EQ(NodeCount(static_cast<ElementType>(1000)), 0);
}

}  // namespace element_traits_test
}  // namespace flexmb::fe
