// Interface displacements of a body as a Nastran static subcase (interface_subcase.hpp).
#include "seflex/io/interface_subcase.hpp"

#include <cstdio>
#include <fstream>

#include "seflex/common/error.hpp"

namespace seflex::io {

void write_interface_subcase(const std::filesystem::path& path, const se::Superelement& body,
                             const Eigen::Ref<const Eigen::VectorXd>& xi, int sid, const std::string& what,
                             const Eigen::VectorXd* inertia_loads) {
  SEFLEX_DEMAND(xi.size() == body.size(), "write_interface_subcase: one elastic coordinate per reduced dof");
  SEFLEX_DEMAND(!inertia_loads || inertia_loads->size() == 6 * static_cast<Eigen::Index>(body.fe_node_ids.size()),
                "write_interface_subcase: six inertia loads per FE node");
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out) throw InputError(SourceRef{path.string(), 0}, "cannot be opened for writing");
  out << "$ seflex: " << what << "\n"
      << "$ interface displacements of the body's elastic deformation (superelement coordinates q_b), as\n"
      << "$ enforced displacements. Add to the body's deck with the case control\n"
      << "$   SUBCASE " << sid << "\n$     SPC = " << sid << "\n$     LOAD = " << sid << "\n";
  char line[96];
  std::snprintf(line, sizeof line, "SPC1    %-8d123456  ", sid);
  std::string spc1 = line;
  int on_line = 0;
  for (std::size_t j = 0; j < body.interfaces.size(); ++j) {
    if (on_line == 6 || (on_line > 6 && (on_line - 6) % 8 == 0)) spc1 += "\n        ";
    std::snprintf(line, sizeof line, "%-8d", body.interfaces[j].id);
    spc1 += line;
    ++on_line;
  }
  out << spc1 << "\n";
  for (std::size_t j = 0; j < body.interfaces.size(); ++j) {
    const se::InterfaceNode& n = body.interfaces[j];
    const Eigen::Index o = 6 * static_cast<Eigen::Index>(j);
    // q_b in body axes; the grid's components are along its nodal triad R_BN (columns in B).
    const Eigen::Vector3d u = n.R_BN.transpose() * xi.segment<3>(o), r = n.R_BN.transpose() * xi.segment<3>(o + 3);
    for (int c = 0; c < 6; ++c) {
      std::snprintf(line, sizeof line, "SPCD*   %-16d%-16d%-16d%16.9E\n", sid, n.id, c + 1, c < 3 ? u[c] : r[c - 3]);
      out << line;
    }
  }
  if (inertia_loads) {
    out << "$ inertia loads of the instant: -M a (a: each grid's acceleration in the body frame from the frame's\n"
        << "$ motion and the elastic accelerations, gravity subtracted), basic axes\n";
    for (std::size_t i = 0; i < body.fe_node_ids.size(); ++i) {
      const int id = body.fe_node_ids[i];
      bool interface = false;
      for (const se::InterfaceNode& n : body.interfaces) interface = interface || n.id == id;
      if (interface) continue;
      for (int h = 0; h < 2; ++h) {
        const Eigen::Vector3d f = inertia_loads->segment<3>(6 * static_cast<Eigen::Index>(i) + 3 * h);
        if (f.squaredNorm() == 0.0) continue;
        std::snprintf(line, sizeof line, "%-8s%-16d%-16d%-16d%16.9E\n", h == 0 ? "FORCE*" : "MOMENT*", sid, id, 0, 1.0);
        out << line;
        std::snprintf(line, sizeof line, "*       %16.9E%16.9E%16.9E\n", f.x(), f.y(), f.z());
        out << line;
      }
    }
  }
  out.flush();
  if (!out) throw InputError(SourceRef{path.string(), 0}, "cannot be written (disk full?)");
}

}  // namespace seflex::io
