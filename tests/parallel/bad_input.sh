#!/usr/bin/env bash
# Bad input under MPI (issue 16): `mpirun -n 2 seflex modes DECK --backend slepc` on a deck with an
# error stops every rank with exit 3 and prints the reader's message once (rank 0), not once per rank.
# A missing deck is checked too, and a distributed backend plugin that is missing or not seflex's
# (SEFLEX_PARALLEL_PLUGIN): exit 1, the file named. (A command-line usage error such as a missing
# --backend value is printed by every rank, exit 2: not checked here.) Usage: bad_input.sh MPIRUN SEFLEX OUTDIR
set -u
mpirun=$1 seflex=$2 out=$3
mkdir -p "$out"
fail=0
deck="$out/bad_pshell.bdf"
cat > "$deck" <<'BDF'
SOL 103
CEND
METHOD = 1
BEGIN BULK
EIGRL   1                       4
GRID    1               0.      0.      0.
GRID    2               1.      0.      0.
GRID    3               1.      1.      0.
GRID    4               0.      1.      0.
CQUAD4  1       7       1       2       3       4
MAT1    1       7.+10           .33     2700.
ENDDATA
BDF
check() {  # name, expected exit code, expected message (grep -E), command...
  local name=$1 code=$2 pattern=$3
  shift 3
  "$@" > "$out/$name.out" 2> "$out/$name.err"
  local rc=$?
  if [ "$rc" -ne "$code" ]; then echo "FAIL $name: exit $rc, expected $code"; cat "$out/$name.err"; fail=1; return; fi
  local n
  n=$(grep -cE "$pattern" "$out/$name.err")
  if [ "$n" -ne 1 ]; then echo "FAIL $name: message /$pattern/ printed $n times, expected once:"; cat "$out/$name.err"; fail=1; return; fi
  echo "ok   $name: exit $rc, $(grep -E "$pattern" "$out/$name.err")"
}
check undefined_pshell 3 "^error: .*bad_pshell.bdf:10: CQUAD4 1, field 3 \(PID\): references property 7, which is not defined" "$mpirun" -n 2 "$seflex" modes "$deck" --backend slepc
check missing_deck 3 "^error: .*nowhere.bdf: no such file; expected a Nastran deck \(rank 0 of 2\)$" "$mpirun" -n 2 "$seflex" modes "$out/nowhere.bdf" --backend slepc
check missing_plugin 1 "^error: the distributed backend \(libseflex_parallel.so\) is not installed: looked for $out/no-plugin.so; set SEFLEX_PARALLEL_PLUGIN to its path$" \
  env SEFLEX_PARALLEL_PLUGIN="$out/no-plugin.so" "$seflex" modes "$deck" --backend slepc
not_plugin=$(ldd "$seflex" | awk '$1 ~ /^libm[.]so/ {print $3}')
check foreign_plugin 1 "^error: the distributed backend $not_plugin has no entry point seflex_parallel_backend: not a seflex plugin$" \
  env SEFLEX_PARALLEL_PLUGIN="$not_plugin" "$seflex" modes "$deck" --backend slepc
exit $fail
