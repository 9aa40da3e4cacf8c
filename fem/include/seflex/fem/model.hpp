#pragma once
// The FE model as data: what a Nastran bulk-data deck (or a gmsh mesh with its property file)
// describes, card by card, with the source location of every card for error messages.
// Readers in io/ fill it; fem/ resolves and consumes it. No parsing and no numerics here.
//
// Conventions
// - Ids are the user's (Nastran) ids. After fem::finalize(model) the maps `*_index` give the
//   position of an id in its vector, coordinate systems are resolved to the basic system, and every
//   GRID has its basic position.
// - Units are whatever the deck uses (seflex does not rescale); PARAM WTMASS multiplies every mass
//   when matrices are built. Angles on cards (e.g. CQUAD4 THETA) are in degrees as Nastran writes
//   them; fem converts to radians.
// - Component lists ("123456", "12 456") are stored as bit masks: bit (c-1) set for component c.
#include <cstddef>
#include <map>
#include <string>
#include <unordered_map>
#include <vector>

#include "seflex/fem/card_ref.hpp"
#include "seflex/fem/model_case_control.hpp"
#include "seflex/fem/model_constraints.hpp"
#include "seflex/fem/model_elements.hpp"
#include "seflex/fem/model_geometry.hpp"
#include "seflex/fem/model_loads.hpp"
#include "seflex/fem/model_parts.hpp"
#include "seflex/fem/model_properties.hpp"
#include "seflex/fem/model_solids.hpp"

namespace seflex::fem {

/// Cards the reader recognised but seflex does not model, or did not recognise at all. `members`
/// holds field 2 (the SID of a load, a method or a set; an element's id) of each card whose field 2
/// is an integer, so that the cards of a selected set can be told from those of unselected sets.
struct UnsupportedCard {
  struct Member {
    int sid = 0;
    CardRef ref;
  };
  std::string name;
  std::size_t count = 0;
  CardRef first;
  std::vector<Member> members;
};

/// Adds notes to a list of unsupported cards (Model::unsupported): one entry per name, in the order
/// of the first note, counted, keeping the card reference of the first note. A name -> position index
/// makes each note O(1). The index holds the entries the list had when the UnsupportedNotes was made
/// plus those it added: code that adds or erases entries otherwise makes a new one afterwards.
class UnsupportedNotes {
 public:
  explicit UnsupportedNotes(std::vector<UnsupportedCard>& list);
  /// `count` more of `name`; a new entry (at the end) keeps `first`. The entry is valid until the next note.
  UnsupportedCard& add(const std::string& name, const CardRef& first, std::size_t count = 1);
  /// The entry of `name`, or nullptr.
  UnsupportedCard* find(const std::string& name);

 private:
  std::vector<UnsupportedCard>* list_;
  std::unordered_map<std::string, std::size_t> index_;
};

// ---------------------------------------------------------------------------------------------
struct Model {
  std::vector<std::string> files;   ///< files[CardRef::file]; files[0] is the main deck

  CaseControl case_control;

  std::vector<CoordSys> coords;
  std::vector<Grid> grids;
  std::vector<ScalarPoint> spoints;
  GridDefaults grdset;

  std::vector<Mat1> mat1;
  std::vector<Mat2> mat2;
  std::vector<Mat8> mat8;
  std::vector<Mat9> mat9;                      ///< anisotropic solid material (model_solids.hpp)
  std::vector<BarProperty> bar_props;
  std::vector<RodProperty> rod_props;
  std::vector<ShellProperty> shell_props;
  std::vector<CompositeProperty> composite_props;  ///< PCOMP, PCOMPG
  std::vector<SpringProperty> spring_props;
  std::vector<BushProperty> bush_props;        ///< PBUSH
  std::vector<MassProperty> mass_props;        ///< PMASS
  std::vector<ShearProperty> shear_props;      ///< PSHEAR
  std::vector<BendProperty> bend_props;        ///< PBEND
  std::vector<MaterialTable> material_tables;  ///< TABLEM1-4 (no solution uses them)

  BarDefaults baror, beamor;
  std::vector<Bar> bars;
  std::vector<Rod> rods;
  std::vector<Shell> shells;
  std::vector<Conm2> conm2;
  std::vector<Spring> springs;
  std::vector<Bush> bushes;                    ///< CBUSH
  std::vector<ScalarMass> scalar_masses;       ///< CMASS1-4
  std::vector<Conm1> conm1;
  std::vector<Genel> genels;                ///< GENEL
  std::vector<ShearPanel> shear_panels;     ///< CSHEAR
  std::vector<Bend> bends;                  ///< CBEND
  std::vector<QuadraticShell> shells8;      ///< CTRIA6, CQUAD8
  std::vector<SolidProperty> solid_props;   ///< PSOLID
  std::vector<Solid> solids;                ///< CHEXA, CPENTA, CTETRA, CPYRAM
  std::vector<Rbe2> rbe2;
  std::vector<Rbar> rbars;
  std::vector<RigidBody> rigid_bodies;      ///< RBE1, CRIGD1, CRIGD2, CRIGD3
  std::vector<RigidRod> rigid_rods;         ///< RROD, CRIGDR
  std::vector<Rbe3> rbe3;

  std::vector<SpcEntry> spcs;
  std::vector<SpcAdd> spcadds;
  std::vector<MpcEquation> mpcs;
  std::vector<MpcAdd> mpcadds;
  std::vector<DofSetEntry> aset, omit, bset, suport;
  std::vector<Suport1Entry> suport1;  ///< SUPORT1 (selected by case control SUPORT1 = SID)
  std::vector<PointLoad> point_loads;
  std::vector<PressureLoad> pressure_loads;
  std::vector<ScalarLoad> scalar_loads;            ///< SLOAD
  std::vector<GridPressureLoad> grid_pressure_loads;  ///< PLOAD
  std::vector<BarLineLoad> bar_line_loads;         ///< PLOAD1
  std::vector<EnforcedMotion> enforced_motions;    ///< SPCD
  std::vector<FaceLoad> face_loads;         ///< PLOAD4
  std::vector<GravityLoad> gravity_loads;
  std::vector<RotationalLoad> rotational_loads;
  std::vector<LoadCombination> load_combinations;
  std::vector<GridTemperature> grid_temperatures;
  std::vector<DefaultTemperature> default_temperatures;
  std::vector<BarTemperature> bar_temperatures;
  std::vector<EigenMethod> eigen_methods;
  std::vector<Dmig> dmigs;
  std::vector<Param> params;

  // Part superelements (BEGIN SUPER = n): the residual's cards that place and connect them, and what
  // fem::assemble_parts (parts.hpp) made of each part merged into this model.
  std::vector<GeometricPoint> points;          ///< POINT
  std::vector<PartLocation> part_locations;    ///< SELOC
  std::vector<PartBulk> part_bulks;            ///< SEBULK
  std::vector<PartConnection> part_connections;  ///< SECONCT
  std::vector<MirrorPlane> mirror_planes;      ///< SEMPLN
  std::vector<ExternalBoundary> external_points;  ///< EXTRN (in an external part's bulk data)
  std::vector<ExternalMatrices> external_parts;   ///< SEBULK EXTOP4 matrices (io reads them; dmig.hpp adds them)
  std::vector<PartSummary> parts;              ///< filled by assemble_parts

  std::vector<UnsupportedCard> unsupported;  ///< in order of first appearance (UnsupportedNotes adds to it)
  /// What the reader chose where a deck could be read two ways, one sentence each starting with
  /// file:line (an INCLUDE found relative to both the main deck's and the including file's folder,
  /// two different files: which one was read). Every command prints them as warnings.
  std::vector<std::string> read_warnings;
  /// Number of cards of each name the reader accepted (e.g. "GRID" -> 18), for reports.
  std::map<std::string, std::size_t> card_counts;

  /// Named node sets (from gmsh physical groups of points, or user definitions): name -> grid ids.
  std::map<std::string, std::vector<int>> node_sets;

  // Lookups, built by fem::finalize (id -> position in the vector above).
  std::unordered_map<int, std::uint32_t> grid_index, coord_index, mat1_index, mat2_index, mat8_index, mat9_index,
      bar_prop_index, rod_prop_index, shell_prop_index, composite_prop_index, spring_prop_index, spoint_index,
      bush_prop_index, mass_prop_index, solid_prop_index, shear_prop_index, bend_prop_index;
  bool finalized = false;
};

/// Whether the model has rigid elements (RBE2, RBAR, RBE1, CRIGD1-3, RROD, CRIGDR) or RBE3s: dependent
/// dofs eliminated from the whole K (constraints.hpp).
inline bool has_rigid_elements(const Model& m) {
  return !m.rbe2.empty() || !m.rbars.empty() || !m.rbe3.empty() || !m.rigid_bodies.empty() || !m.rigid_rods.empty();
}

}  // namespace seflex::fem
