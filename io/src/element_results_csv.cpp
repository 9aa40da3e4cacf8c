// Element results to CSV (element_results_csv.hpp).
#include "seflex/io/element_results_csv.hpp"

#include <charconv>
#include <fstream>

#include "seflex/common/error.hpp"
#include "seflex/io/results_csv.hpp"

namespace seflex::io {

void write_element_results_csv(const std::filesystem::path& path, const fem::ElementResultMap& map,
                               const std::vector<int>& cases, const Eigen::Ref<const Eigen::MatrixXd>& results,
                               bool overwrite) {
  SEFLEX_DEMAND(results.rows() == map.rows && results.cols() == static_cast<Eigen::Index>(cases.size()),
                "write_element_results_csv: one column per case, one row per result");
  check_writable(path, overwrite);
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out) throw InputError(SourceRef{path.string(), 0}, "cannot be opened for writing");
  out << "subcase,element,card,component,value\n";
  char buf[64];
  const auto line = [&](int subcase, const fem::ElementResultMap::Entry& e, const std::string& name, double v) {
    const auto r = std::to_chars(buf, buf + sizeof buf, v);
    out << subcase << ',' << e.id << ',' << e.card << ',' << name << ',';
    out.write(buf, r.ptr - buf);
    out << '\n';
  };
  for (std::size_t k = 0; k < cases.size(); ++k)
    for (const auto& e : map.entries) {
      const double* c = results.col(static_cast<Eigen::Index>(k)).data() + e.row;
      const auto& names = fem::element_result_components(e.kind);
      for (std::size_t i = 0; i < names.size(); ++i) line(cases[k], e, names[i], c[i]);
      if (e.kind == fem::ResultKind::Shell) {
        line(cases[k], e, "vm_z1", fem::plane_von_mises(c[8], c[9], c[10]));
        line(cases[k], e, "vm_z2", fem::plane_von_mises(c[11], c[12], c[13]));
      } else if (e.kind == fem::ResultKind::Solid) {
        line(cases[k], e, "von_mises", fem::element_result_peak(e.kind, c).value);
      }
    }
  out.flush();
  if (!out) throw InputError(SourceRef{path.string(), 0}, "cannot be written (disk full?)");
}

}  // namespace seflex::io
