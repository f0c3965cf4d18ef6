#pragma once
/// \file nastran_sections.h
/// Section constants of the Nastran beam library shapes used by PBARL and
/// PBEAML (TYPE = ROD, TUBE, BAR, BOX, I, CHAN, L, T, H). Dimensions DIMi are
/// as in the MSC/NX Quick Reference Guide figures, which draw the element y
/// axis upwards and z across:
///   ROD  r                         TUBE r_out r_in
///   BAR  width(z) height(y)        BOX  width(z) height(y) t_top/bottom t_sides
///   I    height(y) w_bottom w_top t_web t_bottom t_top
///   CHAN width(z, incl. web) height(y) t_web t_flanges
///   L    width(z) height(y) t_horizontal_leg t_vertical_leg (legs along +z, +y)
///   T    flange width(z) height(y) t_flange t_web
///   H    web length between flanges(z) sum of flange thicknesses flange height(y) t_web
/// Nastran's conventions: I1 = int y^2 dA (bending in plane 1, the element
/// x-y plane, about z), I2 = int z^2 dA, I12 = int y z dA, all about the
/// centroid; K1, K2 are the shear area factors of planes 1 and 2.

#include <array>
#include <string>
#include <vector>

namespace flexmb::io::nastran {

/// Section constants in Nastran's naming (see the file comment) [length^2,
/// length^4; K dimensionless].
struct ShapeProperties {
  double A = 0.0;
  double I1 = 0.0, I2 = 0.0, I12 = 0.0;
  double J = 0.0;
  double K1 = 0.0, K2 = 0.0;
  /// Stress recovery points (y, z) from the centroid [length]: the corners
  /// of the section's convex hull (the normal stress, linear in y and z,
  /// is largest at one of them); round shapes: 8 points on the outer
  /// circle at 45 degree steps from +y.
  std::vector<std::array<double, 2>> points;
};

/// Number of dimensions of a beam library TYPE, 0 if the type is not
/// supported here.
int ShapeDimensionCount(const std::string& type);

/// Computes the constants of `type` from its dimensions and the material's
/// Poisson ratio `nu` (used by the solid sections' shear factors). Returns
/// an empty string on success, otherwise what is wrong with the dimensions
/// (non-positive, walls thicker than the section, ...).
std::string ComputeShape(const std::string& type, const std::vector<double>& dims, double nu,
                         ShapeProperties* out);

}  // namespace flexmb::io::nastran
