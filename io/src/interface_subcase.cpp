// Interface displacements of a body as a Nastran static subcase (interface_subcase.hpp).
#include "seflex/io/interface_subcase.hpp"

#include <cstdio>
#include <fstream>

#include "seflex/common/error.hpp"

namespace seflex::io {

void write_interface_subcase(const std::filesystem::path& path, const se::Superelement& body,
                             const Eigen::Ref<const Eigen::VectorXd>& xi, int sid, const std::string& what) {
  SEFLEX_DEMAND(xi.size() == body.size(), "write_interface_subcase: one elastic coordinate per reduced dof");
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
  out.flush();
  if (!out) throw InputError(SourceRef{path.string(), 0}, "cannot be written (disk full?)");
}

}  // namespace seflex::io
