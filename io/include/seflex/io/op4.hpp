#pragma once
// Nastran OUTPUT4 (OP4) matrices in the formatted (ASCII), dense, real double-precision layout that
// Nastran's OUTPUT4 writes with DIGITS = 16 and that coupled-loads tools read:
//
//   header:  NCOL NROW NF NTYPE (4 x I8), NAME (A8, left-justified), format "1P,3E23.16"
//   columns: ICOL IROW NW (3 x I8): column number, first row written, number of values; then the
//            values from row IROW to the column's last nonzero, 3 per line in E23.16
//            (null columns are not written)
//   end:     a record for column NCOL + 1 (IROW 1, NW 1) followed by one value
// NF (form): 1 square, 2 rectangular, 6 symmetric (all terms are still written). NTYPE 2 = real
// double precision. Rows and columns are 1-based. Several matrices follow one another in a file.
// Exponents of three digits are written the Fortran way (1.0000000000000000-100, no E).
#include <Eigen/Core>
#include <filesystem>
#include <string>
#include <vector>

#include "seflex/superelement/superelement.hpp"

namespace seflex::io {

struct Op4Matrix {
  std::string name;  ///< 1-8 characters
  int form = 2;      ///< 1 square, 2 rectangular, 6 symmetric
  Eigen::MatrixXd values;
};

/// One matrix in OP4 ASCII form (appended to `out`). InvariantError for a bad name, form or
/// non-finite values.
void append_op4(std::string& out, const Op4Matrix& matrix);

/// Several matrices as OP4 ASCII text.
std::string op4_text(const std::vector<Op4Matrix>& matrices);

struct Op4ExportOptions {
  bool recovery = false;  ///< also write RECOVERY (6 n_fe x n, grid-major, basic components)
  bool overwrite = false;
};

/// The superelement's matrices: KAA and MAA (n x n, form 6, dofs in q order: interface grids 6
/// each in body axes, then the modal coordinates) and optionally RECOVERY (form 2).
std::vector<Op4Matrix> superelement_op4_matrices(const se::Superelement& body, bool recovery);

/// Every matrix of OP4 text (any layout Nastran's OUTPUT4 writes as text, FORMATTED): the header
/// NCOL NROW NF NTYPE (4 x I8, NROW < 0: "bigmat") NAME (A8) and a Fortran format such as 1P,3E23.16
/// or 1P,5E16.9 (E or D; the values are read at that width, 3-digit exponents without E too); columns
/// dense (ICOL IROW NW, IROW > 0: NW values from row IROW) or sparse (IROW = 0: strings, each headed
/// by IS = (L + 1) * 65536 + IROW, or by "L + 1  IROW" in bigmat, L the words of the string), ended
/// by column NCOL + 1. Real single (NTYPE 1) and double (2) precision; a double value is 2 words in a
/// sparse string's L and NW. `file` names the text in errors. Throws InputError naming the file, the
/// matrix, the line and what was expected for anything else (complex matrices, a binary file, a
/// row outside the matrix, a value that is no number, text ending inside a matrix).
std::vector<Op4Matrix> parse_op4(const std::string& text, const std::string& file);

/// parse_op4 of a file's text. Throws InputError if it cannot be read.
std::vector<Op4Matrix> read_op4(const std::filesystem::path& path);

/// Write them (atomically). Throws InputError if the file exists and !overwrite, cannot be
/// written, or RECOVERY is asked of a superelement stored without one.
void write_op4(const se::Superelement& body, const std::filesystem::path& path, const Op4ExportOptions& options = {});

}  // namespace seflex::io
