#!/usr/bin/env bash
# How many of the public decks in pyNastran's models/ folder `seflex info` reads, or `seflex static`
# solves (issues 14, 40), and how many of those read carry no unsupported structural card (issue
# 43): every .bdf/.dat/.nas file under models/ of a pyNastran checkout or bare mirror, run through
# `seflex COMMAND` with a time limit; prints the count by outcome (exit 0 = read or solved; 3 =
# refused with an input error; 4 = not converged; anything else = crash or hang) and, per deck, the
# outcome and the first line of the error, to a CSV. With `info`, also the count of decks read whose
# unsupported cards all belong to the families a structural reduction may ignore (below), the other
# unsupported cards by the number of decks that list them, and those cards per deck in the CSV.
#   bench/pynastran_decks.sh SEFLEX PYNASTRAN_GIT_DIR [OUT_CSV] [TIMEOUT_S] [COMMAND]
# COMMAND: info (default) or static (each deck solved in a scratch copy; results thrown away).
# e.g. bench/pynastran_decks.sh build/apps/seflex pyNastran/.git decks.csv 60 static
# A bare mirror is read with `git cat-file` file by file (blobs missing from the mirror are skipped
# and counted).
set -uo pipefail
seflex="$(realpath "$1")"
git_dir="$2"
out="${3:-pynastran-decks.csv}"
limit="${4:-60}"
command="${5:-info}"
case "$command" in
  info|static) ;;
  *) echo "pynastran_decks.sh: COMMAND is info or static, got '$command'" >&2; exit 2 ;;
esac
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT

# The families of unsupported cards a deck may carry and still count as one whose structure seflex
# models in full: aero, dynamic loading and damping, optimisation, heat transfer, contact, output.
# Each entry of `seflex info`'s "unsupported cards" list is a card name or a note on a card ("PBEAM
# (tapered: end-A section used)", "CHEXA on PSOLID on MAT4 (left out)"); a note is classified by the
# patterns below, first match wins. Everything else (structure, materials, static loads, rigid
# elements, superelements, acoustics, model parameters) is "structural"; the data of other solution
# sequences (nonlinear control, temperature-dependent materials, DMAP sets: "other") is counted
# both ways.
family() {
  case "$1" in
    # heat transfer: its cards, and elements/properties left out because they sit on a MAT4/MAT5
    *" on MAT4 (left out)" | *" on MAT5 (left out)" | MAT4 | MAT5 | MATT4 | MATT5 | CHBDYE | CHBDYG | CHBDYP | \
      PHBDY | CONV | CONVM | PCONV | PCONVM | RADBC | RADM | RADMT | RADMTX | RADLST | RADCAV | RADSET | VIEW | \
      VIEW3D | VATVFS | QBDY1 | QBDY2 | QBDY3 | QHBDY | QVOL | QVECT | TEMPBC | CHBDY | TEMPF1) echo heat ;;
    # aeroelasticity (SET1/SET2/SET3 are the splines' grid and panel lists in these decks)
    AERO | AEROS | AEROZ | CAERO[1-7] | PAERO[1-7] | SPLINE[1-7] | SET1 | SET2 | SET3 | AESTAT | AESURF | \
      AESURFS | AELIST | AEPARM | AELINK | AEFACT | AECOMP | AECOMPL | AEFORCE | AEPRESS | AEDW | TRIM | TRIM2 | \
      TRIMVAR | TRIMFNC | TRIMFLT | FLUTTER | FLFACT | MKAERO1 | MKAERO2 | MKAEROZ | GUST | DIVERG | CSSCHD | \
      UXVEC | PAFOIL7 | PANLST1 | PANLST2 | PANLST3 | CELLWNG | CELLBOX) echo aero ;;
    # dynamic loading and damping: dynamic load and frequency/time-step cards, their tables, extra
    # points, transfer functions, complex eigenvalue methods, dampers and damping fields
    DLOAD | RLOAD1 | RLOAD2 | TLOAD1 | TLOAD2 | DAREA | DELAY | DPHASE | LSEQ | FREQ | FREQ[1-5] | TSTEP | \
      TSTEP1 | TSTEPNL | TABLED[1-5] | TABDMP1 | TABRND1 | TABRNDG | RANDPS | RANDT1 | RANDVAR | RCROSS | EPOINT | \
      TIC | NOLIN[1-4] | TF | EIGC | EIGP | CDAMP[1-5] | PDAMP | PDAMP5 | PDAMPT | CVISC | PVISC | PELAST | PBUSHT | ACSRCE | \
      "PBUSH B (viscous damping ignored: statics and real modes)" | \
      "PBUSH GE (structural damping ignored: statics and real modes)" | \
      "PBUSH1D C (viscous damping ignored: statics and real modes)") echo dynamics ;;
    # design optimisation
    DESVAR | DVPREL1 | DVPREL2 | DVMREL1 | DVMREL2 | DVCREL1 | DVCREL2 | DVTREL1 | DVGRID | DVSHAP | DRESP1 | \
      DRESP2 | DRESP3 | DCONSTR | DCONADD | DOPTPRM | DTABLE | DEQATN | DLINK | DSCREEN | TOPVAR | MODTRAK | \
      DMRLAW | DMNCON) echo optimisation ;;
    # contact and gap elements
    BCTSET | BCTPARA | BCTPARM | BCTADD | BCTABL1 | BSURF | BSURFS | BCPROP | BCBODY | BCBDPRP | BCONP | BLSEG | \
      BFRIC | BCRPARA | BCSURF | BCPARA | BCONPRP | BCONPRG | BCONECT | BGSET | BGADD | BEDGE | CGAP | PGAP) echo contact ;;
    # output: plot elements and plot control, monitor points, output formats, stress-recovery data
    PLOTEL | PLOTEL3 | PLOTEL4 | PLOTEL6 | PLOTEL8 | PLOTOPT | PLOTG | PLOTE | MONPNT1 | MONPNT2 | MONPNT3 | \
      MONDSP1 | MONSUM | OUTPUT | OUTRCV | ECHOON | ECHOOFF | PARVEC | CBARAO | GROUP | "MDLPRM HDF5 (output format)" | \
      "PSHELL Z1/Z2 (fibre distances for stresses, which seflex does not compute: not used)" | \
      "PSOLID STRESS (stress output system; seflex gives no stresses)" | \
      "PBUSH RCV (stress recovery coefficients ignored)") echo output ;;
    # other solutions' data a linear static or modal reduction does not read: nonlinear-analysis
    # control and material data, temperature-dependent materials and their tables, DMAP sets and
    # matrices
    NLPARM | NLPCI | NLCNTL | NLCNTLG | NLCNTL2 | NLSTEP | MATS1 | MATS3 | MATS8 | TABLES1 | MATT1 | MATT2 | MATT3 | \
      MATT8 | MATT9 | MATT11 | TABLEM[1-5] | PBUSH1D | USET | USET1 | DMI | DTI | \
      "PBUSH1D SHOCKA (nonlinear: linear solutions use K and C)" | "PBUSH1D SPRING (nonlinear: linear solutions use K and C)" | \
      "PBUSH1D DAMPER (nonlinear: linear solutions use K and C)" | "PBUSH1D GENER (nonlinear: linear solutions use K and C)") echo other ;;
    *) echo structural ;;
  esac
}

commit=$(git --git-dir="$git_dir" rev-parse HEAD)
missing=0
while read -r _ type obj path; do
  [ "$type" = blob ] || continue
  mkdir -p "$tmp/$(dirname "$path")"
  git --git-dir="$git_dir" cat-file blob "$obj" > "$tmp/$path" 2> /dev/null || { rm -f "$tmp/$path"; missing=$((missing + 1)); }
done < <(git --git-dir="$git_dir" ls-tree -r HEAD models)
echo "deck,outcome,exit,message,structural_unsupported,other_solutions_unsupported" > "$out"
declare -A count=([read]=0 [refused]=0 [unconverged]=0 [crash]=0 [timeout]=0)
declare -A blocking=()  # structural unsupported card -> number of decks listing it
clean=0             # only the six families above
clean_with_other=0  # and other solutions' data
while IFS= read -r deck; do
  rel="${deck#"$tmp"/}"
  if [ "$command" = static ]; then
    msg=$(cd "$(dirname "$deck")" && timeout "$limit" "$seflex" static "$(basename "$deck")" -o "$tmp/static.csv" --force 2>&1 > /dev/null)
  else
    msg=$(cd "$(dirname "$deck")" && timeout "$limit" "$seflex" info "$(basename "$deck")" 2>&1 > "$tmp/info.txt")
  fi
  rc=$?
  # the first line that is not a warning (the error), else the first line
  msg=$( (grep -v '^warning' <<< "$msg" | grep -m1 .) || head -1 <<< "$msg")
  case "$rc" in
    0) outcome=read ;;
    3) outcome=refused ;;
    4) outcome=unconverged ;;
    124) outcome=timeout ;;
    *) outcome=crash ;;
  esac
  count[$outcome]=$((count[$outcome] + 1))
  structural=""
  other=""
  if [ "$command" = info ] && [ "$outcome" = read ]; then
    # "  NAME    COUNT   first at FILE:LINE" lines after the "unsupported cards" heading
    while IFS= read -r card; do
      case "$(family "$card")" in
        structural) structural="${structural:+$structural;}$card"; blocking[$card]=$((${blocking[$card]:-0} + 1)) ;;
        other) other="${other:+$other;}$card" ;;
      esac
    done < <(awk '/^unsupported cards/ {f = 1; next} f && /^  / {sub(/^  /, ""); sub(/  +[0-9]+   first at .*/, ""); print} /^$/ {f = 0}' "$tmp/info.txt" | sort -u)
    [ -z "$structural" ] && clean_with_other=$((clean_with_other + 1))
    [ -z "$structural$other" ] && clean=$((clean + 1))
  fi
  printf '%s,%s,%s,"%s","%s","%s"\n' "$rel" "$outcome" "$rc" "${msg//\"/\'}" "${structural//\"/\'}" "${other//\"/\'}" >> "$out"
done < <(find "$tmp/models" -type f \( -iname '*.bdf' -o -iname '*.dat' -o -iname '*.nas' \) | sort)
total=$((count[read] + count[refused] + count[unconverged] + count[crash] + count[timeout]))
echo "# seflex $command on pyNastran models/ at $commit ($(date -I)): $total decks ($missing files missing from the mirror)"
echo "$([ "$command" = static ] && echo solved || echo read) (exit 0): ${count[read]}  refused (exit 3): ${count[refused]}  not converged (exit 4): ${count[unconverged]}  crash: ${count[crash]}  timeout (${limit} s): ${count[timeout]}"
if [ "$command" = info ]; then
  echo "read with no unsupported card but aero, dynamic loading and damping, optimisation, heat transfer, contact and output: $clean"
  echo "  ... with other solutions' data (nonlinear control, temperature-dependent materials, DMAP sets) ignorable too: $clean_with_other"
  echo "structural unsupported cards, by number of decks read that list them:"
  for card in "${!blocking[@]}"; do printf '%5d  %s\n' "${blocking[$card]}" "$card"; done | sort -k1,1nr -k2 | head -40
fi
echo "per deck: $out"
