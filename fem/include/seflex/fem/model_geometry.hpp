#pragma once
// Part of model.hpp (the FE model as data; conventions there), kept apart to keep headers short:
// coordinate systems (CORD1x/CORD2x), GRID, SPOINT, GRDSET and the component masks.
// Field layouts: MSC Nastran Quick Reference Guide. No parsing and no numerics here.
#include <Eigen/Core>
#include <array>
#include <cstdint>

#include "seflex/fem/card_ref.hpp"

namespace seflex::fem {

using ComponentMask = std::uint8_t;  ///< bit (c-1) for component c = 1..6

// ---------------------------------------------------------------------------------------------
// Coordinate systems
enum class CoordType : std::uint8_t { Rectangular, Cylindrical, Spherical };

/// CORD2R/C/S (defined by points A, B, C in system rid) or CORD1R/C/S (by three grids).
struct CoordSys {
  int id = 0;
  CoordType type = CoordType::Rectangular;
  bool by_grids = false;            ///< CORD1x
  int rid = 0;                      ///< CORD2x reference system
  std::array<double, 9> abc{};      ///< CORD2x: A(3), B(3), C(3) in rid
  std::array<int, 3> grids{};       ///< CORD1x: G1, G2, G3
  CardRef ref;
  // Resolved by fem::finalize: origin and axes (columns) in the basic system.
  bool resolved = false;
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  Eigen::Matrix3d axes = Eigen::Matrix3d::Identity();  ///< columns e1, e2, e3 in basic
};

// ---------------------------------------------------------------------------------------------
// Grids and scalar points
struct Grid {
  int id = 0;
  int cp = 0;                       ///< system of x
  Eigen::Vector3d x = Eigen::Vector3d::Zero();  ///< coordinates in cp (r, theta_deg, z for cylindrical ...)
  int cd = 0;                       ///< displacement (global) system
  ComponentMask ps = 0;             ///< permanent single-point constraints
  CardRef ref;
  Eigen::Vector3d x_basic = Eigen::Vector3d::Zero();  ///< resolved by finalize
};

struct ScalarPoint {  ///< SPOINT: one degree of freedom, used by DMIG matrices
  int id = 0;
  CardRef ref;
};

struct GridDefaults {  ///< GRDSET (blank = 0)
  int cp = 0, cd = 0;
  ComponentMask ps = 0;
  bool present = false;
  CardRef ref;
};

}  // namespace seflex::fem
