#pragma once
/// \file vtk_animation.h
/// Animation output for ParaView: one XML VTK unstructured grid (.vtu) per
/// frame in DIR/frames/, and a collection file DIR/anim.pvd listing the
/// frames with their times. After every frame the new entry and the closing
/// tags are written over the previous closing tags and flushed, so the .pvd
/// is complete XML between frames and an interrupted run leaves a loadable
/// animation (constant cost per frame, however long the run).
///
/// Each body with a display shape (Body::shape) becomes cells: a box one
/// hexahedron, a cylinder a fan of wedges, a sphere a triangulated surface.
/// Bodies without a shape (Shape::Type::kNone) are skipped. Every cell
/// carries the index of its body in Model::bodies as cell data "body_id".
///
/// Each floating-frame flexible body (bodies/flexible_body.h) also becomes
/// its deformed FE mesh: every node at r + R (rho_k + s H_k^t w) in world,
/// s = OutputSettings::deformation_scale; shells as quads and triangles,
/// beams as lines, solids as tetrahedra (4 and 10 nodes) and hexahedra.
///
/// Each body with a centre line (Body::CentreLinePoints: ANCF beams, cables
/// and hoisting ropes) becomes one polyline cell (VTK type 4) through its
/// points.
///
/// Encoding (VtkEncoding): binary by default, every DataArray
/// format="binary": base64 of one stream holding a UInt64 byte count
/// (header_type="UInt64" in <VTKFile>, version 1.0) followed by the raw
/// values in the machine's byte order (byte_order attribute); the values
/// are bit-exact. ASCII writes the numbers as text (points, displacement
/// with 10 significant digits, von Mises with 8).
/// Point data "displacement": the elastic displacement H_k^t w of each node
/// relative to the floating frame, body axes, unscaled [m] (0 on shape
/// vertices). Cell data "von_mises": the largest von Mises stress over the
/// element's recovery points from the stress modes [Pa] (shells: bottom and
/// top surface; solids: centroid); 0 for beams (the section's shape is not
/// stored), elements without stress modes and shape cells.

#include <cstdint>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "flexmb/bodies/body.h"
#include "flexmb/kinematics/marker.h"

namespace flexmb {

class Model;
struct State;
class FlexibleBody;
namespace fe {
struct Mesh;
}

/// Vertices and cells of one body's shape in the user's body frame.
struct ShapeMesh {
  int body = 0;                    ///< index in Model::bodies
  std::vector<Vec3> points_B;      ///< vertices in the user's body frame [m]
  std::vector<int> connectivity;   ///< vertex indices of all cells (local to this mesh)
  std::vector<int> cell_sizes;     ///< vertices per cell
  std::vector<unsigned char> cell_types;  ///< VTK cell types (5 triangle, 12 hexahedron, 13 wedge)
};

/// Builds the mesh of a body's shape (empty for kNone). Cylinders use
/// `segments` wedges; spheres `segments` slices and segments/2 stacks.
/// Throws InputError naming the body if a size is not positive.
ShapeMesh MakeShapeMesh(const Model& model, int body, int segments = 24);

/// The mesh of `shape` (in the user's body frame of body `body`) as
/// MakeShapeMesh builds it for a body's own shape: a further shape of a
/// body, added with VtkAnimationWriter::AddShapeMesh. Throws InputError
/// naming `what` if a size is not positive.
ShapeMesh MakeShapeMesh(const Shape& shape, int body, const std::string& what, int segments = 24);

/// The elements of an FE mesh as the cells of a shape of body `body` (cell
/// types as for flexible bodies' meshes), vertices at the nodes' positions
/// in the mesh's basic frame taken as the user's body frame: the undeformed
/// mesh moving with the body, e.g. a rigid body standing for an FE part.
ShapeMesh MakeMeshShape(int body, const fe::Mesh& mesh);

/// How the frames' DataArrays are stored.
enum class VtkEncoding {
  kBinary,  ///< format="binary": base64 of a UInt64 byte count and the raw values (bit-exact)
  kAscii,   ///< format="ascii": numbers as text
};

/// The arrays of the last frame written, as they are stored in the .vtu
/// (the writer's own copy, e.g. to check a file read back).
struct VtkFrameArrays {
  std::vector<double> points;            ///< x y z per point, world [m]
  std::vector<std::int32_t> connectivity;  ///< global point indices of all cells
  std::vector<std::int32_t> offsets;       ///< end of each cell in connectivity
  std::vector<std::uint8_t> types;         ///< VTK cell type per cell
  std::vector<double> displacement;      ///< point data: elastic displacement, body axes [m]
  std::vector<std::int32_t> body_id;       ///< cell data: index in Model::bodies
  std::vector<double> von_mises;         ///< cell data: von Mises stress [Pa]
};

/// Writer of the frames and the .pvd collection of one run.
class VtkAnimationWriter {
 public:
  /// Creates DIR/frames/ and the shape meshes. Throws InputError if the
  /// directory cannot be created. `model` must outlive the writer.
  VtkAnimationWriter(const std::string& dir, const Model& model, VtkEncoding encoding = VtkEncoding::kBinary);
  ~VtkAnimationWriter();
  VtkAnimationWriter(const VtkAnimationWriter&) = delete;
  VtkAnimationWriter& operator=(const VtkAnimationWriter&) = delete;

  /// Adds a mesh fixed to body mesh.body (vertices in its user's body
  /// frame), drawn like a shape (body_id, zero displacement and stress),
  /// e.g. MakeMeshShape of a rigid part or road markings on the ground.
  /// Before the first frame only; throws InputError otherwise, or for a body
  /// index, vertex index or cell size out of range.
  void AddShapeMesh(ShapeMesh mesh);

  /// Writes frame number frames() at time state.t [s] with the body poses of
  /// `state`, then appends it to anim.pvd.
  void WriteFrame(const State& state);

  /// Adds a straight link drawn as a line cell between the origins of
  /// markers marker_i and marker_j (indices in Model::markers), e.g. a
  /// distance joint's rod; cell data body_id is the body of marker_i. Before
  /// the first frame only; throws InputError otherwise or for an index out
  /// of range.
  void AddLink(int marker_i, int marker_j);

  /// Number of frames written.
  int frames() const { return static_cast<int>(times_.size()); }
  /// Path of the .pvd file.
  const std::string& pvd_path() const { return pvd_; }
  /// Path of frame i.
  std::string FramePath(int i) const;
  /// The encoding of the frames.
  VtkEncoding encoding() const { return encoding_; }
  /// The arrays of the last frame written (empty before the first).
  const VtkFrameArrays& last_frame() const { return arrays_; }

 private:
  // the FE mesh of one flexible body with its per-frame scratch
  struct FlexMesh {
    int body = 0;
    const FlexibleBody* flexible = nullptr;
    std::vector<int> connectivity;          // node indices (local to this mesh)
    std::vector<int> cell_sizes;
    std::vector<unsigned char> cell_types;
    std::vector<int> cell_of_element;       // mesh element -> cell
    VecX u;                                 // scratch: modes * w, 6 per node
    VecX stress[2];                         // scratch: shell, solid table values
    VecX element_von_mises[2];              // scratch: per element of the shell, solid table
    std::vector<double> von_mises;          // scratch: per cell
  };
  void AppendToPvd(double t);
  void UpdateFlexMesh(FlexMesh& m, const double* w);
  void FillArrays(const State& state);
  template <class T>
  void WriteArray(std::FILE* f, const char* type, const char* name, int components, const std::vector<T>& values,
                  const char* ascii_format);

  const Model& model_;
  std::string dir_, pvd_;
  std::vector<ShapeMesh> meshes_;
  std::vector<FlexMesh> flex_;
  std::vector<std::pair<int, int>> links_;  ///< marker pairs drawn as lines
  std::vector<int> lines_;                  ///< bodies drawn by their centre lines
  VtkEncoding encoding_;
  VtkFrameArrays arrays_;                   ///< scratch: the arrays of the frame
  std::string text_;                        ///< scratch: base64 or ASCII text of one array
  MarkerState marker_state_;                ///< scratch: a link's marker
  std::vector<double> times_;
  std::FILE* pvd_file_ = nullptr;
  long pvd_tail_ = 0;  ///< file position of the closing tags in anim.pvd
  int n_points_ = 0, n_cells_ = 0, n_conn_ = 0;
};

}  // namespace flexmb
