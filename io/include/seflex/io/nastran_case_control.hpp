#pragma once
// Executive and case control sections of a Nastran deck: what seflex keeps of them.
// - Executive control (before CEND): SOL, and ASSIGN INPUTT4 = 'file', UNIT = n (the OP4 files of
//   SEBULK EXTOP4 parts). Everything else is skipped.
// - Case control (CEND to BEGIN BULK): TITLE, SUBTITLE, LABEL, SUBCASE, SPC, LOAD, METHOD, MPC,
//   K2GG, M2GG, PARAM; commands that select analysis input seflex does not use (TEMPERATURE(LOAD),
//   DLOAD, DEFORM, SUPORT1, ...) are kept in Subcase::other so that a solution needing them can
//   refuse the deck; other commands (output requests, SET, ...) are skipped. Commands may be
//   abbreviated to their first four letters, as Nastran allows. A line ending with a comma continues
//   on the next one. Subcases inherit the global selections they do not set.
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "seflex/fem/model.hpp"
#include "seflex/io/nastran_lines.hpp"

namespace seflex::io::nastran {

/// ASSIGN INPUTT4 = 'path', UNIT = n [, FORM = ...]: an OP4 file on a Fortran unit.
struct AssignedUnit {
  int unit = 0;
  std::string path;      ///< as written (quotes removed)
  std::string where;     ///< file:line of the ASSIGN
};

class CaseControlReader {
 public:
  explicit CaseControlReader(fem::Model& model) : model_(model) {}
  /// One executive-control line. Returns true when it is CEND.
  bool executive_line(const Line& line, const std::string& file, std::uint32_t file_index);
  /// One case-control line.
  void case_line(const Line& line, const std::string& file, std::uint32_t file_index);
  /// After the last case-control line: complete subcases with the global selections.
  void finish();
  /// The ASSIGN INPUTT4 statements of the executive control, in order.
  const std::vector<AssignedUnit>& assigned_units() const { return assigned_; }

 private:
  void assign(const std::string& text, const std::string& where);
  void command(const std::string& text, const std::string& file, std::uint32_t file_index, std::uint32_t line);
  fem::Subcase& current() { return model_.case_control.subcases.empty() || !in_subcase_ ? model_.case_control.global : model_.case_control.subcases.back(); }
  fem::Model& model_;
  std::vector<AssignedUnit> assigned_;
  bool in_subcase_ = false;
  std::string pending_;            ///< a command continued over lines ending in ','
  std::uint32_t pending_line_ = 0;
  std::string pending_file_;
  std::uint32_t pending_file_index_ = 0;
};

}  // namespace seflex::io::nastran
