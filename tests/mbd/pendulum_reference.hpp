#pragma once
// The rigid double pendulum of the multibody tests and its independent reference time history
// (tests/data/mbd/double_pendulum_reference.csv, written by double_pendulum_reference.py: Lagrange's
// equations in absolute angles, scipy DOP853 at rtol = atol = 1e-12; independent of seflex).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "mbd_models.hpp"
#include "test_support.hpp"

namespace seflex::test {

using mbd::HingeOptions;
using mbd::ModelBuilder;
using mbd::Pose;

struct RefRow {
  double t, phi1, phi2, w1, w2, energy;
};

inline std::vector<RefRow> read_reference(const std::string& file) {
  std::ifstream in(data_dir() / "mbd" / file);
  std::vector<RefRow> rows;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::replace(line.begin(), line.end(), ',', ' ');
    std::istringstream is(line);
    RefRow r{};
    is >> r.t >> r.phi1 >> r.phi2 >> r.w1 >> r.w2 >> r.energy;
    rows.push_back(r);
  }
  return rows;
}

inline mbd::Model double_pendulum() {
  ModelBuilder mb;
  const auto se_rod = mb.add_superelement(rod(1.0, 1.0));
  const auto g = mb.add_ground("pivot", Pose{});
  const auto h1 = mb.add_hinge("H1", g, Eigen::Vector3d::UnitZ());
  const auto r1 = mb.add_rigid_body("rod1", se_rod, mb.hinge_child(h1), 0, Pose{Eigen::Matrix3d::Identity(), Eigen::Vector3d(0.5, 0, 0)});
  HingeOptions ho;
  ho.phidot0 = 0.5;
  const auto h2 = mb.add_hinge("H2", mb.rigid_body(r1).nodes[1], Eigen::Vector3d::UnitZ(), ho);
  mb.add_rigid_body("rod2", se_rod, mb.hinge_child(h2), 0, Pose{Eigen::Matrix3d::Identity(), Eigen::Vector3d(1.5, 0, 0)});
  mb.set_gravity(Eigen::Vector3d(0, -9.81, 0));
  return mb.build();
}

/// Largest errors of samples against the reference rows: angles, rates, and total energy relative
/// to the potential-energy scale (m1 + m2) g L = 2 x 9.81 J. Samples must be at the reference times.
struct ReferenceErrors {
  double phi = 0.0, rate = 0.0, energy = 0.0;
};
inline ReferenceErrors reference_errors(const std::vector<mbd::Sample>& samples, const std::vector<RefRow>& ref) {
  ReferenceErrors e;
  EXPECT_EQ(samples.size(), ref.size());
  for (std::size_t k = 0; k < std::min(samples.size(), ref.size()); ++k) {
    const mbd::Sample& smp = samples[k];
    EXPECT_NEAR(smp.t, ref[k].t, 1e-12);
    e.phi = std::max({e.phi, std::abs(smp.hinges[0].phi - ref[k].phi1), std::abs(smp.hinges[1].phi - ref[k].phi2)});
    e.rate = std::max({e.rate, std::abs(smp.hinges[0].phidot - ref[k].w1), std::abs(smp.hinges[1].phidot - ref[k].w2)});
    e.energy = std::max(e.energy, std::abs(smp.energy.total() - ref[k].energy) / (2 * 9.81));
  }
  return e;
}

}  // namespace seflex::test
