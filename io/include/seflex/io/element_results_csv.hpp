#pragma once
// Element results (fem/element_results.hpp) as a CSV table, one line per element, component and case:
//   subcase,element,card,component,value
// with the element's linear components in their order (Nastran's conventions, element_results.hpp) and,
// after them, the derived von Mises stresses: shells vm_z1 and vm_z2, solids von_mises.
#include <Eigen/Core>
#include <filesystem>
#include <vector>

#include "seflex/fem/element_results.hpp"

namespace seflex::io {

/// results: map.rows x cases (column k the results of case k, named cases[k]). Throws InputError
/// (naming the file) if it exists and !overwrite, or cannot be written.
void write_element_results_csv(const std::filesystem::path& path, const fem::ElementResultMap& map,
                               const std::vector<int>& cases, const Eigen::Ref<const Eigen::MatrixXd>& results,
                               bool overwrite = false);

}  // namespace seflex::io
