// The animation a user opens in ParaView: a series written by io::PvdSeries is loaded by ParaView's
// own Python (pvbatch, Debian's paraview + python3-paraview, through scripts/pvrender.sh), which
// reports the point/cell/step counts it read and renders the last step to a PNG.
#include <gtest/gtest.h>

#include "seflex/common/so3.hpp"
#include "seflex/io/vtk_animation.hpp"
#include "test_support.hpp"

using namespace seflex;

TEST(ParaView, OpensSeriesAndRendersAFrame) {
  test::TempDir tmp;
  se::Superelement body;
  body.name = "plate";
  body.interfaces.resize(1);
  body.K = body.M = Eigen::MatrixXd::Identity(6, 6);
  body.Phi_f = Eigen::MatrixXd::Zero(6, 6);
  // a 2 x 2 quad patch (9 nodes, 4 quads)
  body.p_BoI_B.resize(3, 9);
  for (int i = 0; i < 9; ++i) {
    body.fe_node_ids.push_back(i + 1);
    body.p_BoI_B.col(i) = Eigen::Vector3d(0.5 * (i % 3), 0.5 * (i / 3), 0.0);
  }
  body.recovery = Eigen::MatrixXd::Zero(54, 6);
  for (int i = 0; i < 9; ++i) body.recovery(6 * i + 2, 2) = 0.5 * (i % 3);  // bending-like z displacement
  for (int r = 0; r < 2; ++r)
    for (int c = 0; c < 2; ++c)
      body.cells.push_back({se::MeshCell::Type::Quad, {3 * r + c, 3 * r + c + 1, 3 * r + c + 4, 3 * r + c + 3}, 10 * r + c});
  io::PvdSeries series(tmp.path(), "plate", {&body});
  for (int k = 0; k < 4; ++k) {
    io::BodySnapshot s;
    s.R_WB = so3::exp(Eigen::Vector3d(0, 0, 0.3 * k));
    s.q = Eigen::VectorXd::Zero(6);
    s.q[2] = 0.1 * k;
    series.write_step(0.25 * k, {s});
  }
  const auto png = tmp / "frame.png";
  const std::string cmd = "'" + (test::source_dir() / "scripts" / "pvrender.sh").string() + "' '" +
                          series.pvd_path().string() + "' '" + png.string() + "' > '" + (tmp / "log.txt").string() +
                          "' 2>&1";
  const int rc = std::system(cmd.c_str());
  const std::string log = test::read_file(tmp / "log.txt");
  ASSERT_EQ(rc, 0) << log;
  EXPECT_NE(log.find("points=9 cells=4 steps=4 time=0.75"), std::string::npos) << log;
  const std::string bytes = test::read_file(png);
  ASSERT_GT(bytes.size(), 2000u);
  EXPECT_EQ(bytes.substr(1, 3), "PNG");
}
