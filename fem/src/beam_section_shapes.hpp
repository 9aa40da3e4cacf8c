#pragma once
// Internal: the PBARL/PBEAML sections made of rectangles (T, T1, T2, L, CHAN, CHAN1, CHAN2, Z, I1,
// H, CROSS, HAT, HAT1, BOX1, DBOX), the hexagon (HEXA) and TUBE2 (beam_section.hpp lists the
// conventions). Each takes its DIMs (already checked > 0) and throws InputError (no location) for
// dimensions that do not describe the section.
#include <vector>

#include "seflex/fem/beam_section.hpp"

namespace seflex::fem::detail {

BeamSection tube2_section(const std::vector<double>& d);
BeamSection t_section(const std::vector<double>& d);
BeamSection t1_section(const std::vector<double>& d);
BeamSection t2_section(const std::vector<double>& d);
BeamSection l_section(const std::vector<double>& d);
BeamSection chan_section(const std::vector<double>& d);
BeamSection chan1_section(const std::vector<double>& d);
BeamSection chan2_section(const std::vector<double>& d);
BeamSection z_section(const std::vector<double>& d);
BeamSection i1_section(const std::vector<double>& d);
BeamSection h_section(const std::vector<double>& d);
BeamSection cross_section(const std::vector<double>& d);
BeamSection hat_section(const std::vector<double>& d);
BeamSection hat1_section(const std::vector<double>& d);
BeamSection box1_section(const std::vector<double>& d);
BeamSection dbox_section(const std::vector<double>& d);
BeamSection hexa_section(const std::vector<double>& d);

}  // namespace seflex::fem::detail
