#pragma once
// Part of fem::finalize: elements whose property or material seflex does not model are left out of
// the model and listed, so that `seflex info` reads the deck and every solution refuses it.
#include "seflex/fem/model.hpp"

namespace seflex::fem::detail {

/// Leave out, and list in model.unsupported under a name ending in "(left out)", which
/// solutions::check_card_usage refuses in every solution (role Structure):
///   - a PBAR/PBARL/PBEAM/PBEAML/PROD/PSOLID (or CONROD) whose MID is not a MAT1 but a MAT2, a MAT8 or
///     a material card seflex lists as unsupported (MAT4, MAT10, MATHP ...) with no MAT1 of that id;
///   - a PSHELL or PCOMP/PCOMPG with a MID of an unsupported material card (and no MAT1/MAT2/MAT8 of that id);
///   - every CBAR/CBEAM, CROD, CQUAD4/CTRIA3, CHEXA/CPENTA/CTETRA/CPYRAM on such a property, or on a property
///     card seflex lists as unsupported (PCOMPS, PBCOMP, PSOLID FCTN = PFLUID ...) with no supported
///     property of that id.
/// References to ids that no card defines are left alone: finalize reports them as errors.
void leave_out_unsupported(Model& model);

}  // namespace seflex::fem::detail
