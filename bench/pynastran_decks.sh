#!/usr/bin/env bash
# How many of the public decks in pyNastran's models/ folder `seflex info` reads, or `seflex static`
# solves (issues 14, 40): every .bdf/.dat/.nas file under models/ of a pyNastran checkout or bare
# mirror, run through `seflex COMMAND` with a time limit; prints the count by outcome (exit 0 = read
# or solved; 3 = refused with an input error; 4 = not converged; anything else = crash or hang) and,
# per deck, the outcome and the first line of the error, to a CSV.
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
commit=$(git --git-dir="$git_dir" rev-parse HEAD)
missing=0
while read -r _ type obj path; do
  [ "$type" = blob ] || continue
  mkdir -p "$tmp/$(dirname "$path")"
  git --git-dir="$git_dir" cat-file blob "$obj" > "$tmp/$path" 2> /dev/null || { rm -f "$tmp/$path"; missing=$((missing + 1)); }
done < <(git --git-dir="$git_dir" ls-tree -r HEAD models)
echo "deck,outcome,exit,message" > "$out"
declare -A count=([read]=0 [refused]=0 [unconverged]=0 [crash]=0 [timeout]=0)
while IFS= read -r deck; do
  rel="${deck#"$tmp"/}"
  if [ "$command" = static ]; then
    msg=$(cd "$(dirname "$deck")" && timeout "$limit" "$seflex" static "$(basename "$deck")" -o "$tmp/static.csv" --force 2>&1 > /dev/null)
  else
    msg=$(cd "$(dirname "$deck")" && timeout "$limit" "$seflex" info "$(basename "$deck")" 2>&1 > /dev/null)
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
  printf '%s,%s,%s,"%s"\n' "$rel" "$outcome" "$rc" "${msg//\"/\'}" >> "$out"
done < <(find "$tmp/models" -type f \( -iname '*.bdf' -o -iname '*.dat' -o -iname '*.nas' \) | sort)
total=$((count[read] + count[refused] + count[unconverged] + count[crash] + count[timeout]))
echo "# seflex $command on pyNastran models/ at $commit ($(date -I)): $total decks ($missing files missing from the mirror)"
echo "$([ "$command" = static ] && echo solved || echo read) (exit 0): ${count[read]}  refused (exit 3): ${count[refused]}  not converged (exit 4): ${count[unconverged]}  crash: ${count[crash]}  timeout (${limit} s): ${count[timeout]}"
echo "per deck: $out"
