// VTK animation writer: deformed coordinates = p_WBo + R_WB (X + U) with U = recovery q, the elastic
// displacement point data in world axes, and a .pvd collection complete after every step. The files
// are read back with VTK's own XML reader.
#include <gtest/gtest.h>

#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

#include "seflex/common/error.hpp"
#include "seflex/common/so3.hpp"
#include "seflex/io/vtk_animation.hpp"
#include "test_support.hpp"

using namespace seflex;

namespace {
// One interface node (6 dofs), four FE nodes: a unit square quad plus a line to a fifth node.
se::Superelement square_body() {
  se::Superelement s;
  s.name = "square";
  s.interfaces.resize(1);
  s.K = Eigen::MatrixXd::Identity(6, 6);
  s.M = Eigen::MatrixXd::Identity(6, 6);
  s.Phi_f = Eigen::MatrixXd::Zero(6, 6);
  s.fe_node_ids = {1, 2, 3, 4, 5};
  s.p_BoI_B.resize(3, 5);
  s.p_BoI_B << 0, 1, 1, 0, 2, 0, 0, 1, 1, 0, 0, 0, 0, 0, 0;
  // recovery: every node translates with the interface node's u, node 5 twice as much
  s.recovery = Eigen::MatrixXd::Zero(30, 6);
  for (int i = 0; i < 5; ++i) s.recovery.block<3, 3>(6 * i, 0) = (i == 4 ? 2.0 : 1.0) * Eigen::Matrix3d::Identity();
  s.cells.push_back({se::MeshCell::Type::Quad, {0, 1, 2, 3}, 11});
  s.cells.push_back({se::MeshCell::Type::Line, {1, 4, -1, -1}, 12});
  return s;
}
}  // namespace

TEST(VtkAnimation, DeformedCoordinatesAndPointDataReadBack) {
  test::TempDir tmp;
  const auto body = square_body();
  io::PvdSeries series(tmp.path(), "anim", {&body});
  std::vector<io::BodySnapshot> snaps(1);
  for (int step = 0; step < 3; ++step) {
    snaps[0].R_WB = so3::exp(Eigen::Vector3d(0, 0, 0.5 * step));
    snaps[0].p_WBo = Eigen::Vector3d(step, 0, 0);
    snaps[0].q = Eigen::VectorXd::Zero(6);
    snaps[0].q.head<3>() = Eigen::Vector3d(0, 0, 0.01 * step);
    series.write_step(0.1 * step, snaps);
    // The collection on disk is complete after every step: one entry per step, closed once.
    const std::string now = test::read_file(series.pvd_path());
    std::size_t entries = 0;
    for (auto at = now.find("<DataSet "); at != std::string::npos; at = now.find("<DataSet ", at + 1)) ++entries;
    EXPECT_EQ(entries, static_cast<std::size_t>(step + 1)) << now;
    const std::string closing = "  </Collection>\n</VTKFile>\n";
    ASSERT_GE(now.size(), closing.size());
    EXPECT_EQ(now.substr(now.size() - closing.size()), closing) << now;
    EXPECT_EQ(now.find("</Collection>"), now.rfind("</Collection>")) << now;
  }
  EXPECT_EQ(series.steps_written(), 3);
  const std::string pvd = test::read_file(series.pvd_path());
  EXPECT_NE(pvd.find("timestep=\"0.2\""), std::string::npos) << pvd;
  EXPECT_NE(pvd.find("file=\"anim/anim_000002.vtu\""), std::string::npos) << pvd;

  vtkNew<vtkXMLUnstructuredGridReader> reader;
  reader->SetFileName((tmp / "anim/anim_000002.vtu").string().c_str());
  reader->Update();
  vtkUnstructuredGrid* g = reader->GetOutput();
  ASSERT_EQ(g->GetNumberOfPoints(), 5);
  ASSERT_EQ(g->GetNumberOfCells(), 2);
  const Eigen::Matrix3d R = so3::exp(Eigen::Vector3d(0, 0, 1.0));
  for (int i = 0; i < 5; ++i) {
    const Eigen::Vector3d u_B(0, 0, (i == 4 ? 2.0 : 1.0) * 0.02);
    const Eigen::Vector3d expect = Eigen::Vector3d(2, 0, 0) + R * (body.p_BoI_B.col(i) + u_B);
    double p[3];
    g->GetPoint(i, p);
    EXPECT_LT((Eigen::Vector3d(p[0], p[1], p[2]) - expect).norm(), 1e-14) << "node " << i;
    double e[3];
    g->GetPointData()->GetArray("elastic_displacement")->GetTuple(i, e);
    EXPECT_LT((Eigen::Vector3d(e[0], e[1], e[2]) - R * u_B).norm(), 1e-15);
  }
  EXPECT_EQ(g->GetCellData()->GetArray("element_id")->GetTuple1(1), 12);
  // displacement is measured from the first step's positions
  double d[3];
  g->GetPointData()->GetArray("displacement")->GetTuple(0, d);
  EXPECT_NEAR(d[0], 2.0, 1e-14);
}

TEST(VtkAnimation, RefusesToOverwriteAnExistingSeries) {
  test::TempDir tmp;
  const auto body = square_body();
  {
    io::PvdSeries series(tmp.path(), "anim", {&body});
    series.write_step(0.0, {io::BodySnapshot{}});
  }
  try {
    io::PvdSeries again(tmp.path(), "anim", {&body});
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("anim.pvd: exists already"), std::string::npos) << e.what();
  }
}
