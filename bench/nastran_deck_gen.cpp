// Generates a Nastran deck for the reader benchmark (bench/nastran_read_bench.sh): an n x n grid of
// GRIDs and (n-1)^2 CQUAD4 on a flat plate, with a MAT1 (with density) and a PSHELL so that mass
// properties have work to do.
//   nastran_deck_gen OUT.bdf N small|free|large
// N = 1001 gives 1,002,001 GRIDs and 1,000,000 CQUAD4.
#include <charconv>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace {

void pad(std::string& line, const char* text, std::size_t width) {
  std::string f(text);
  f.resize(width, ' ');
  line += f;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 4) {
    std::fprintf(stderr, "usage: %s OUT.bdf N small|free|large\n", argv[0]);
    return 2;
  }
  const std::string out = argv[1], format = argv[3];
  const long n = std::strtol(argv[2], nullptr, 10);
  if (n < 2 || (format != "small" && format != "free" && format != "large")) {
    std::fprintf(stderr, "N must be >= 2 and the format small, free or large\n");
    return 2;
  }
  std::FILE* f = std::fopen(out.c_str(), "wb");
  if (!f) {
    std::perror(out.c_str());
    return 1;
  }
  std::fprintf(f, "$ seflex reader benchmark: %ld x %ld grids, %ld CQUAD4, %s field\n", n, n, (n - 1) * (n - 1),
               format.c_str());
  std::fprintf(f, "SOL 103\nCEND\nTITLE = reader benchmark\nBEGIN BULK\n");
  std::fprintf(f, "MAT1,1,7.0+10,,0.33,2700.\nPSHELL,1,1,0.002,1,,1\nPARAM,GRDPNT,1\n");
  const double h = 1.0 / static_cast<double>(n - 1);
  std::string line;
  char x[32], y[32], num[4][24];
  for (long j = 0; j < n; ++j)
    for (long i = 0; i < n; ++i) {
      const long id = j * n + i + 1;
      std::snprintf(x, sizeof x, "%.6f", i * h);
      std::snprintf(y, sizeof y, "%.6f", j * h);
      std::snprintf(num[0], sizeof num[0], "%ld", id);
      line.clear();
      if (format == "free") {
        line = "GRID," + std::string(num[0]) + ",," + x + "," + y + ",0.\n";
      } else if (format == "small") {
        pad(line, "GRID", 8), pad(line, num[0], 8), pad(line, "", 8), pad(line, x, 8), pad(line, y, 8), line += "0.\n";
      } else {
        pad(line, "GRID*", 8), pad(line, num[0], 16), pad(line, "", 16), pad(line, x, 16), pad(line, y, 16);
        line += "\n*       0.\n";
      }
      std::fputs(line.c_str(), f);
    }
  for (long j = 0; j + 1 < n; ++j)
    for (long i = 0; i + 1 < n; ++i) {
      const long g = j * n + i + 1, eid = j * (n - 1) + i + 1;
      char e[24];
      std::snprintf(e, sizeof e, "%ld", eid);
      std::snprintf(num[0], sizeof num[0], "%ld", g);
      std::snprintf(num[1], sizeof num[1], "%ld", g + 1);
      std::snprintf(num[2], sizeof num[2], "%ld", g + n + 1);
      std::snprintf(num[3], sizeof num[3], "%ld", g + n);
      line.clear();
      if (format == "free") {
        line = std::string("CQUAD4,") + e + ",1," + num[0] + "," + num[1] + "," + num[2] + "," + num[3] + "\n";
      } else if (format == "small") {
        pad(line, "CQUAD4", 8), pad(line, e, 8), pad(line, "1", 8);
        for (int k = 0; k < 3; ++k) pad(line, num[k], 8);
        line += num[3];
        line += "\n";
      } else {
        pad(line, "CQUAD4*", 8), pad(line, e, 16), pad(line, "1", 16), pad(line, num[0], 16), pad(line, num[1], 16);
        line += "\n";
        pad(line, "*", 8), pad(line, num[2], 16), line += num[3];
        line += "\n";
      }
      std::fputs(line.c_str(), f);
    }
  std::fputs("ENDDATA\n", f);
  if (std::fclose(f) != 0) {
    std::perror(out.c_str());
    return 1;
  }
  return 0;
}
